// Which of a chunk's triangles a view can show. A chunk holds many states stacked over the same
// ground, often over far more ground than a view at its lowest z covers (at the base scale a
// chunk of 1 to 2 km under a view of 340 m). Three things keep a view from drawing all of it:
// - Ground cells: the worker splits the chunk's ground into CELLS x CELLS cells and groups the
//   triangles by the cell of their ground box's centre. A cell whose triangles' ground box
//   misses the view is not drawn: none of its triangles could cover a pixel of it. On
//   bgt_otterlo_1800m at 1:1,000 (bench:render) a frame drew 8,640 triangles before, 2,701 now.
//   A chunk whose triangles all lie at one z (a floor chunk) has 8 x 8 cells: with no z order
//   to keep, a finer grid only culls more. That view, drawn from the floor chunks, drew 3,819
//   triangles with 4 x 4 cells, 1,599 with 8 x 8 (937 needed).
// - Lowest z: within a band (below) the triangles are ordered by their lowest z, so those at or
//   below the view's highest slice z are a prefix, found from a small table of blocks. A
//   triangle above the slice everywhere would be discarded pixel by pixel by id.frag, after
//   being rasterized.
// - End z: a triangle whose upper face has ended (its stepHigh, from the face pages) at or below
//   the view's lowest slice z is covered by newer surfaces. Within a cell the triangles are cut
//   into BANDS bands of nearly equal count by that end z, and a band all ended is left out. High
//   in a cube most triangles have ended: on bgt_otterlo_1800m at 1:8,929 (bench:passes) a frame
//   drew 70,384 triangles before, 37,263 now (26,933 are live, offline for a centre view; 8
//   bands would draw 7% fewer there for 11% more ranges). A chunk's ends come from the face
//   pages that hold its faces; a floor chunk, or one whose pages failed to load, leaves every
//   triangle unended (Infinity).
//
// Ended triangles used to fill pixels the GPU leaves uncovered where live triangles meet at a
// T-junction (one piece's corner on another's edge) or beside a sliver: on bgt_otterlo_400m at
// 640 x 480, z 200 to 430, 1 to 3 such pixels a frame now show the background, where before
// they showed a face that had ended; the same pixels differed from the CPU slicer then too.
// Pure: the worker orders a decoded chunk; the renderer picks the ranges each frame.

/** The blocks of a chunk ordered for drawing, as transferred to the renderer. */
export interface DrawBlocks {
  /** Per cell, the ground box of its triangles (x0, y0, x1, y1, relative to the chunk's origin); empty cells are left out. */
  cellBox: Float32Array;
  /** Per cell, its first band; the band count last (cells + 1 entries). */
  cellBands: Uint32Array;
  /** Per band, the highest end z of its triangles (ascending within a cell). */
  bandEnd: Float32Array;
  /** Per band, its first block; the block count last (bands + 1 entries). */
  bandBlocks: Uint32Array;
  /** Lowest vertex z of each block's first triangle (ascending within a band). */
  zLow: Float32Array;
  /** First triangle of each block, and the triangle count last (blocks + 1 entries). */
  first: Uint32Array;
}

/** Cells along each side of a chunk's ground. */
const CELLS = 4;
/** Cells along each side of a chunk whose triangles all lie at one z (floor chunks): no z order to keep, so finer. */
const FLAT_CELLS = 8;
/** Bands of end z a cell's triangles are parted into, at most. */
const BANDS = 4;
/** Triangles a block holds at least: the table stays small, and a cell's prefix ends at most this much late. */
const BLOCK = 16;

/**
 * Reorders the first `count` triangles of `indices` in place by ground cell, then by band of
 * end z (`end(t)`: the z from which triangle t is covered for good; Infinity when unknown), then
 * by their lowest vertex z (`positions` holds x, y, z per vertex; ties keep their order), and
 * returns their cells, bands and blocks.
 */
