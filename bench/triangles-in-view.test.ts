import assert from 'node:assert/strict';
import { test } from 'node:test';
import type { ChunkData } from '../format/chunk.js';
import { forNeededTriangles } from './triangles-in-view.js';

// A chunk at origin (100, 200) with four triangles over the unit square's halves:
// 0: flat at z 0, face 1 (ends at z 5);
// 1: flat at z 0, face 2 (ends at z 3);
// 2: tilted from z 1 to z 3, face 3 (a merge's ramp, lives on);
// 3: flat at z 4, face 4, far off at x 10.
function chunk(): ChunkData {
  const corners = [
    [0, 0, 0], [1, 0, 0], [1, 1, 0],
    [0, 0, 0], [1, 1, 0], [0, 1, 0],
    [0, 0, 1], [1, 0, 2], [1, 1, 3],
    [10, 0, 4], [11, 0, 4], [11, 1, 4],
  ];
  const faces = [1, 2, 3, 4];
  const n = corners.length;
  return {
    vertexCount: n,
    triangleCount: n / 3,
    originX: 100,
    originY: 200,
    box: Float32Array.from([0, 0, 0, 11, 1, 4]),
    positions: Float32Array.from(corners.flat()),
    upper: Uint32Array.from(corners.map((_, i) => faces[Math.floor(i / 3)]!)),
    lower: new Uint32Array(n),
    upperClass: new Uint16Array(n),
    lowerClass: new Uint16Array(n),
    indices: Uint16Array.from(corners.map((_, i) => i)),
  };
}
const END = [0, 5, 3, Infinity, Infinity];
const endOf = (f: number): number => END[f]!;
const square: [number, number, number, number] = [100, 200, 101, 201];

function needed(z: number, box: [number, number, number, number]): [number, boolean][] {
  const out: [number, boolean][] = [];
  forNeededTriangles(chunk(), z, box, endOf, (t, cut) => out.push([t, cut]));
  return out;
}

test('a slice needs what lies at or below it, over its ground, whose upper face has not ended', () => {
  // Below the ramp's lowest corner: the two floor triangles, neither cut.
  assert.deepEqual(needed(0.5, square), [[0, false], [1, false]]);
  // At z 2 the ramp (corners at z 1 to 3) is cut; at 3.5 it lies below the slice, and face 2 has ended (at 3).
  assert.deepEqual(needed(2, square), [[0, false], [1, false], [2, true]]);
  assert.deepEqual(needed(3.5, square), [[0, false], [2, false]]);
  // Triangle 3 is needed only over its own ground.
  assert.deepEqual(needed(4.5, square), [[0, false], [2, false]]);
  assert.deepEqual(needed(5, square), [[2, false]]);
  assert.deepEqual(needed(4.5, [110, 200, 111, 201]), [[3, false]]);
});
