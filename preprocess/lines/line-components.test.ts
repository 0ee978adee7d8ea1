import test from 'node:test';
import assert from 'node:assert/strict';
import { lineComponentLabels, lineComponents } from './line-components.js';

test('polylines sharing a point are one piece; a near miss is not', () => {
  const a = [0, 0, 10, 0];
  const b = [10, 0, 10, 10]; // starts where a ends
  const c = [5, 5, 5, 20, 20, 20]; // apart from a and b
  const d = [20, 20, 30, 30]; // meets c at its last point
  const e = [10, 10.000001, 0, 10]; // misses b's end by a micrometre
  assert.equal(lineComponents([a, b, c, d, e]), 3);
  assert.equal(lineComponents([a, c]), 2);
  assert.equal(lineComponents([]), 0);
  // A crossing without a shared vertex does not join: lines meet only where they say so.
  assert.equal(lineComponents([[0, 0, 10, 10], [0, 10, 10, 0]]), 2);
});

test('each polyline gets its piece, numbered in order of first appearance', () => {
  const a = [0, 0, 10, 0];
  const b = [50, 50, 60, 60];
  const c = [10, 0, 10, 10]; // meets a
  const d = [60, 60, 70, 70, 0, 0]; // meets b, and a at its last point: all one piece
  assert.deepEqual([...lineComponentLabels([a, b, c])], [0, 1, 0]);
  assert.deepEqual([...lineComponentLabels([a, b, c, d])], [0, 0, 0, 0]);
  assert.deepEqual([...lineComponentLabels([b, a])], [0, 1]);
});
