import test from 'node:test';
import assert from 'node:assert/strict';
import { planeDeficit } from './plane-deficit.js';

const near = (a: number, b: number): void => assert.ok(Math.abs(a - b) < 1e-12, `${a}, expected ${b}`);

test('two flat triangles: the deficit is the difference in z plus the gap, wherever they overlap', () => {
  const a = [0, 0, 4, 0, 0, 4], b = [1, 1, 3, 1, 1, 3];
  near(planeDeficit(a, [2, 2, 2], b, [5, 5, 5], 0.5), 3.5);
  near(planeDeficit(a, [9, 9, 9], b, [5, 5, 5], 0.5), -3.5);
});

test('a long ramp over a small surface at its low end: only the overlap counts, not the ramp\'s far corner', () => {
  // a rises from z 0 at x = 0 to z 10 at x = 100; b (z 3) covers x 40..50 near the middle.
  const a = [0, 0, 100, 0, 0, 10], za = [0, 10, 0];
  const b = [40, 0, 50, 0, 40, 1];
  // Over b, a is lowest at (40, 1): z 4 ... its plane z = x / 10, so at x = 40: 4 >= 3 + 0.5.
  near(planeDeficit(a, za, b, [3, 3, 3], 0.5), 3 + 0.5 - 4);
  // A surface at z 6 over the same spot: a must rise by 6.5 - 4 there.
  near(planeDeficit(a, za, b, [6, 6, 6], 0.5), 2.5);
  // The corner-wise rule (every corner of a above b's top) would lift a's corner at x = 0 to 6.5.
});

test('triangles that only touch, or lie apart, have no deficit; orientation does not matter', () => {
  const a = [0, 0, 4, 0, 0, 4];
  assert.equal(planeDeficit(a, [0, 0, 0], [4, 0, 0, 4, 4, 4], [9, 9, 9], 0), -Infinity, 'a shared edge');
  assert.equal(planeDeficit(a, [0, 0, 0], [10, 10, 12, 10, 10, 12], [9, 9, 9], 0), -Infinity, 'apart');
  const b = [1, 1, 3, 1, 1, 3];
  near(planeDeficit(a, [0, 0, 0], [b[0]!, b[1]!, b[4]!, b[5]!, b[2]!, b[3]!], [1, 1, 1], 0), 1);
});

test('a tilted surface under a tilted one: the deficit is at the overlap\'s worst vertex', () => {
  // Both over the unit square's lower triangle; a = x, b = 1 - x: they cross at x = 0.5, and
  // with gap 0 a is short by 1 at x = 0 (b 1, a 0).
  near(planeDeficit([0, 0, 1, 0, 0, 1], [0, 1, 0], [0, 0, 1, 0, 0, 1], [1, 0, 1], 0), 1);
});
