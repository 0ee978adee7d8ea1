// An area given as triangles, asked whether it holds a point: which face held back in a
// cascade lies under a ramp triangle (surfaces.ts names it the triangle's lower face).
import { orient } from '../geom/predicates.js';
import { trianglesOverlap } from '../geom/triangles-overlap.js';

export class AreaIndex {
  /** x0 y0 x1 y1 x2 y2 per triangle, in the first `used` entries (the rest is room to grow). */
  private corners = new Float64Array(0);
  private used = 0;
  private readonly box: [number, number, number, number] = [Infinity, Infinity, -Infinity, -Infinity];

  /** `tris`: vertex ids, 3 per triangle, counterclockwise, into xs and ys. */
  constructor(tris: readonly number[], xs: ArrayLike<number>, ys: ArrayLike<number>) {
    this.add(tris, xs, ys);
  }

  /** The area grows by triangles `tris` (what a face held back takes: a loser, a split's part, a removal's corner). */
  add(tris: readonly number[], xs: ArrayLike<number>, ys: ArrayLike<number>): void {
    const from = this.used;
    this.used += 2 * tris.length;
    if (this.used > this.corners.length) {
      // Doubling: a face that takes many small corners one by one is not copied each time.
      const corners = new Float64Array(Math.max(this.used, 2 * this.corners.length));
      corners.set(this.corners.subarray(0, from));
      this.corners = corners;
    }
    const corners = this.corners;
    tris.forEach((v, i) => {
      const x = xs[v]!, y = ys[v]!;
      corners[from + 2 * i] = x;
      corners[from + 2 * i + 1] = y;
      this.box[0] = Math.min(this.box[0], x);
      this.box[1] = Math.min(this.box[1], y);
      this.box[2] = Math.max(this.box[2], x);
      this.box[3] = Math.max(this.box[3], y);
    });
  }

  /** Whether (x, y) lies in one of the triangles (their edges included). */
  contains(x: number, y: number): boolean {
    const [x0, y0, x1, y1] = this.box;
    if (x < x0 || x > x1 || y < y0 || y > y1) return false;
    const c = this.corners;
    for (let i = 0; i < this.used; i += 6) {
      if (orient(c[i]!, c[i + 1]!, c[i + 2]!, c[i + 3]!, x, y) >= 0 && orient(c[i + 2]!, c[i + 3]!, c[i + 4]!, c[i + 5]!, x, y) >= 0 && orient(c[i + 4]!, c[i + 5]!, c[i]!, c[i + 1]!, x, y) >= 0) return true;
    }
    return false;
  }

  /** Whether triangle [x0, y0, x1, y1, x2, y2] overlaps one of the triangles (touching does not count). */
  overlaps(t: ArrayLike<number>): boolean {
    const [x0, y0, x1, y1] = this.box;
    if (Math.max(t[0]!, t[2]!, t[4]!) <= x0 || Math.min(t[0]!, t[2]!, t[4]!) >= x1 || Math.max(t[1]!, t[3]!, t[5]!) <= y0 || Math.min(t[1]!, t[3]!, t[5]!) >= y1) return false;
    const c = this.corners;
    for (let i = 0; i < this.used; i += 6) if (trianglesOverlap(t, c.subarray(i, i + 6))) return true;
    return false;
  }
}
