// Candidate cuts and side boxes on eight hand-made triangles of one byte each, already sorted
// (list = 0..7).
import test from 'node:test';
import assert from 'node:assert/strict';
import { candidateCuts, sideBoxes, type SortedRange, type TriangleBoxes } from './chunk-cuts.js';

const list = Uint32Array.from({ length: 8 }, (_, i) => i);
const cost = new Float64Array(8).fill(1);
const range = (keys: number[], k: number): SortedRange => ({ list, key: (i) => keys[i]!, lo: 0, hi: 8, k, bytes: 8 });

test('into two chunks the cut falls half-way, where the bytes are even', () => {
  assert.deepEqual(candidateCuts(range([0, 1, 2, 3, 4, 5, 6, 7], 2), cost), [{ at: 4, kl: 1 }]);
  // Into four: after 2, 4 and 6 bytes.
  assert.deepEqual(candidateCuts(range([0, 1, 2, 3, 4, 5, 6, 7], 4), cost), [{ at: 2, kl: 1 }, { at: 4, kl: 2 }, { at: 6, kl: 3 }]);
});

test('a cut moves to a near change of key rather than cut through equal keys', () => {
  // Half-way (4) lies among five equal keys; the key changes one place on, at 5.
  assert.deepEqual(candidateCuts(range([0, 0, 0, 0, 0, 1, 1, 1], 2), cost), [{ at: 5, kl: 1 }]);
  // No change of key near: the cut stays.
  assert.deepEqual(candidateCuts(range([0, 0, 0, 0, 0, 0, 0, 0], 2), cost), [{ at: 4, kl: 1 }]);
});

test('the boxes on either side of each cut, and the bytes on the left', () => {
  // Triangle i: x i..i+1, y 0..i, z i/2..8.
  const col = (f: (i: number) => number): Float64Array => Float64Array.from({ length: 8 }, (_, i) => f(i));
  const boxes: TriangleBoxes = { x0: col((i) => i), x1: col((i) => i + 1), y0: col(() => 0), y1: col((i) => i), z0: col((i) => i / 2), z1: col(() => 8) };
  const r = range([0, 1, 2, 3, 4, 5, 6, 7], 4);
  const cuts = [{ at: 6, kl: 3 }, { at: 2, kl: 1 }];
  const { leftBox, rightBox, leftBytes } = sideBoxes(r, cuts, boxes, cost);
  assert.deepEqual(leftBytes, [6, 2]);
  // x0, y0, x1, y1, z0, z1
  assert.deepEqual(leftBox, [[0, 0, 6, 5, 0, 8], [0, 0, 2, 1, 0, 8]]);
  assert.deepEqual(rightBox, [[6, 0, 8, 7, 3, 8], [2, 0, 8, 7, 1, 8]]);
});
