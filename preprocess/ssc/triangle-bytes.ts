// What each surface triangle adds to the size of the chunk it goes to.
import type { Surfaces } from './surfaces.js';

/**
 * Bytes each triangle costs in a chunk: its three u16 indices and its share of its piece's
 * vertices as the GPU holds them (docs/FORMAT.md: 24 bytes a decoded vertex; the file is smaller).
 */
export function triangleBytes(s: Surfaces): Float64Array {
  const n = s.count;
  const verts = new Float64Array(s.pieces), tris = new Float64Array(s.pieces);
  // A piece's triangles come in runs; vertices are counted per run (an estimate, a little high
  // for a piece split over several runs).
  let run = new Set<number>();
  for (let i = 0; i < n; i++) {
    const p = s.piece[i]!;
    if (i > 0 && s.piece[i - 1] !== p) run = new Set();
    tris[p]!++;
    for (let j = 0; j < 3; j++) {
      const v = s.v[3 * i + j]!;
      if (!run.has(v)) {
        run.add(v);
        verts[p]!++;
      }
    }
  }
  const cost = new Float64Array(n);
  for (let i = 0; i < n; i++) cost[i] = 6 + (24 * verts[s.piece[i]!]!) / tris[s.piece[i]!]!;
  return cost;
}
