// Exact orientation tests. robust-predicates returns a negative value for a left turn;
// we flip it so that every caller reads "positive = c lies left of a->b (counterclockwise)".
import { orient2d } from 'robust-predicates';

export function orient(ax: number, ay: number, bx: number, by: number, cx: number, cy: number): number {
  return -orient2d(ax, ay, bx, by, cx, cy);
}

/** True when c lies on the closed segment a-b (exactly). */
export function onSegment(ax: number, ay: number, bx: number, by: number, cx: number, cy: number): boolean {
  if (orient(ax, ay, bx, by, cx, cy) !== 0) return false;
  return Math.min(ax, bx) <= cx && cx <= Math.max(ax, bx) && Math.min(ay, by) <= cy && cy <= Math.max(ay, by);
}

/**
 * True when the closed segments a-b and c-d share at least one point.
 * Callers exclude pairs that legitimately share an endpoint.
 */
export function segmentsIntersect(
  ax: number, ay: number, bx: number, by: number,
  cx: number, cy: number, dx: number, dy: number,
): boolean {
  const o1 = orient(ax, ay, bx, by, cx, cy);
  const o2 = orient(ax, ay, bx, by, dx, dy);
  const o3 = orient(cx, cy, dx, dy, ax, ay);
  const o4 = orient(cx, cy, dx, dy, bx, by);
  if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0))) return true;
  if (o1 === 0 && onSegment(ax, ay, bx, by, cx, cy)) return true;
  if (o2 === 0 && onSegment(ax, ay, bx, by, dx, dy)) return true;
  if (o3 === 0 && onSegment(cx, cy, dx, dy, ax, ay)) return true;
  if (o4 === 0 && onSegment(cx, cy, dx, dy, bx, by)) return true;
  return false;
}

/**
 * Strictly inside triangle (a, b, c) given in either orientation, or on its side a-c
 * (the chord that replaces a-b-c when b is removed) without being a or c.
 */
export function blocksRemoval(
  ax: number, ay: number, bx: number, by: number, cx: number, cy: number, px: number, py: number,
): boolean {
  const s = orient(ax, ay, bx, by, cx, cy);
  if (s === 0) return onSegment(ax, ay, cx, cy, px, py) && !(px === ax && py === ay) && !(px === cx && py === cy);
  const d1 = orient(ax, ay, bx, by, px, py);
  const d2 = orient(bx, by, cx, cy, px, py);
  const d3 = orient(cx, cy, ax, ay, px, py);
  if (s > 0) {
    if (d1 < 0 || d2 < 0 || d3 < 0) return false;
    if (d1 > 0 && d2 > 0 && d3 > 0) return true;
  } else {
    if (d1 > 0 || d2 > 0 || d3 > 0) return false;
    if (d1 < 0 && d2 < 0 && d3 < 0) return true;
  }
  // On the boundary of the triangle: only the chord a-c (open) blocks; points on a-b or b-c
  // are vertices of the same chain (never other vertices in a valid partition).
  return d3 === 0 && !(px === ax && py === ay) && !(px === cx && py === cy);
}
