// The segment of a piecewise-linear table that holds x: shared by zoom-time.ts and areaShare.

/** The last knot at or before x, strictly inside the table (knots[0] <= x < knots[n - 1]). */
export function knotBefore(knots: ArrayLike<number>, x: number): number {
  let lo = 0, hi = knots.length - 1;
  while (hi - lo > 1) {
    const mid = (lo + hi) >> 1;
    if (knots[mid]! <= x) lo = mid;
    else hi = mid;
  }
  return lo;
}
