// Smooth merge (docs/FORMAT.md, "Smooth cube"): the z of each vertex of the loser's
// triangulated area is the time at which a front, starting on the boundary the loser shares
// with the winner and advancing along the triangulation's edges at an even speed, reaches it;
// where an older surface still lies in the loser's area the front waits above it. The winner
// thus takes the loser's area from that boundary outwards, and what it takes stays attached.
import FlatQueue from 'flatqueue';

/** The vertices of a triangulation and their neighbours along its edges. */
class MeshGraph {
  readonly nbrs = new Map<number, number[]>();

  constructor(tris: ArrayLike<number>) {
    const link = (a: number, b: number): void => {
      let l = this.nbrs.get(a);
      if (!l) this.nbrs.set(a, (l = []));
      l.push(b);
    };
    for (let i = 0; i + 2 < tris.length; i += 3) {
      for (let j = 0; j < 3; j++) {
        const a = tris[i + j]!, b = tris[i + ((j + 1) % 3)]!;
        link(a, b);
        link(b, a);
      }
    }
  }

  /**
   * Earliest arrival of a front leaving each source at its start and taking `perUnit` (z) per
   * unit of edge length, held at each vertex until its `lowest` (Dijkstra: every step only adds).
   * Vertices no source reaches are left out.
   */
  arrivals(xs: Float64Array, ys: Float64Array, sources: Iterable<[vertex: number, start: number]>, perUnit: number, lowest?: ReadonlyMap<number, number>): Map<number, number> {
    const at = new Map<number, number>();
    const queue = new FlatQueue<number>();
    for (const [s, start] of sources) {
      if (!this.nbrs.has(s)) continue;
      const a = Math.max(start, lowest?.get(s) ?? -Infinity);
      if (a < (at.get(s) ?? Infinity)) {
        at.set(s, a);
        queue.push(s, a);
      }
    }
    while (queue.length > 0) {
      const av = queue.peekValue() ?? 0;
      const v = queue.pop() ?? -1;
      if (av > (at.get(v) ?? Infinity)) continue; // a stale entry
      for (const w of this.nbrs.get(v) ?? []) {
        const aw = Math.max(av + perUnit * Math.hypot(xs[w]! - xs[v]!, ys[w]! - ys[v]!), lowest?.get(w) ?? -Infinity);
        if (aw < (at.get(w) ?? Infinity)) {
          at.set(w, aw);
          queue.push(w, aw);
        }
      }
    }
    return at;
  }
}

/**
 * Shortest distances along the triangles' edges (Euclidean edge lengths) from the source
 * vertices (d = 0) to every vertex of `tris` (vertex ids, 3 per triangle). Along mesh edges,
 * every vertex but a source has a neighbour nearer the sources, so z taken from d has no local
 * minimum away from them: the winner's gain stays attached to the winner. Vertices no source
 * reaches get the largest distance found.
 */
export function meshDistances(tris: ArrayLike<number>, xs: Float64Array, ys: Float64Array, sources: Iterable<number>): Map<number, number> {
  const graph = new MeshGraph(tris);
  const d = graph.arrivals(xs, ys, [...sources].map((s): [number, number] => [s, 0]), 1);
  fillUnreached(graph, d, largest(d)[1]);
  return d;
}

function fillUnreached(graph: MeshGraph, at: Map<number, number>, value: number): void {
  for (const v of graph.nbrs.keys()) if (!at.has(v)) at.set(v, value);
}

const largest = (d: Map<number, number>): [vertex: number, d: number] => {
  let best: [number, number] = [-1, 0];
  for (const [v, x] of d) if (x > best[1]) best = [v, x];
  return best;
};

/** Bisections of the front's pace when older surfaces hold it back (to a 2^-20 share of the slowest). */
const SPEED_BISECTIONS = 20;

export interface RampBounds {
  /** No vertex below this: where the transition may start at the earliest. */
  zFoot: number;
  /** The merge's z: the transition is over here. */
  zMerge: number;
  /** Per vertex, the lowest z it may take: above the older surfaces in its triangles' area. */
  lowest?: ReadonlyMap<number, number>;
}

/**
 * z of every vertex of a smooth merge: the arrival of a front leaving each vertex of the
 * shared boundary (`shared`: vertex -> the z from which the winner lies beside it) no earlier
 * than zFoot, advancing at one speed along the edges and waiting at a vertex until its
 * `lowest`. The speed is the slowest at which the last vertex is reached by zMerge: without
 * waits the farthest vertex gets zMerge exactly; with them, the front moves faster elsewhere. When every vertex lies on the shared boundary
 * (an enclave in the winner, or a sliver), the front leaves from one end of the face's longest
 * path instead (two sweeps): the winner then sweeps across it from that vertex, still attached.
 * Every vertex but a source has a neighbour the front reached earlier, so the winner's gain
 * stays attached to the winner. null when it cannot tilt: no room in z, or no shared boundary.
 */
export function smoothMergeZ(
  tris: ArrayLike<number>, xs: Float64Array, ys: Float64Array, shared: ReadonlyMap<number, number>, b: RampBounds,
): Map<number, number> | null {
  const { zFoot, zMerge } = b;
  let lowest = b.lowest;
  if (!(zFoot < zMerge) || tris.length === 0) return null;
  const graph = new MeshGraph(tris);
  let sources: [number, number][] = [...shared].filter(([v]) => graph.nbrs.has(v)).map(([v, z]) => [v, Math.max(z, zFoot)]);
  if (sources.length === 0) return null;
  let d = graph.arrivals(xs, ys, sources.map(([v]): [number, number] => [v, 0]), 1);
  let [, dMax] = largest(d);
  if (dMax === 0) {
    const [end] = largest(graph.arrivals(xs, ys, [[tris[0]!, 0]], 1));
    d = graph.arrivals(xs, ys, [[end, 0]], 1);
    [, dMax] = largest(d);
    if (dMax === 0) return null;
    // Every vertex lies beside the winner, each from its own time: the front waits for it.
    const waits = new Map(lowest);
    for (const [v, z] of shared) waits.set(v, Math.max(waits.get(v) ?? -Infinity, z));
    lowest = waits;
    sources = [[end, zFoot]];
  }
  // From the earliest start across the farthest distance: without waits, and with every
  // source starting together, the farthest vertex gets zMerge exactly.
  let first = Infinity;
  for (const [, z] of sources) first = Math.min(first, z);
  if (!(first < zMerge)) return null;
  const slowest = (zMerge - first) / dMax; // z per unit of distance
  const reach = (perUnit: number): Map<number, number> => graph.arrivals(xs, ys, sources, perUnit, lowest);
  // Rounding may carry the farthest vertex a hair past zMerge: not a wait.
  const late = (at: Map<number, number>): boolean => largest(at)[1] > zMerge + 1e-9 * Math.max(1, zMerge);
  let z = reach(slowest);
  if (late(z)) {
    // Waits made the front late: the slowest pace that still arrives everywhere by zMerge.
    let lo = 0, hi = slowest;
    for (let i = 0; i < SPEED_BISECTIONS; i++) {
      const mid = (lo + hi) / 2;
      if (late(reach(mid))) hi = mid;
      else lo = mid;
    }
    z = reach(lo);
    // Even standing still, a wait past zMerge or a source starting after it leaves no room.
    if (late(z)) return null;
  }
  for (const [v, zv] of z) if (zv > zMerge) z.set(v, zMerge);
  fillUnreached(graph, z, zMerge);
  return z;
}
