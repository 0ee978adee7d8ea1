// How many triangles cover a point: tests compare two cuts of the same ground by it.

/** How many of `tris` (x, y of 3 corners each, counterclockwise) hold (x, y) strictly inside. */
export function cover(tris: readonly (readonly number[])[], x: number, y: number): number {
  let n = 0;
  for (const t of tris) {
    const s = (i: number, j: number): number => (t[2 * j]! - t[2 * i]!) * (y - t[2 * i + 1]!) - (t[2 * j + 1]! - t[2 * i + 1]!) * (x - t[2 * i]!);
    if (s(0, 1) > 0 && s(1, 2) > 0 && s(2, 0) > 0) n++;
  }
  return n;
}
