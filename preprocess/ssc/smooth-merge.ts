// Smooth merge (docs/FORMAT.md, "Smooth cube"): the z of each vertex of the loser's
// triangulated area rises with its distance inside the loser from the boundary it shares with
// the winner, so the winner takes the loser's area from that boundary outwards.
import FlatQueue from 'flatqueue';

/**
 * Shortest distances along the triangles' edges (Euclidean edge lengths) from the source
 * vertices (d = 0) to every vertex of `tris` (vertex ids, 3 per triangle). Along mesh edges,
 * every vertex but a source has a neighbour nearer the sources, so z taken from d has no local
 * minimum away from them: the winner's gain stays attached to the winner. Vertices no source
 * reaches get the largest distance found.
 */
export function meshDistances(tris: ArrayLike<number>, xs: Float64Array, ys: Float64Array, sources: Iterable<number>): Map<number, number> {
  const nbrs = new Map<number, number[]>();
  const link = (a: number, b: number): void => {
    let l = nbrs.get(a);
    if (!l) nbrs.set(a, (l = []));
    l.push(b);
  };
  for (let i = 0; i + 2 < tris.length; i += 3) {
    for (let j = 0; j < 3; j++) {
      const a = tris[i + j]!, b = tris[i + ((j + 1) % 3)]!;
      link(a, b);
      link(b, a);
    }
  }
  const d = new Map<number, number>();
  const queue = new FlatQueue<number>();
  for (const s of sources) {
    if (!nbrs.has(s) || d.has(s)) continue;
    d.set(s, 0);
    queue.push(s, 0);
  }
  while (queue.length > 0) {
    const dv = queue.peekValue() ?? 0;
    const v = queue.pop() ?? -1;
    if (dv > (d.get(v) ?? Infinity)) continue; // a stale entry
    for (const w of nbrs.get(v) ?? []) {
      const dw = dv + Math.hypot(xs[w]! - xs[v]!, ys[w]! - ys[v]!);
      if (dw < (d.get(w) ?? Infinity)) {
        d.set(w, dw);
        queue.push(w, dw);
      }
    }
  }
  let dMax = 0;
  for (const x of d.values()) dMax = Math.max(dMax, x);
  for (const v of nbrs.keys()) if (!d.has(v)) d.set(v, dMax);
  return d;
}

/**
 * Where the ramp starts above zStart, as a share of the transition: the loser's latest surface
 * may lie at zStart itself, and a triangle with all three corners on the shared boundary would
 * tie with it in depth (16ths of a phase still differ in float32 up to about 2^16 steps).
 */
const START_GAP = 1 / 16;

const largest = (d: Map<number, number>): [vertex: number, d: number] => {
  let best: [number, number] = [-1, 0];
  for (const [v, x] of d) if (x > best[1]) best = [v, x];
  return best;
};

/**
 * z of every vertex of a smooth merge: just above zStart on the shared boundary, rising with the
 * distance to zMerge at the farthest vertex. When every vertex lies on the shared boundary (an
 * enclave in the winner, or a sliver), the distance is taken from one end of the face's longest
 * path instead (two sweeps): the winner then sweeps across it from that vertex, still attached.
 * null when it cannot tilt: no room in z, or no shared boundary.
 */
export function smoothMergeZ(
  tris: ArrayLike<number>, xs: Float64Array, ys: Float64Array, shared: Iterable<number>, zStart: number, zMerge: number,
): Map<number, number> | null {
  if (!(zStart < zMerge) || tris.length === 0) return null;
  let d = meshDistances(tris, xs, ys, shared);
  let [, dMax] = largest(d);
  if (dMax === 0) {
    if (![...shared].some((v) => d.has(v))) return null;
    const [end] = largest(meshDistances(tris, xs, ys, [tris[0]!]));
    if (end < 0) return null;
    d = meshDistances(tris, xs, ys, [end]);
    [, dMax] = largest(d);
  }
  const z = new Map<number, number>();
  const z0 = zStart + (zMerge - zStart) * START_GAP;
  for (const [v, dv] of d) z.set(v, dv < dMax ? z0 + ((zMerge - z0) * dv) / dMax : zMerge);
  return z;
}
