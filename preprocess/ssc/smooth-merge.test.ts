// Distances inside a hand-triangulated L-shaped face:
//
//   5 +--+ 4        0 (0,0)  1 (2,0)  2 (2,1)
//     |  |          3 (1,1)  4 (1,3)  5 (0,3)
//     |  |
//     |  +--+ 2     triangles 0 1 2, 0 2 3, 0 3 4, 0 4 5
//     |     |       sources: 1 and 2 (the foot's end, x = 2)
//   0 +-----+ 1
//
// Along the edges: d1 = d2 = 0, d3 = |2-3| = 1, d0 = |1-0| = 2 (not via 2: sqrt 5),
// d4 = d3 + |3-4| = 3 (not via 0: 2 + sqrt 10), d5 = d4 + |4-5| = 4 (not via 0: 2 + 3).
// Vertex 5 is 2 sqrt 2 from (2,1) in a straight line: the distance goes round the corner.
import test from 'node:test';
import assert from 'node:assert/strict';
import { meshDistances, smoothMergeZ } from './smooth-merge.js';

const xs = Float64Array.of(0, 2, 2, 1, 1, 0, 5, 6, 5);
const ys = Float64Array.of(0, 0, 1, 1, 3, 3, 0, 0, 1);
const TRIS = [0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 5];

test('distances run along the mesh edges from the shared boundary', () => {
  const d = meshDistances(TRIS, xs, ys, [1, 2]);
  assert.deepEqual([0, 1, 2, 3, 4, 5].map((v) => d.get(v)), [2, 0, 0, 1, 3, 4]);
});

test('vertices no source reaches get the largest distance', () => {
  // Triangle 6 7 8 stands apart.
  const d = meshDistances([...TRIS, 6, 7, 8], xs, ys, [1, 2]);
  assert.deepEqual([6, 7, 8].map((v) => d.get(v)), [4, 4, 4]);
});

test('z rises with the distance from just above zStart to zMerge', () => {
  // zStart 0, zMerge 16: the ramp starts a 16th of the way up, at 1, and climbs 15 over d = 4.
  const z = smoothMergeZ(TRIS, xs, ys, [1, 2], 0, 16);
  assert.deepEqual([0, 1, 2, 3, 4, 5].map((v) => z?.get(v)), [1 + 7.5, 1, 1, 1 + 3.75, 1 + 11.25, 16]);
});

test('a face all on the shared boundary is swept from one end of its longest path', () => {
  // From vertex 0 (the first) the farthest is 4 (sqrt 10, straight). From 4: d5 = 1, d3 = 2,
  // d2 = 3, d0 = sqrt 10 and d1 = 4, the largest: z = 1 + 15 d / 4.
  const z = smoothMergeZ(TRIS, xs, ys, [0, 1, 2, 3, 4, 5], 0, 16);
  const want = [1 + 3.75 * Math.sqrt(10), 16, 12.25, 8.5, 1, 4.75];
  want.forEach((w, v) => assert.ok(Math.abs((z?.get(v) ?? NaN) - w) < 1e-12, `vertex ${v}: ${z?.get(v)}, expected ${w}`));
});

test('without a shared boundary or room in z it does not tilt', () => {
  assert.equal(smoothMergeZ(TRIS, xs, ys, [], 0, 16), null);
  assert.equal(smoothMergeZ(TRIS, xs, ys, [1, 2], 16, 16), null);
});