export function orderForDrawing(positions: ArrayLike<number>, indices: Uint16Array | Uint32Array, count: number, end: (t: number) => number = () => Infinity): DrawBlocks {
  const low = new Float64Array(count);
  const ends = new Float64Array(count);
  const box = new Float64Array(4 * count);
  let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  for (let t = 0; t < count; t++) {
    const a = 3 * indices[3 * t]!, b = 3 * indices[3 * t + 1]!, c = 3 * indices[3 * t + 2]!;
    low[t] = Math.min(positions[a + 2]!, positions[b + 2]!, positions[c + 2]!);
    ends[t] = end(t);
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
  // Within a cell, by end z; then cut into bands of nearly equal count, each ordered by lowest z.
  const byEnd = Array.from({ length: count }, (_, t) => t).sort((p, q) => cellOf[p]! - cellOf[q]! || ends[p]! - ends[q]! || p - q);
  const bandOf = new Uint8Array(count);
  for (let s = 0; s < count;) {
    let e = s;
    while (e < count && cellOf[byEnd[e]!] === cellOf[byEnd[s]!]) e++;
    for (let k = s; k < e; k++) {
      // Ties in end z share a band, so triangles that never end (or a chunk without ends) stay one band in lowest-z order.
      const same = k > s && ends[byEnd[k]!] === ends[byEnd[k - 1]!];
      bandOf[byEnd[k]!] = same ? bandOf[byEnd[k - 1]!]! : Math.floor(((k - s) * BANDS) / (e - s));
    }
    s = e;
  }
  const order = byEnd.slice().sort((p, q) => cellOf[p]! - cellOf[q]! || bandOf[p]! - bandOf[q]! || low[p]! - low[q]! || p - q);
  const copy = indices.slice(0, 3 * count);
  for (let i = 0; i < count; i++) {
    const t = order[i]!;
    indices[3 * i] = copy[3 * t]!;
    indices[3 * i + 1] = copy[3 * t + 1]!;
    indices[3 * i + 2] = copy[3 * t + 2]!;
  }
  const boxes: number[] = [], cellBands: number[] = [], bandEnd: number[] = [], bandBlocks: number[] = [], zLow: number[] = [], first: number[] = [];
  for (let s = 0; s < count;) {
    const cell = cellOf[order[s]!]!;
    let bx0 = Infinity, by0 = Infinity, bx1 = -Infinity, by1 = -Infinity;
    cellBands.push(bandEnd.length);
    while (s < count && cellOf[order[s]!] === cell) {
      const band = bandOf[order[s]!]!;
      let e = s, top = -Infinity;
      for (; e < count && cellOf[order[e]!] === cell && bandOf[order[e]!] === band; e++) {
        const t = order[e]!;
        bx0 = Math.min(bx0, box[4 * t]!); by0 = Math.min(by0, box[4 * t + 1]!);
        bx1 = Math.max(bx1, box[4 * t + 2]!); by1 = Math.max(by1, box[4 * t + 3]!);
        top = Math.max(top, ends[t]!);
      }
      // Rounded up: a band is left out only below its true end.
      const top32 = Math.fround(top);
      bandEnd.push(top32 < top ? nextUp32(top32) : top32);
      bandBlocks.push(zLow.length);
      for (let k = s; k < e; k += BLOCK) {
        zLow.push(low[order[k]!]!);
        first.push(k);
      }
      s = e;
    }
    // positions are float32, so the box and the blocks' lowest z are exact in float32.
    boxes.push(bx0, by0, bx1, by1);
  }
  cellBands.push(bandEnd.length);
  bandBlocks.push(zLow.length);
  first.push(count);
  return {
    cellBox: Float32Array.from(boxes), cellBands: Uint32Array.from(cellBands), bandEnd: Float32Array.from(bandEnd),
    bandBlocks: Uint32Array.from(bandBlocks), zLow: Float32Array.from(zLow), first: Uint32Array.from(first),
  };
}

/** The next float32 above a finite float32 `v`. */
function nextUp32(v: number): number {
  const f = new Float32Array([v]);
  const u = new Int32Array(f.buffer);
  u[0]! += v >= 0 ? 1 : -1;
  return v === 0 ? 1.4e-45 : f[0]!;
}

/** The triangle ranges a view draws: `n` of them, each from `first[i]`, `count[i]` long. */
export interface DrawRanges {
  n: number;
  first: Uint32Array;
  count: Uint32Array;
  /** Triangles over all ranges. */
  triangles: number;
}

/** Room for the ranges of a chunk of these blocks (one per band at most). */
export function drawRanges(b: DrawBlocks): DrawRanges {
  const bands = b.bandBlocks.length - 1;
  return { n: 0, first: new Uint32Array(bands), count: new Uint32Array(bands), triangles: 0 };
}

/**
 * The ranges that slices from `zMin` up to `zMax` over the ground box `rect` (x0, y0, x1, y1
 * relative to the chunk's origin) can show, into `out`: every triangle whose lowest z is at or
 * below zMax (the index's test for a chunk's z0), whose end z lies above zMin, and whose cell's
 * box meets `rect` is in one of them.
 */
export function rangesFor(b: DrawBlocks, zMin: number, zMax: number, rect: ArrayLike<number>, out: DrawRanges): DrawRanges {
  out.n = 0;
  out.triangles = 0;
  const cells = b.cellBands.length - 1;
  for (let c = 0; c < cells; c++) {
    if (b.cellBox[4 * c]! > rect[2]! || b.cellBox[4 * c + 2]! < rect[0]! || b.cellBox[4 * c + 1]! > rect[3]! || b.cellBox[4 * c + 3]! < rect[1]!) continue;
    for (let band = b.cellBands[c]!; band < b.cellBands[c + 1]!; band++) {
      // Ended at or below every slice z: newer surfaces cover all of it.
      if (b.bandEnd[band]! <= zMin) continue;
      let lo = b.bandBlocks[band]!, hi = b.bandBlocks[band + 1]!;
      const start = b.first[lo]!;
      while (lo < hi) {
        const mid = (lo + hi) >> 1;
        if (b.zLow[mid]! <= zMax) lo = mid + 1;
        else hi = mid;
      }
      const n = b.first[lo]! - start;
      if (n === 0) continue;
      out.triangles += n;
      // A range that goes on where the last one ended joins it: one call.
      if (out.n > 0 && out.first[out.n - 1]! + out.count[out.n - 1]! === start) {
        out.count[out.n - 1]! += n;
        continue;
      }
      out.first[out.n] = start;
      out.count[out.n] = n;
      out.n++;
    }
  }
  return out;
}
