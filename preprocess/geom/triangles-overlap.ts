// Whether two triangles' interiors overlap (separating axis test): triangles that only touch,
// along an edge or at a vertex, do not. Coordinates are flat [x0, y0, x1, y1, x2, y2].

/** Overlaps shallower than this share of an axis' length count as touching (rounding). */
const TOUCH = 1e-9;

function separated(a: ArrayLike<number>, b: ArrayLike<number>): boolean {
  for (let i = 0; i < 3; i++) {
    const j = (i + 1) % 3;
    // The normal of a's edge i -> j.
    const nx = a[2 * j + 1]! - a[2 * i + 1]!, ny = a[2 * i]! - a[2 * j]!;
    let aMin = Infinity, aMax = -Infinity, bMin = Infinity, bMax = -Infinity;
    for (let k = 0; k < 3; k++) {
      const pa = nx * a[2 * k]! + ny * a[2 * k + 1]!;
      const pb = nx * b[2 * k]! + ny * b[2 * k + 1]!;
      aMin = Math.min(aMin, pa);
      aMax = Math.max(aMax, pa);
      bMin = Math.min(bMin, pb);
      bMax = Math.max(bMax, pb);
    }
    const tol = TOUCH * Math.max(aMax - aMin, bMax - bMin, Math.hypot(nx, ny));
    if (Math.min(aMax, bMax) - Math.max(aMin, bMin) <= tol) return true;
  }
  return false;
}

export function trianglesOverlap(a: ArrayLike<number>, b: ArrayLike<number>): boolean {
  return !separated(a, b) && !separated(b, a);
}
