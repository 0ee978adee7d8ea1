// The smallest box x0, y0, x1, y1 around some points: what a projected outline covers, or an
// overlay feature's extent for its spatial index.
import type { Bbox } from './view.js';

export function boxAround(pts: Iterable<readonly [number, number]>): Bbox {
  const b: Bbox = [Infinity, Infinity, -Infinity, -Infinity];
  for (const [x, y] of pts) {
    b[0] = Math.min(b[0], x);
    b[1] = Math.min(b[1], y);
    b[2] = Math.max(b[2], x);
    b[3] = Math.max(b[3], y);
  }
  return b;
}
