// Points that no edge uses (a removed spike's tip, a point merged into a nearer one) are
// dropped: kept, they were counted as vertices and widened the extent of the output. Ids keep
// their order, so input without such points keeps the same numbering.
import type { TopoEdge } from './topology-types.js';

/** Renumbers the edges' points in place to the used ones; returns their coordinates. */
export function dropUnusedPoints(edges: TopoEdge[], xs: Float64Array, ys: Float64Array): { xs: Float64Array; ys: Float64Array; count: number } {
  const nv = xs.length;
  const used = new Uint8Array(nv);
  for (const e of edges) for (const v of e.verts) used[v] = 1;
  const newId = new Int32Array(nv);
  let kept = 0;
  for (let v = 0; v < nv; v++) newId[v] = used[v] ? kept++ : -1;
  const keptXs = new Float64Array(kept), keptYs = new Float64Array(kept);
  for (let v = 0; v < nv; v++) {
    if (newId[v]! < 0) continue;
    keptXs[newId[v]!] = xs[v]!;
    keptYs[newId[v]!] = ys[v]!;
  }
  if (kept < nv) {
    for (const e of edges) {
      e.start = newId[e.start]!;
      e.end = newId[e.end]!;
      for (let i = 0; i < e.verts.length; i++) e.verts[i] = newId[e.verts[i]!]!;
    }
  }
  return { xs: keptXs, ys: keptYs, count: kept };
}
