// When two segments of the rings (as point ids) conflict: they cross, or touch other than at
// a shared end, or run along each other from a shared end. Both the per-ring check for
// self-intersections and the check of the whole partition use it.
import Flatbush from 'flatbush';
import { orient, segmentsIntersect } from '../geom/predicates.js';

export function segmentsConflict(a: number, b: number, c: number, d: number, xs: Float64Array, ys: Float64Array): boolean {
  if (a === c || a === d || b === c || b === d) {
    // Sharing one point is fine unless the two run along each other.
    const shared = a === c || a === d ? a : b;
    const p = shared === a ? b : a, q = shared === c ? d : c;
    return p === q || (orient(xs[shared]!, ys[shared]!, xs[p]!, ys[p]!, xs[q]!, ys[q]!) === 0 &&
      (xs[p]! - xs[shared]!) * (xs[q]! - xs[shared]!) + (ys[p]! - ys[shared]!) * (ys[q]! - ys[shared]!) > 0);
  }
  return segmentsIntersect(xs[a]!, ys[a]!, xs[b]!, ys[b]!, xs[c]!, ys[c]!, xs[d]!, ys[d]!);
}

/** A point where segments ab and cd meet (the middle of ab when they are parallel). */
export function crossingPoint(a: number, b: number, c: number, d: number, xs: Float64Array, ys: Float64Array): [number, number] {
  const ax = xs[a]!, ay = ys[a]!, bx = xs[b]!, by = ys[b]!, cx = xs[c]!, cy = ys[c]!, dx = xs[d]!, dy = ys[d]!;
  const den = (bx - ax) * (dy - cy) - (by - ay) * (dx - cx);
  if (den === 0) return [(ax + bx) / 2, (ay + by) / 2];
  const t = ((cx - ax) * (dy - cy) - (cy - ay) * (dx - cx)) / den;
  const tc = Math.max(0, Math.min(1, t));
  return [ax + tc * (bx - ax), ay + tc * (by - ay)];
}

/** Every pair of segments (point ids from[i] -> to[i]) whose boxes meet, each pair once with i < j. */
export function forEachNearPair(from: ArrayLike<number>, to: ArrayLike<number>, xs: Float64Array, ys: Float64Array, visit: (i: number, j: number) => void): void {
  const n = from.length;
  if (n === 0) return;
  const box = (i: number): [number, number, number, number] => {
    const a = from[i]!, b = to[i]!;
    return [Math.min(xs[a]!, xs[b]!), Math.min(ys[a]!, ys[b]!), Math.max(xs[a]!, xs[b]!), Math.max(ys[a]!, ys[b]!)];
  };
  const index = new Flatbush(n);
  for (let i = 0; i < n; i++) index.add(...box(i));
  index.finish();
  const hits: number[] = [];
  for (let i = 0; i < n; i++) {
    hits.length = 0;
    index.search(...box(i), (j) => {
      if (j > i) hits.push(j);
      return false;
    });
    for (const j of hits) visit(i, j);
  }
}
