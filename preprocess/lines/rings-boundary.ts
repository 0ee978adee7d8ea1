// A polygon given as rings (outer ring first, then holes; open, either orientation) as the
// directed boundary `centreline` takes: the outer ring counterclockwise, holes clockwise, so
// that the area lies left of every segment.
import { ringArea2Flat } from '../geom/ring.js';
import type { Boundary } from './centreline.js';

export function ringsBoundary(rings: readonly (readonly (readonly [number, number])[])[]): Boundary {
  const xs: number[] = [], ys: number[] = [], segs: number[] = [];
  rings.forEach((ring, i) => {
    const flat = ring.flat();
    const ccw = ringArea2Flat(flat) > 0;
    const pts = ccw === (i === 0) ? ring : [...ring].reverse();
    const first = xs.length;
    for (const [x, y] of pts) {
      xs.push(x);
      ys.push(y);
    }
    for (let k = 0; k < pts.length; k++) segs.push(first + k, first + ((k + 1) % pts.length));
  });
  return { xs, ys, segs };
}
