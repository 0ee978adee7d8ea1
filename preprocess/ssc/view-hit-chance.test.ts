// The chunk split's cost model, worked by hand on a 100 x 100 extent whose views are 1/100 of
// the scale denominator wide and high: at the base scale 1:1000 a view is 10 x 10, and the
// whole extent fits at 1:10,000 (z = 1, with scale 1000 x 10^z).
import test from 'node:test';
import assert from 'node:assert/strict';
import { assertNear } from '../../testing/planar-fixtures.js';
import { viewHitChance } from './view-hit-chance.js';

const chance = viewHitChance({ extent: [0, 0, 100, 100], scaleAt: (z) => 1000 * 10 ** z, viewPerScale: [0.01, 0.01] });

test('a box seen only at the base scale gets the floor value', () => {
  assert.equal(chance(0, 0, 100, 100, 0, 0), 0.05);
});

test('a box over the whole extent is met by every view: the chance is the log-scale range it spans', () => {
  // From 1:1000 to 1:10,000: ln 10, plus 0.05.
  assertNear(chance(0, 0, 100, 100, 0, 1), Math.LN10 + 0.05, 'whole extent, z 0..1');
});

test('beyond the scale where the extent fits, every view is the whole extent', () => {
  // Scales are capped at 1:10,000, so z 1..2 spans no range (weight 0.05), and a view there is
  // 100 x 100: it meets a point when the point lies in it, (100 / 200)^2 = 1/4 of the places.
  assertNear(chance(0, 0, 100, 100, 1, 2), 0.05, 'whole extent, z 1..2');
  assertNear(chance(50, 50, 50, 50, 1, 2), 0.25 * 0.05, 'a point, z 1..2');
});

test('smaller boxes and shorter z ranges are less likely to be fetched', () => {
  const point = chance(50, 50, 50, 50, 0, 1);
  const quarter = chance(0, 0, 50, 50, 0, 1);
  const whole = chance(0, 0, 100, 100, 0, 1);
  assert.ok(point < quarter && quarter < whole, `${point} < ${quarter} < ${whole}`);
  assert.ok(chance(0, 0, 50, 50, 0, 0.5) < quarter);
});
