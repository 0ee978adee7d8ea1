// Smooth merge (docs/FORMAT.md, "Smooth cube"): the z of each vertex of the loser's
// triangulated area is the time at which a front, starting on the boundary the loser shares
// with the winner and advancing along the triangulation's edges at an even speed, reaches it;
// where an older surface still lies in the loser's area the front waits above it. The winner
// thus takes the loser's area from that boundary outwards, and what it takes stays attached.
import FlatQueue from 'flatqueue';
import { orient } from '../geom/predicates.js';
import { knotBefore } from './knot-before.js';

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
  /**
   * The time in which the front advances evenly (zoom-time.ts: u, the log of the scale), as
   * increasing maps from z and back; without it, z itself.
   */
  time?: { u(z: number): number; z(u: number): number };
  /** Pace the front by the share of the area it has passed (areaShare), so that it takes about as much in each moment. */
  evenArea?: boolean;
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
  const time = b.time;
  if (!time) return evenFront(tris, xs, ys, shared, b);
  // The same front, even in u: every bound mapped to u, every arrival back to z.
  const toU = (m: ReadonlyMap<number, number>): Map<number, number> => new Map([...m].map(([v, z]) => [v, time.u(z)]));
  const u = evenFront(tris, xs, ys, toU(shared), { ...b, zFoot: time.u(b.zFoot), zMerge: time.u(b.zMerge), ...(b.lowest ? { lowest: toU(b.lowest) } : {}) });
  if (!u) return null;
  const z = new Map<number, number>();
  // Rounding on the way back must not carry a vertex past the merge or below its wait.
  for (const [v, uv] of u) z.set(v, Math.min(b.zMerge, Math.max(time.z(uv), b.lowest?.get(v) ?? -Infinity)));
  return z;
}

function evenFront(
  tris: ArrayLike<number>, xs: Float64Array, ys: Float64Array, shared: ReadonlyMap<number, number>, b: RampBounds,
): Map<number, number> | null {
  const { zFoot, zMerge } = b;
  let lowest = b.lowest;
  if (!(zFoot < zMerge) || tris.length === 0) return null;
  const graph = new MeshGraph(tris);
  const onBoundary = [...shared].filter(([v]) => graph.nbrs.has(v));
  // A vertex beside the winner only from zMerge on (a face held back shows there) cannot lead the front.
  const late = onBoundary.filter(([, z]) => z >= zMerge).map(([v]): [number, number] => [v, 0]);
  let sources: [number, number][] = onBoundary.filter(([, z]) => z < zMerge).map(([v, z]) => [v, Math.max(z, zFoot)]);
  if (sources.length === 0) return null;
  let d: Map<number, number>;
  let dMax: number;
  if (onBoundary.length === graph.nbrs.size) {
    // Every vertex lies beside the winner, each from its own time: the front sweeps from one
    // end (the farthest from the late vertices, which it reaches last) and waits for each.
    const [end] = largest(graph.arrivals(xs, ys, late.length > 0 ? late : [[tris[0]!, 0]], 1));
    d = graph.arrivals(xs, ys, [[end, 0]], 1);
    [, dMax] = largest(d);
    if (dMax === 0) return null;
    const waits = new Map(lowest);
    for (const [v, z] of shared) if (z < zMerge) waits.set(v, Math.max(waits.get(v) ?? -Infinity, z));
    lowest = waits;
    sources = [[end, zFoot]];
  } else {
    d = graph.arrivals(xs, ys, sources.map(([v]): [number, number] => [v, 0]), 1);
    [, dMax] = largest(d);
  }
  // From the earliest start across the farthest distance: without waits, and with every
  // source starting together, the farthest vertex gets zMerge exactly.
  let first = Infinity;
  for (const [, z] of sources) first = Math.min(first, z);
  if (!(first < zMerge)) return null;
  let z: Map<number, number> | null;
  if (b.evenArea) {
    // Paced in the share of the area the front has passed (areaShare), not in distance: time
    // tau in [0, dMax] is the distance at which that share is passed without waits.
    const share = areaShare(tris, xs, ys, d, dMax);
    const toTau = (x: number): number => dMax * share.inverse((x - first) / (zMerge - first));
    const fromTau = (tau: number): number => first + (zMerge - first) * share.at(tau / dMax);
    const tauLowest = lowest && new Map([...lowest].map(([v, x]) => [v, toTau(x)]));
    const tau = paced(graph, xs, ys, sources.map(([v, x]) => [v, toTau(x)]), tauLowest, 0, dMax, dMax);
    if (!tau) return null;
    z = new Map();
    for (const [v, t] of tau) z.set(v, Math.max(fromTau(t), lowest?.get(v) ?? -Infinity));
  } else {
    z = paced(graph, xs, ys, sources, lowest, first, zMerge, dMax);
  }
  if (!z) return null;
  for (const [v, zv] of z) if (zv > zMerge) z.set(v, zMerge);
  fillUnreached(graph, z, zMerge);
  return z;
}

