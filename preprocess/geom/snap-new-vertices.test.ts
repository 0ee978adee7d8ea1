import assert from 'node:assert/strict';
import { test } from 'node:test';
import { orient } from './predicates.js';
import { snapNewVertices } from './snap-new-vertices.js';

/** Triangle 0 1 2 fanned around vertex 3. */
const FAN = [0, 1, 3, 1, 2, 3, 2, 0, 3];

const ccwAll = (tris: number[], xs: Float64Array, ys: Float64Array): boolean => {
  for (let t = 0; t < tris.length; t += 3) {
    const [a, b, c] = [tris[t]!, tris[t + 1]!, tris[t + 2]!];
    if (!(orient(xs[a]!, ys[a]!, xs[b]!, ys[b]!, xs[c]!, ys[c]!) > 0)) return false;
  }
  return true;
};

test('a new centre goes to the grid point it rounds to when its triangles stay counterclockwise', () => {
  // Triangle (0,0) (8,0) (0,8) on a grid of 1, its centre (8/3, 8/3) fanned to the corners.
  const xs = Float64Array.of(0, 8, 0, 8 / 3), ys = Float64Array.of(0, 0, 8, 8 / 3);
  assert.equal(snapNewVertices(FAN, xs, ys, 3, 4, 1), 0);
  assert.deepEqual([xs[3], ys[3]], [3, 3]);
  assert.ok(ccwAll(FAN, xs, ys));
});

test('the nearest grid point that keeps the triangles counterclockwise, not the one it rounds to', () => {
  // Triangle (0,0) (20,2) (0,6) on a grid of 1, fanned around a new point at (10.4, 1.1), just
  // above the side (0,0)-(20,2) (y = 1.04 there). It rounds to (10, 1), on that side: flat. Of
  // the points one step from (10, 1), (10, 0) lies outside and (9, 1) inside (the side is at
  // 0.9 there).
  const xs = Float64Array.of(0, 20, 0, 10.4), ys = Float64Array.of(0, 2, 6, 1.1);
  assert.ok(ccwAll(FAN, xs, ys), 'counterclockwise before');
  assert.equal(snapNewVertices(FAN, xs, ys, 3, 4, 1), 0);
  assert.deepEqual([xs[3], ys[3]], [9, 1]);
  assert.ok(ccwAll(FAN, xs, ys));
});

test('a point with no grid point nearby that keeps its triangles stays where it is, and is counted', () => {
  // A sliver 0.2 high on a grid of 1: no grid point lies strictly inside it.
  const xs = Float64Array.of(0.5, 10.5, 5.5, 5.5), ys = Float64Array.of(0.3, 0.3, 0.5, 0.4);
  assert.equal(snapNewVertices(FAN, xs, ys, 3, 4, 1), 1);
  assert.deepEqual([xs[3], ys[3]], [5.5, 0.4]);
});

test('points already on the grid, and a step of 0, leave everything as it is', () => {
  const xs = Float64Array.of(0, 8, 0, 3), ys = Float64Array.of(0, 0, 8, 3);
  assert.equal(snapNewVertices(FAN, xs, ys, 3, 4, 1), 0);
  xs[3] = 2.6;
  assert.equal(snapNewVertices(FAN, xs, ys, 3, 4, 0), 0);
  assert.equal(xs[3], 2.6);
});
