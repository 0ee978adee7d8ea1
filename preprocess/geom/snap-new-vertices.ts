// Points the generalization and the surfaces make (a split's midpoints and centres, a ramp's
// chord midpoints and apexes) onto the chunks' position grid, at a grid point that keeps their
// triangles counterclockwise. The input's points are on that grid already (position-grid.ts); a
// made point off it is rounded when a chunk is written, and a thin triangle at it could turn
// over there. Such a point need not be exactly a midpoint or a centre: it only cuts a triangle.
import { orient } from './predicates.js';

/** Grid points tried around a vertex, nearest first: within this many steps in x and y. */
const REACH = 2;

/** Offsets (in steps) of the grid points within REACH, by distance, then y, then x: a fixed order. */
const OFFSETS: [number, number][] = (() => {
  const out: [number, number][] = [];
  for (let dy = -REACH; dy <= REACH; dy++) for (let dx = -REACH; dx <= REACH; dx++) out.push([dx, dy]);
  return out.sort((p, q) => p[0] ** 2 + p[1] ** 2 - (q[0] ** 2 + q[1] ** 2) || p[1] - q[1] || p[0] - q[0]);
})();

/**
 * Moves each vertex from `first` to `end` (not included; ids into xs, ys, in this order), the
 * ones just made, onto the grid of `step`: to the
 * grid point nearest it (counting from the one it rounds to) at which every triangle of `tris`
 * (counterclockwise, 3 ids each) that uses it stays counterclockwise. A vertex with no such point
 * within REACH steps stays where it is. Each test uses the positions as they are by then, so
 * every triangle with a moved vertex is counterclockwise at the end if it was before. Returns the
 * number of vertices left off the grid.
 */
export function snapNewVertices(tris: ArrayLike<number>, xs: Float64Array, ys: Float64Array, first: number, end: number, step: number): number {
  if (end <= first || !(step > 0)) return 0;
  const around = new Map<number, number[]>();
  for (let t = 0; t + 2 < tris.length; t += 3) {
    for (let j = 0; j < 3; j++) {
      const v = tris[t + j]!;
      if (v < first || v >= end) continue;
      let l = around.get(v);
      if (!l) around.set(v, (l = []));
      l.push(t);
    }
  }
  const ccw = (t: number): boolean => {
    const a = tris[t]!, b = tris[t + 1]!, c = tris[t + 2]!;
    return orient(xs[a]!, ys[a]!, xs[b]!, ys[b]!, xs[c]!, ys[c]!) > 0;
  };
  let off = 0;
  for (let v = first; v < end; v++) {
    const x = xs[v]!, y = ys[v]!;
    const gx = Math.round(x / step), gy = Math.round(y / step);
    if (gx * step === x && gy * step === y) continue;
    const mine = around.get(v) ?? [];
    const at = OFFSETS.find(([dx, dy]) => {
      xs[v] = (gx + dx) * step;
      ys[v] = (gy + dy) * step;
      return mine.every(ccw);
    });
    if (!at) {
      xs[v] = x;
      ys[v] = y;
      off++;
    }
  }
  return off;
}
