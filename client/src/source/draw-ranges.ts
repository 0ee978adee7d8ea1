// Which of a chunk's triangles a view can show. A chunk holds many states stacked over the same
// ground, often over far more ground than a view at its lowest z covers (at the base scale a
// chunk of 1 to 2 km under a view of 340 m). Two things keep a view from drawing all of it:
// - Ground cells: the worker splits the chunk's ground into CELLS x CELLS cells and groups the
//   triangles by the cell of their ground box's centre. A cell whose triangles' ground box
//   misses the view is not drawn: none of its triangles could cover a pixel of it. On
//   bgt_otterlo_1800m at 1:1,000 (bench:render) a frame drew 8,640 triangles before, 2,701 now.
//   A chunk whose triangles all lie at one z (a floor chunk) has 8 x 8 cells: with no z order
//   to keep, a finer grid only culls more. That view, drawn from the floor chunks, drew 3,819
//   triangles with 4 x 4 cells, 1,599 with 8 x 8 (937 needed).
// - Lowest z: within a cell the triangles are ordered by their lowest z, so those at or below the
//   view's highest slice z are a prefix, found from a small table of blocks. A triangle above the
//   slice everywhere would be discarded pixel by pixel by id.frag, after being rasterized.
//
// Triangles whose upper face has ended below the slice are still drawn: newer surfaces cover
// them, but where the GPU leaves a pixel between current triangles uncovered they fill it.
// Shared corners across chunks now land on one spot (id.vert), yet the current triangles do not
// always meet corner to corner: beside a sliver a few centimetres wide, or where one piece's
// corner lies on another's edge, a software GPU's sub-pixel snapping opens pixel-wide gaps.
// Leaving the ended triangles out (tried: blocks ordered by end z within) opened such pixels on
// bgt_otterlo_400m at z 420, and filled them differently as the slice's z range changed.
// Leaving out a cell that misses the view leaves no such gap: it covers no pixel of the view.
// Tried again (commit 710fc2c, reverted): 4 bands of end z per cell, the end being the upper
// face's stepHigh from the face pages. bgt_otterlo_400m at 640 x 480 then showed 1 to 3 pixels
// of background a frame at z 200 to 430 (pixels that showed an ended face before, and differed
// from the CPU slicer either way), and bgt_otterlo_1800m at 1:8,929 drew 37,263 triangles
// instead of 70,384 (ID pass 55 -> 40 ms, bench:passes). But the face pages cost the session
// 0.04 MB on bgt_otterlo_1800m and 0.30 MB on nlcd_zion (+6%), where triangles a frame fell by
// 6 to 30% and bench:session's frame time did not change: its frames wait on chunks, not the
// ID pass. Bands written by the build instead (each chunk's triangles in 4 bands of end z, a
// band table in the file) would cost 1% of the chunks' bytes (bgt_otterlo_1800m: 1.848 ->
// 1.866 MB gzip, the codecs' order kept within each band) for the same savings.
// Tried a third time, with the cracks filled: each face's end bounded by a byte in the chunk
// file (a version 6; the chunks 1.1% larger gzip on bgt_otterlo_1800m, 1.7% on nlcd_zion),
// 4 bands of ends per cell, and the colour pass giving a pixel the ID pass left undrawn between
// two drawn ones a neighbour's face. At 1:8,929 (bench:passes, 3 turns) 70,384 -> 34,689
// triangles a frame, but the ID pass took 40-41 ms against 42-46, and the fill's branch cost the
// colour pass 5 to 8 ms at every scale (19.3 -> 25.3 at 1:1,000): the software GPU pays for it
// at every pixel. Its ID pass is not bound by these triangles: with a fragment shader that only
// writes its inputs it took 38 ms at 1:8,929, and with one range a chunk (more triangles, far
// fewer draws) 51-53. Not kept.
// Pure: the worker orders a decoded chunk; the renderer picks the ranges each frame.

/** The blocks of a chunk ordered for drawing, as transferred to the renderer. */
export interface DrawBlocks {
  /** Per cell, the ground box of its triangles (x0, y0, x1, y1, relative to the chunk's origin); empty cells are left out. */
  cellBox: Float32Array;
  /** Per cell, its first block; the block count last (cells + 1 entries). */
  cellBlocks: Uint32Array;
  /** Lowest vertex z of each block's first triangle (ascending within a cell). */
  zLow: Float32Array;
  /** First triangle of each block, and the triangle count last (blocks + 1 entries). */
  first: Uint32Array;
}

