// A face's area as triangles, from the edges around it: the edges are joined into rings
// (split where the face touches itself), holes are put in the outer ring that holds them, and
// earcut triangulates. Should earcut's triangles not add up to the face's area (a degenerate
// configuration), a constrained Delaunay triangulation of the boundary is used instead.
import { triangulateRegion } from '../geom/cdt.js';
import { LocalVertices } from '../geom/local-vertices.js';
import { earcutFace, faceArea2, type FaceEdge } from '../../format/face-rings.js';

export type { FaceEdge };

export interface TriangulateStats {
  earcut: number;
  fallback: number;
  failed: number;
}

/** Counterclockwise triangles (3 vertex ids each), appended to `out`; returns how many. */
export function triangulateFace(edges: FaceEdge[], xs: Float64Array, ys: Float64Array, out: number[], stats: TriangulateStats): number {
  if (edges.length === 0) return 0;
  const before = out.length;
  if (earcutFace(edges, xs, ys, out)) {
    stats.earcut++;
    return (out.length - before) / 3;
  }
  if (cdtEdges(edges, xs, ys, out)) {
    stats.fallback++;
    return (out.length - before) / 3;
  }
  stats.failed++;
  throw new Error(`cannot triangulate a face of ${edges.length} edges (area ${faceArea2(edges, xs, ys) / 2})`);
}

function cdtEdges(edges: FaceEdge[], xs: Float64Array, ys: Float64Array, out: number[]): boolean {
  const lv = new LocalVertices();
  const segs: number[] = [];
  for (const e of edges) {
    const n = e.verts.length;
    for (let k = 0; k + 1 < n; k++) {
      const a = e.verts[k]!, b = e.verts[k + 1]!;
      if (e.forward) segs.push(lv.of(a), lv.of(b));
      else segs.push(lv.of(b), lv.of(a));
    }
  }
  const r = triangulateRegion(lv.coords(xs, ys), segs);
  if (!r) return false;
  for (const t of r.triangles) out.push(lv.ids[t]!);
  return true;
}
