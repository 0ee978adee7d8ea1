// The triangles drawn: the upward (counterclockwise) ones, chosen from the file's coordinates.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { keepUpwardTriangles } from './upward-triangles.js';

describe('the inside-facing triangles', () => {
  test('are the counterclockwise ones; clockwise and degenerate ones are dropped', () => {
    const pos = Float32Array.from([0, 0, 0, 1, 0, 0, 0, 1, 0, 2, 2, 0]);
    const idx = Uint16Array.from([0, 1, 2, 0, 2, 1, 1, 2, 3, 0, 3, 0, 1, 3, 2]);
    const n = keepUpwardTriangles(pos, idx);
    assert.equal(n, 2);
    assert.deepEqual([...idx.subarray(0, 6)], [0, 1, 2, 1, 3, 2]);
  });
});