/** Cells along each side of a chunk's ground. */
const CELLS = 4;
/** Cells along each side of a chunk whose triangles all lie at one z (floor chunks): no z order to keep, so finer. */
const FLAT_CELLS = 8;
/** Triangles a block holds at least: the table stays small, and a cell's prefix ends at most this much late. */
const BLOCK = 16;

/** Triangle numbers below this fit beside a float32's bits in a float64 sort key (32 + 21 = 53 bits). */
const KEYED_TRIANGLES = 2 ** 21;

/** A float32's bits as a number that sorts as the float does (-0 as +0). */
const sortKeyBits = (() => {
  const f = new Float32Array(1), u = new Uint32Array(f.buffer);
  return (z: number): number => {
    f[0] = z === 0 ? 0 : z;
    const b = u[0]!;
    return b >= 0x80000000 ? ~b >>> 0 : b + 0x80000000;
  };
})();

/**
 * The triangles in order of cell (`cellOf`, below `cellCount`), then of lowest z (`low`, float32
 * values; all equal when `flat`), ties in their own order. A counting sort by cell, then within
 * each cell one numeric sort of float64 keys that hold both the z and the triangle. Ordering the
 * 34 floor chunks of nlcd_zion's first view at 1:50,000 took the worker 100 to 157 ms in three
 * page loads with a sort by comparator, 52 to 72 ms so (the rest is the boxes and the blocks); in
 * one run of 9 page loads each, alternated, with no network throttling, the first complete map
 * came in 998 ms instead of 1,033 (such runs differ by some 50 ms).
 */
export function drawingOrder(cellOf: Uint8Array, cellCount: number, low: Float64Array, flat: boolean): Uint32Array {
  const count = cellOf.length;
  if (count >= KEYED_TRIANGLES) {
    return Uint32Array.from(Array.from({ length: count }, (_, t) => t).sort((p, q) => cellOf[p]! - cellOf[q]! || low[p]! - low[q]! || p - q));
  }
  const start = new Uint32Array(cellCount + 1);
  for (let t = 0; t < count; t++) start[cellOf[t]! + 1]!++;
  for (let c = 0; c < cellCount; c++) start[c + 1]! += start[c]!;
  const order = new Uint32Array(count);
  const next = start.slice(0, cellCount);
  for (let t = 0; t < count; t++) order[next[cellOf[t]!]!++] = t;
  if (flat) return order;
  const keys = new Float64Array(count);
  for (let c = 0; c < cellCount; c++) {
    const s = start[c]!, e = start[c + 1]!;
    if (e - s < 2) continue;
    const part = keys.subarray(s, e);
    for (let k = s; k < e; k++) keys[k] = sortKeyBits(low[order[k]!]!) * KEYED_TRIANGLES + order[k]!;
    part.sort();
    for (let k = s; k < e; k++) order[k] = keys[k]! % KEYED_TRIANGLES;
  }
  return order;
}

/**
 * Reorders the first `count` triangles of `indices` in place by ground cell, then by their
 * lowest vertex z (`positions` holds x, y, z per vertex; ties keep their order), and returns
 * their cells and blocks.
 */
