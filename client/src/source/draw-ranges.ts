// Which of a chunk's triangles a slice needs. A triangle matters to slices from its lowest
// vertex's z up to the z where its upper face ends; below, it lies above the slice and is
// discarded pixel by pixel; above, newer surfaces cover it. A chunk holds many states stacked
// over the same ground, so drawing it whole rasterizes every one of them (id.frag writes its
// depth, so nothing is rejected early). Here the triangles are put in an order in which the
// ones a slice range needs form a few runs, and the runs are found from a small table:
// - groups by lowest z (equal counts), so the groups above the slice are skipped;
// - inside a group, by ascending end, so the ones ended below the slice are a prefix;
// - blocks of equal count inside each group, each with its lowest z and highest end.
// What is drawn in excess is at most the group the slice is in and a block per group.
// Pure: the worker orders a decoded chunk; the renderer picks the runs each frame.

/** The blocks of a chunk ordered for drawing, as transferred to the renderer. */
export interface DrawBlocks {
  /** Lowest vertex z of each block's triangles. */
  zLow: Float32Array;
  /** Highest end of each block's triangles. */
  zHigh: Float32Array;
  /** First triangle of each block, and the triangle count last (blocks + 1 entries). */
  first: Uint32Array;
}

/** Groups by lowest z in a chunk, and blocks in a group, at most (draw calls and table size stay small). */
const MAX_GROUPS = 16, MAX_BLOCKS_PER_GROUP = 16;
/** Triangles a block holds at least: below that, the table costs more than it saves. */
const MIN_BLOCK = 32;

/**
 * Reorders the first `count` triangles of `indices` in place for drawing and returns their
 * blocks. `positions` holds x, y, z per vertex; `upperEnd` the end z of each vertex's upper face
 * (the same on a triangle's three vertices).
 */
export function orderForDrawing(positions: ArrayLike<number>, upperEnd: ArrayLike<number>, indices: Uint16Array | Uint32Array, count: number): DrawBlocks {
  const low = new Float64Array(count), end = new Float64Array(count);
  for (let t = 0; t < count; t++) {
    const a = indices[3 * t]!, b = indices[3 * t + 1]!, c = indices[3 * t + 2]!;
    low[t] = Math.min(positions[3 * a + 2]!, positions[3 * b + 2]!, positions[3 * c + 2]!);
    end[t] = upperEnd[a]!;
  }
  const byLow = Array.from({ length: count }, (_, t) => t).sort((p, q) => low[p]! - low[q]! || p - q);
  const groups = Math.max(1, Math.min(MAX_GROUPS, Math.floor(count / (MIN_BLOCK * 4))));
  const order: number[] = [];
  const first: number[] = [], zLow: number[] = [], zHigh: number[] = [];
  for (let g = 0; g < groups; g++) {
    const group = byLow.slice(Math.floor((g * count) / groups), Math.floor(((g + 1) * count) / groups));
    group.sort((p, q) => end[p]! - end[q]! || p - q);
    const blocks = Math.max(1, Math.min(MAX_BLOCKS_PER_GROUP, Math.floor(group.length / MIN_BLOCK)));
    for (let k = 0; k < blocks; k++) {
      const from = Math.floor((k * group.length) / blocks), to = Math.floor(((k + 1) * group.length) / blocks);
      if (to === from) continue;
      let lo = Infinity, hi = -Infinity;
      for (let i = from; i < to; i++) {
        lo = Math.min(lo, low[group[i]!]!);
        hi = Math.max(hi, end[group[i]!]!);
      }
      first.push(order.length);
      zLow.push(lo);
      zHigh.push(hi);
      for (let i = from; i < to; i++) order.push(group[i]!);
    }
  }
  first.push(count);
  const copy = indices.slice(0, 3 * count);
  for (let i = 0; i < count; i++) {
    const t = order[i]!;
    indices[3 * i] = copy[3 * t]!;
    indices[3 * i + 1] = copy[3 * t + 1]!;
    indices[3 * i + 2] = copy[3 * t + 2]!;
  }
  // float32 tables: lowest z rounds down and ends round up, so a block is never skipped by rounding.
  return { zLow: roundedTable(zLow, -1), zHigh: roundedTable(zHigh, 1), first: Uint32Array.from(first) };
}

function roundedTable(xs: number[], toward: 1 | -1): Float32Array {
  const out = Float32Array.from(xs);
  for (let i = 0; i < xs.length; i++) {
    if (toward * (out[i]! - xs[i]!) < 0) out[i] = out[i]! + toward * Math.max(Math.abs(out[i]!) * 2 ** -23, 2 ** -149);
  }
  return out;
}

/**
 * The runs of triangles that slices between `zMin` and `zMax` need, as [first, count] pairs in
 * `out` (adjacent blocks joined); returns the triangles in them. A block is needed when its
 * lowest z is at or below zMax and its highest end above zMin: the index's test for a chunk.
 */
export function drawRuns(b: DrawBlocks, zMin: number, zMax: number, out: number[]): number {
  out.length = 0;
  let total = 0;
  for (let k = 0; k < b.zLow.length; k++) {
    if (!(b.zLow[k]! <= zMax && b.zHigh[k]! > zMin)) continue;
    const from = b.first[k]!, n = b.first[k + 1]! - from;
    const last = out.length - 2;
    if (last >= 0 && out[last]! + out[last + 1]! === from) out[last + 1]! += n;
    else out.push(from, n);
    total += n;
  }
  return total;
}
