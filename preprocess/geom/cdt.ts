// Constrained Delaunay triangulation of a region given by its directed boundary segments
// (region on the left): holes, islands and rings that touch themselves need no ring assembly.
import Delaunator from 'delaunator';
import { Constrainautor } from './constrainautor.js';

export interface RegionTriangulation {
  /** Local vertex indices, 3 per triangle, counterclockwise. */
  triangles: Int32Array;
}

/**
 * `coords`: local x, y pairs (translate them near the origin first); `segs`: [a, b] local
 * index pairs with the region on the left of a->b. Returns null when the input cannot be
 * triangulated as a closed region.
 */
export function triangulateRegion(coords: Float64Array, segs: ArrayLike<number>): RegionTriangulation | null {
  let del: Delaunator<ArrayLike<number>>;
  let con: InstanceType<typeof Constrainautor>;
  try {
    del = new Delaunator(coords);
    con = new Constrainautor(del);
    if (con.untriangulatedPoints().length > 0) return null;
    for (let i = 0; i < segs.length; i += 2) con.constrainOne(segs[i]!, segs[i + 1]!);
  } catch {
    return null;
  }
  const tri = del.triangles, half = del.halfedges;
  const nt = tri.length / 3;
  // Delaunator's triangles lie right of their half-edges, so the region's triangle on the left
  // of segment a->b is the triangle of half-edge b->a.
  const inside = new Uint8Array(nt);
  const stack: number[] = [];
  for (let i = 0; i < segs.length; i += 2) {
    const h = con.findEdge(segs[i + 1]!, segs[i]!);
    if (!(h >= 0) || !Number.isFinite(h)) return null;
    const t = Math.floor(h / 3);
    if (!inside[t]) {
      inside[t] = 1;
      stack.push(t);
    }
  }
  while (stack.length) {
    const t = stack.pop()!;
    for (let k = 0; k < 3; k++) {
      const h = 3 * t + k;
      if (con.isConstrained(h)) continue;
      const o = half[h]!;
      if (o < 0) return null; // reached the hull: the boundary is not closed
      const u = Math.floor(o / 3);
      if (!inside[u]) {
        inside[u] = 1;
        stack.push(u);
      }
    }
  }
  let n = 0;
  for (let t = 0; t < nt; t++) n += inside[t]!;
  const out = new Int32Array(n * 3);
  let o = 0;
  for (let t = 0; t < nt; t++) {
    if (!inside[t]) continue;
    // Counterclockwise: Delaunator's order reversed.
    out[o++] = tri[3 * t]!;
    out[o++] = tri[3 * t + 2]!;
    out[o++] = tri[3 * t + 1]!;
  }
  return { triangles: out };
}