/**
 * Arrivals of a front leaving `sources` at their starts at one pace: the slowest at which the
 * last vertex is reached by zMerge (`first`: the earliest start; dMax: the farthest distance).
 * null when even standing still a wait or a start lies past zMerge.
 */
function paced(graph: MeshGraph, xs: Float64Array, ys: Float64Array, sources: [number, number][], lowest: ReadonlyMap<number, number> | undefined, first: number, zMerge: number, dMax: number): Map<number, number> | null {
  const slowest = (zMerge - first) / dMax; // z per unit of distance
  const reach = (perUnit: number): Map<number, number> => graph.arrivals(xs, ys, sources, perUnit, lowest);
  // Rounding may carry the farthest vertex a hair past zMerge: not a wait.
  const late = (at: Map<number, number>): boolean => largest(at)[1] > zMerge + 1e-9 * Math.max(1, Math.abs(zMerge));
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
  return z;
}

/** Of the share of time, this much stays even in distance, so that the map stays strictly increasing. */
const EVEN_DISTANCE_SHARE = 0.25;

/**
 * The share of the area of `tris` that a front has passed at each distance (d: per vertex,
 * from the sources), each triangle's area spread evenly between its nearest and farthest
 * corner, mixed with the share of the distance (EVEN_DISTANCE_SHARE): an increasing
 * piecewise-linear map of [0, 1] (distance / dMax) onto [0, 1], and its inverse.
 */
export function areaShare(tris: ArrayLike<number>, xs: Float64Array, ys: Float64Array, d: ReadonlyMap<number, number>, dMax: number): { at(x: number): number; inverse(y: number): number } {
  const knots = [...new Set([0, ...[...d.values()].map((x) => Math.min(1, x / dMax)), 1])].sort((a, b) => a - b);
  const index = new Map(knots.map((k, i) => [k, i]));
  const n = knots.length;
  const density = new Float64Array(n), mass = new Float64Array(n);
  let total = 0;
  for (let i = 0; i + 2 < tris.length; i += 3) {
    const a = tris[i]!, b = tris[i + 1]!, c = tris[i + 2]!;
    const area = Math.abs(orient(xs[a]!, ys[a]!, xs[b]!, ys[b]!, xs[c]!, ys[c]!)) / 2;
    const ds = [a, b, c].map((v) => Math.min(1, (d.get(v) ?? dMax) / dMax));
    const lo = Math.min(...ds), hi = Math.max(...ds);
    total += area;
    if (hi > lo) {
      density[index.get(lo)!]! += area / (hi - lo);
      density[index.get(hi)!]! -= area / (hi - lo);
    } else {
      mass[index.get(lo)!]! += area;
    }
  }
  // Cumulative share at each knot.
  const ys2 = new Float64Array(n);
  let acc = 0, rho = 0;
  for (let i = 0; i < n; i++) {
    if (i > 0) acc += rho * (knots[i]! - knots[i - 1]!);
    acc += mass[i]!;
    rho += density[i]!;
    ys2[i] = acc;
  }
  // Area at distance 0 (a triangle with every corner on the sources) is passed at the start:
  // the share starts at 0 there, so that the front still starts at the earliest source's time.
  const k = EVEN_DISTANCE_SHARE;
  const at0 = ys2[0]!;
  for (let i = 0; i < n; i++) ys2[i] = (1 - k) * (total > 0 && acc > at0 ? (ys2[i]! - at0) / (acc - at0) : knots[i]!) + k * knots[i]!;
  const xs2 = Float64Array.from(knots);
  return { at: (x) => interpolate(xs2, ys2, x), inverse: (y) => interpolate(ys2, xs2, y) };
}

/** Piecewise-linear through (xk[i], yk[i]) (xk increasing), extended with slope 1 beyond the ends. */
function interpolate(xk: Float64Array, yk: Float64Array, x: number): number {
  const n = xk.length;
  if (x <= xk[0]!) return yk[0]! + (x - xk[0]!);
  if (x >= xk[n - 1]!) return yk[n - 1]! + (x - xk[n - 1]!);
  const lo = knotBefore(xk, x), hi = lo + 1;
  const t = (x - xk[lo]!) / (xk[hi]! - xk[lo]!);
  return yk[lo]! + t * (yk[hi]! - yk[lo]!);
}
