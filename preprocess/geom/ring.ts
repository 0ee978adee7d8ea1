// Small helpers on rings stored as vertex-id lists over shared coordinate arrays.
export { ringArea2 } from '../../format/face-rings.js';

/** Twice the signed area (positive = counterclockwise) of a closed ring given as flat x,y pairs. */
export function ringArea2Flat(coords: ArrayLike<number>): number {
  const n = coords.length >> 1;
  if (n < 3) return 0;
  // Relative to the first point: national grid coordinates lose digits in the products otherwise.
  const x0 = coords[0]!, y0 = coords[1]!;
  let s = 0;
  for (let i = 1; i < n - 1; i++) {
    const ax = coords[2 * i]! - x0, ay = coords[2 * i + 1]! - y0;
    const bx = coords[2 * i + 2]! - x0, by = coords[2 * i + 3]! - y0;
    s += ax * by - bx * ay;
  }
  return s;
}

/** Length of the boundary of a closed ring given as flat x,y pairs (open: the closing segment is counted). */
export function ringPerimeterFlat(coords: ArrayLike<number>): number {
  const n = coords.length >> 1;
  let p = 0;
  for (let i = 0; i < n; i++) {
    const j = (i + 1) % n;
    p += Math.hypot(coords[2 * j]! - coords[2 * i]!, coords[2 * j + 1]! - coords[2 * i + 1]!);
  }
  return p;
}

/**
 * Twice the signed area contribution of an open chain relative to a reference point:
 * summing it over the oriented chains of a closed boundary gives twice its area.
 */
export function chainArea2(ids: ArrayLike<number>, xs: Float64Array, ys: Float64Array, rx: number, ry: number): number {
  let s = 0;
  for (let i = 0; i + 1 < ids.length; i++) {
    const ax = xs[ids[i]!]! - rx, ay = ys[ids[i]!]! - ry;
    const bx = xs[ids[i + 1]!]! - rx, by = ys[ids[i + 1]!]! - ry;
    s += ax * by - bx * ay;
  }
  return s;
}

/** Length of the closed ring through the vertex ids (without the closing id). */
export function ringLength(ids: ArrayLike<number>, xs: Float64Array, ys: Float64Array): number {
  const n = ids.length;
  if (n < 2) return 0;
  const a = ids[n - 1]!, b = ids[0]!;
  return chainLength(ids, xs, ys) + Math.hypot(xs[b]! - xs[a]!, ys[b]! - ys[a]!);
}

export function chainLength(ids: ArrayLike<number>, xs: Float64Array, ys: Float64Array): number {
  let s = 0;
  for (let i = 0; i + 1 < ids.length; i++) {
    s += Math.hypot(xs[ids[i + 1]!]! - xs[ids[i]!]!, ys[ids[i + 1]!]! - ys[ids[i]!]!);
  }
  return s;
}
