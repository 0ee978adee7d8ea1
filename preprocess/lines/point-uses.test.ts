import test from 'node:test';
import assert from 'node:assert/strict';
import { pointKey, pointUses } from './point-uses.js';

test('vertices at each point: a junction of three polylines, a closed ring\'s first and last', () => {
  const uses = pointUses([[0, 0, 5, 5], [5, 5, 10, 0], [5, 5, 5, 10], [20, 20, 30, 20, 30, 30, 20, 20]]);
  assert.equal(uses.get(pointKey(5, 5)), 3);
  assert.equal(uses.get(pointKey(0, 0)), 1);
  assert.equal(uses.get(pointKey(20, 20)), 2);
  assert.equal(uses.get(pointKey(5, 5.000001)), undefined, 'only exactly equal coordinates meet');
  assert.equal(uses.size, 7);
});
