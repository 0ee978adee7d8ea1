// Time measured in zoom: u = ln(scale denominator), as a function of the cube's z, and back.
// A geometric zoom (the map's wheel and pinch, bench:smoothness) moves u at an even rate,
// while z per frame is proportional to the number of faces alive: over a transition one zoom
// level long, a frame at its start spans 4x the z of one at its end. A front that advances
// evenly in u, not in z, changes about as much of the map in each frame of such a zoom.
import type { ScaleInfo } from '../../format/scale.js';
import { knotBefore } from './knot-before.js';

export class ZoomTime {
  /** Knots: z, faces alive, and u at the knot. */
  private readonly zs: Float64Array;
  private readonly alive: Float64Array;
  private readonly us: Float64Array;
  /** u per step where the number of faces alive does not change (u must keep growing with z). */
  private readonly flat: number;

  constructor(info: ScaleInfo) {
    const t = info.scaleTable;
    const n = t.length;
    this.zs = Float64Array.from(t, (k) => k[0]);
    this.alive = Float64Array.from(t, (k) => Math.max(1, k[1]));
    this.flat = 0.5 / Math.max(1, info.baseFaces);
    this.us = new Float64Array(n);
    for (let i = 1; i < n; i++) {
      const f0 = this.alive[i - 1]!, f1 = this.alive[i]!;
      const dz = this.zs[i]! - this.zs[i - 1]!;
      this.us[i] = this.us[i - 1]! + (f1 < f0 ? 0.5 * Math.log(f0 / f1) : this.flat * dz);
    }
  }

  /** u at z (0 at the table's first knot; beyond its ends it grows at the flat rate). */
  u(z: number): number {
    const { zs, alive, us } = this;
    const n = zs.length;
    if (n === 1 || z <= zs[0]!) return us[0]! + this.flat * (z - zs[0]!);
    if (z >= zs[n - 1]!) return us[n - 1]! + this.flat * (z - zs[n - 1]!);
    const lo = knotBefore(zs, z), hi = lo + 1;
    const f0 = alive[lo]!, f1 = alive[hi]!;
    if (!(f1 < f0)) return us[lo]! + this.flat * (z - zs[lo]!);
    const f = f0 + ((z - zs[lo]!) / (zs[hi]! - zs[lo]!)) * (f1 - f0);
    return us[lo]! + 0.5 * Math.log(f0 / f);
  }

  /** The z at which u is reached: the inverse of u(z). */
  z(u: number): number {
    const { zs, alive, us } = this;
    const n = zs.length;
    if (n === 1 || u <= us[0]!) return zs[0]! + (u - us[0]!) / this.flat;
    if (u >= us[n - 1]!) return zs[n - 1]! + (u - us[n - 1]!) / this.flat;
    const lo = knotBefore(us, u), hi = lo + 1;
    const f0 = alive[lo]!, f1 = alive[hi]!;
    if (!(f1 < f0)) return zs[lo]! + (u - us[lo]!) / this.flat;
    const f = f0 * Math.exp(-2 * (u - us[lo]!));
    return zs[lo]! + ((f0 - f) / (f0 - f1)) * (zs[hi]! - zs[lo]!);
  }
}
