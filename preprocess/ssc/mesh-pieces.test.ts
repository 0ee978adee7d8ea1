import test from 'node:test';
import assert from 'node:assert/strict';
import { meshPieces } from './mesh-pieces.js';

const sorted = (pieces: number[][]): number[][] => pieces.map((p) => [...p].sort((a, b) => a - b)).sort((a, b) => a[0]! - b[0]!);

test('triangles sharing an edge or only a vertex are one piece; apart, two', () => {
  // A square of two triangles, a triangle touching it at vertex 2 only, and a triangle apart.
  const tris = [0, 1, 2, 0, 2, 3, 2, 4, 5, 10, 11, 12];
  assert.deepEqual(sorted(meshPieces(tris)), [[0, 1, 2, 3, 4, 5], [10, 11, 12]]);
});

test('pieces joined late by a triangle are merged, whatever the order', () => {
  const tris = [0, 1, 2, 5, 6, 7, 8, 9, 10, 2, 5, 8];
  assert.deepEqual(sorted(meshPieces(tris)), [[0, 1, 2, 5, 6, 7, 8, 9, 10]]);
  assert.deepEqual(meshPieces([]), []);
});
