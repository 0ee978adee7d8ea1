// How far one tilted triangle must rise to lie a gap above another where they overlap. z is
// linear on each, so their difference is linear on the overlap (a convex polygon, clipped
// here), and its vertices bound it: the check is exact, not a per-corner guess that holds a
// long triangle's far corners up because one end crosses a small surface.

/** Coordinates flat [x0, y0, x1, y1, x2, y2]. */
type Tri = ArrayLike<number>;

/**
 * The most `a` (z per corner `za`) lies less than `gap` above `b` (z per corner `zb`) over
 * the interiors they share: > 0 means a must rise by that much; -Infinity when they only touch
 * or do not meet (overlaps thinner than `touch` of b's size count as touching).
 */
export function planeDeficit(a: Tri, za: ArrayLike<number>, b: Tri, zb: ArrayLike<number>, gap: number, touch = 1e-9): number {
  const areaB = cross(b, 0, 1, 2);
  if (areaB === 0 || cross(a, 0, 1, 2) === 0) return -Infinity;
  const sign = Math.sign(areaB);
  let poly: number[] = [a[0]!, a[1]!, a[2]!, a[3]!, a[4]!, a[5]!];
  const size = Math.max(Math.abs(b[2]! - b[0]!), Math.abs(b[3]! - b[1]!), Math.abs(b[4]! - b[0]!), Math.abs(b[5]! - b[1]!));
  for (let e = 0; e < 3 && poly.length >= 6; e++) {
    const x0 = b[2 * e]!, y0 = b[2 * e + 1]!, x1 = b[(2 * e + 2) % 6]!, y1 = b[(2 * e + 3) % 6]!;
    const len = Math.hypot(x1 - x0, y1 - y0);
    // Signed distance inside b's edge e (positive inside).
    const side = (x: number, y: number): number => (sign * ((x1 - x0) * (y - y0) - (y1 - y0) * (x - x0))) / len;
    const next: number[] = [];
    const n = poly.length / 2;
    for (let i = 0; i < n; i++) {
      const px = poly[2 * i]!, py = poly[2 * i + 1]!, qx = poly[(2 * i + 2) % (2 * n)]!, qy = poly[(2 * i + 3) % (2 * n)]!;
      const sp = side(px, py), sq = side(qx, qy);
      if (sp >= 0) next.push(px, py);
      if ((sp > 0 && sq < 0) || (sp < 0 && sq > 0)) {
        const t = sp / (sp - sq);
        next.push(px + t * (qx - px), py + t * (qy - py));
      }
    }
    poly = next;
  }
  if (poly.length < 6 || Math.abs(polygonArea2(poly)) <= touch * size * size) return -Infinity;
  let worst = -Infinity;
  for (let i = 0; i < poly.length; i += 2) {
    const x = poly[i]!, y = poly[i + 1]!;
    worst = Math.max(worst, planeAt(b, zb, x, y) + gap - planeAt(a, za, x, y));
  }
  return worst;
}

function cross(t: Tri, i: number, j: number, k: number): number {
  return (t[2 * j]! - t[2 * i]!) * (t[2 * k + 1]! - t[2 * i + 1]!) - (t[2 * k]! - t[2 * i]!) * (t[2 * j + 1]! - t[2 * i + 1]!);
}

function polygonArea2(p: readonly number[]): number {
  let s = 0;
  for (let i = 0; i < p.length; i += 2) {
    const j = (i + 2) % p.length;
    s += p[i]! * p[j + 1]! - p[j]! * p[i + 1]!;
  }
  return s;
}

/** z at (x, y) on the plane through t's corners. */
function planeAt(t: Tri, z: ArrayLike<number>, x: number, y: number): number {
  const d = cross(t, 0, 1, 2);
  const l1 = ((x - t[0]!) * (t[5]! - t[1]!) - (t[4]! - t[0]!) * (y - t[1]!)) / d;
  const l2 = ((t[2]! - t[0]!) * (y - t[1]!) - (x - t[0]!) * (t[3]! - t[1]!)) / d;
  return (1 - l1 - l2) * z[0]! + l1 * z[1]! + l2 * z[2]!;
}