export function orderForDrawing(positions: ArrayLike<number>, indices: Uint16Array | Uint32Array, count: number): DrawBlocks {
  const low = new Float64Array(count);
  const box = new Float64Array(4 * count);
  let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  for (let t = 0; t < count; t++) {
    const a = 3 * indices[3 * t]!, b = 3 * indices[3 * t + 1]!, c = 3 * indices[3 * t + 2]!;
    low[t] = Math.min(positions[a + 2]!, positions[b + 2]!, positions[c + 2]!);
    box[4 * t] = Math.min(positions[a]!, positions[b]!, positions[c]!);
    box[4 * t + 1] = Math.min(positions[a + 1]!, positions[b + 1]!, positions[c + 1]!);
    box[4 * t + 2] = Math.max(positions[a]!, positions[b]!, positions[c]!);
    box[4 * t + 3] = Math.max(positions[a + 1]!, positions[b + 1]!, positions[c + 1]!);
    x0 = Math.min(x0, box[4 * t]!); y0 = Math.min(y0, box[4 * t + 1]!);
    x1 = Math.max(x1, box[4 * t + 2]!); y1 = Math.max(y1, box[4 * t + 3]!);
  }
  // The cell of each triangle's ground box centre.
  const cells = low.every((z) => z === low[0]) ? FLAT_CELLS : CELLS;
  const cellOf = new Uint8Array(count);
  const along = (v: number, lo: number, hi: number): number => (hi > lo ? Math.min(cells - 1, Math.floor(((v - lo) / (hi - lo)) * cells)) : 0);
  for (let t = 0; t < count; t++) {
    const i = along((box[4 * t]! + box[4 * t + 2]!) / 2, x0, x1), j = along((box[4 * t + 1]! + box[4 * t + 3]!) / 2, y0, y1);
    cellOf[t] = j * cells + i;
  }
  const order = drawingOrder(cellOf, cells * cells, low, cells === FLAT_CELLS);
  const copy = indices.slice(0, 3 * count);
  for (let i = 0; i < count; i++) {
    const t = order[i]!;
    indices[3 * i] = copy[3 * t]!;
    indices[3 * i + 1] = copy[3 * t + 1]!;
    indices[3 * i + 2] = copy[3 * t + 2]!;
  }
  const boxes: number[] = [], cellBlocks: number[] = [], zLow: number[] = [], first: number[] = [];
  for (let s = 0; s < count;) {
    const cell = cellOf[order[s]!]!;
    let e = s;
    let bx0 = Infinity, by0 = Infinity, bx1 = -Infinity, by1 = -Infinity;
    for (; e < count && cellOf[order[e]!] === cell; e++) {
      const t = order[e]!;
      bx0 = Math.min(bx0, box[4 * t]!); by0 = Math.min(by0, box[4 * t + 1]!);
      bx1 = Math.max(bx1, box[4 * t + 2]!); by1 = Math.max(by1, box[4 * t + 3]!);
    }
    // positions are float32, so the box and the blocks' lowest z are exact in float32.
    boxes.push(bx0, by0, bx1, by1);
    cellBlocks.push(zLow.length);
    for (let k = s; k < e; k += BLOCK) {
      zLow.push(low[order[k]!]!);
      first.push(k);
    }
    s = e;
  }
  cellBlocks.push(zLow.length);
  first.push(count);
  return { cellBox: Float32Array.from(boxes), cellBlocks: Uint32Array.from(cellBlocks), zLow: Float32Array.from(zLow), first: Uint32Array.from(first) };
}

/** The triangle ranges a view draws: `n` of them, each from `first[i]`, `count[i]` long. */
export interface DrawRanges {
  n: number;
  first: Uint32Array;
  count: Uint32Array;
  /** Triangles over all ranges. */
  triangles: number;
}

/** Room for the ranges of a chunk of these blocks (one per cell at most). */
export function drawRanges(b: DrawBlocks): DrawRanges {
  const cells = b.cellBlocks.length - 1;
  return { n: 0, first: new Uint32Array(cells), count: new Uint32Array(cells), triangles: 0 };
}

/**
 * The ranges that slices up to `zMax` over the ground box `rect` (x0, y0, x1, y1 relative to
 * the chunk's origin) can show, into `out`: every triangle whose lowest z is at or below zMax
 * (the index's test for a chunk's z0) and whose cell's box meets `rect` is in one of them.
 */
export function rangesFor(b: DrawBlocks, zMax: number, rect: ArrayLike<number>, out: DrawRanges): DrawRanges {
  out.n = 0;
  out.triangles = 0;
  const cells = b.cellBlocks.length - 1;
  for (let c = 0; c < cells; c++) {
    if (b.cellBox[4 * c]! > rect[2]! || b.cellBox[4 * c + 2]! < rect[0]! || b.cellBox[4 * c + 1]! > rect[3]! || b.cellBox[4 * c + 3]! < rect[1]!) continue;
    let lo = b.cellBlocks[c]!, hi = b.cellBlocks[c + 1]!;
    const start = b.first[lo]!;
    // The first block of the cell that starts above zMax: it and all after it in the cell are skipped.
    while (lo < hi) {
      const mid = (lo + hi) >> 1;
      if (b.zLow[mid]! <= zMax) lo = mid + 1;
      else hi = mid;
    }
    const n = b.first[lo]! - start;
    if (n === 0) continue;
    out.triangles += n;
    // A range that goes on where the last one ended (a whole cell before it) joins it: one call.
    if (out.n > 0 && out.first[out.n - 1]! + out.count[out.n - 1]! === start) {
      out.count[out.n - 1]! += n;
      continue;
    }
    out.first[out.n] = start;
    out.count[out.n] = n;
    out.n++;
  }
  return out;
}
