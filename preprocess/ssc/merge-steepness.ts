// How evenly a smooth merge's front advances (issue 11): the coefficient of variation of
// |grad z| over the merge's triangles, weighted by area. 0: one even slope, the front moves at
// one speed; flat triangles inside a ramp count as |grad z| = 0 (they go at once).
import type { Surfaces } from './surfaces.js';

/** |grad z| of triangle i of `s` (z per ground unit) and its area; area 0 for a degenerate one. */
export function triangleSlope(s: Surfaces, i: number, xs: Float64Array, ys: Float64Array): { slope: number; area: number } {
  const a = s.v[3 * i]!, b = s.v[3 * i + 1]!, c = s.v[3 * i + 2]!;
  const za = s.z[3 * i]!, zb = s.z[3 * i + 1]!, zc = s.z[3 * i + 2]!;
  const bx = xs[b]! - xs[a]!, by = ys[b]! - ys[a]!, cx = xs[c]! - xs[a]!, cy = ys[c]! - ys[a]!;
  const area2 = bx * cy - cx * by;
  if (area2 === 0) return { slope: 0, area: 0 };
  // The plane z = za + gx (x - xa) + gy (y - ya) through the three corners.
  const gx = ((zb - za) * cy - (zc - za) * by) / area2;
  const gy = (bx * (zc - za) - cx * (zb - za)) / area2;
  return { slope: Math.hypot(gx, gy), area: Math.abs(area2) / 2 };
}

/** The area-weighted coefficient of variation of |grad z| over triangles `tris` of `s` (NaN: no slope at all). */
export function slopeVariation(s: Surfaces, tris: readonly number[], xs: Float64Array, ys: Float64Array): number {
  let w = 0, sum = 0, sum2 = 0;
  for (const i of tris) {
    const { slope, area } = triangleSlope(s, i, xs, ys);
    w += area;
    sum += area * slope;
    sum2 += area * slope * slope;
  }
  if (w === 0 || sum === 0) return NaN;
  const mean = sum / w;
  return Math.sqrt(Math.max(0, sum2 / w - mean * mean)) / mean;
}
