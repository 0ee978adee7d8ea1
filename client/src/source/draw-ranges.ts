// Which of a chunk's triangles a slice can show. A chunk holds many states stacked over the same
// ground; a triangle whose lowest corner lies above the slicing surface everywhere in the view
// is discarded pixel by pixel by id.frag, after being rasterized (it writes its depth, so nothing
// is rejected early). Here the triangles are ordered by their lowest z, so those at or below the
// view's highest slice z are a prefix, found from a small table of blocks: at the base scale that
// skips almost the whole chunk.
//
// Triangles whose upper face has ended below the slice are still drawn: newer surfaces cover
// them, but where the GPU leaves a pixel between current triangles uncovered they fill it.
// Shared corners across chunks now land on one spot (id.vert), yet the current triangles do not
// always meet corner to corner: beside a sliver a few centimetres wide, or where one piece's
// corner lies on another's edge, a software GPU's sub-pixel snapping opens pixel-wide gaps.
// Leaving the ended triangles out (tried: blocks ordered by end z within) opened such pixels on
// bgt_otterlo_400m at z 420, and filled them differently as the slice's z range changed.
// Pure: the worker orders a decoded chunk; the renderer picks the prefix each frame.

/** The blocks of a chunk ordered for drawing, as transferred to the renderer. */
export interface DrawBlocks {
  /** Lowest vertex z of each block's first triangle (the blocks ascend). */
  zLow: Float32Array;
  /** First triangle of each block, and the triangle count last (blocks + 1 entries). */
  first: Uint32Array;
}

/** Triangles a block holds at least: the table stays small, and the prefix ends at most this much late. */
const BLOCK = 64;

/**
 * Reorders the first `count` triangles of `indices` in place by their lowest vertex z
 * (`positions` holds x, y, z per vertex; ties keep their order) and returns their blocks.
 */
export function orderForDrawing(positions: ArrayLike<number>, indices: Uint16Array | Uint32Array, count: number): DrawBlocks {
  const low = new Float64Array(count);
  for (let t = 0; t < count; t++) {
    low[t] = Math.min(positions[3 * indices[3 * t]! + 2]!, positions[3 * indices[3 * t + 1]! + 2]!, positions[3 * indices[3 * t + 2]! + 2]!);
  }
  const order = Array.from({ length: count }, (_, t) => t).sort((p, q) => low[p]! - low[q]! || p - q);
  const copy = indices.slice(0, 3 * count);
  for (let i = 0; i < count; i++) {
    const t = order[i]!;
    indices[3 * i] = copy[3 * t]!;
    indices[3 * i + 1] = copy[3 * t + 1]!;
    indices[3 * i + 2] = copy[3 * t + 2]!;
  }
  const blocks = Math.ceil(count / BLOCK);
  // positions are float32, so the lowest z of a block is exact in the float32 table.
  const zLow = Float32Array.from({ length: blocks }, (_, k) => low[order[k * BLOCK]!]!);
  const first = Uint32Array.from({ length: blocks + 1 }, (_, k) => Math.min(count, k * BLOCK));
  return { zLow, first };
}

/**
 * How many triangles, from the first, slices up to `zMax` can show: every triangle whose
 * lowest z is at or below zMax is among them (the index's test for a chunk's z0).
 */
export function trianglesUpTo(b: DrawBlocks, zMax: number): number {
  let lo = 0, hi = b.zLow.length;
  // The first block that starts above zMax: it and all after it are skipped.
  while (lo < hi) {
    const mid = (lo + hi) >> 1;
    if (b.zLow[mid]! <= zMax) lo = mid + 1;
    else hi = mid;
  }
  return b.first[lo]!;
}
