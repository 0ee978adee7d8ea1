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
import { areaShare, meshDistances, smoothMergeZ } from './smooth-merge.js';

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

const at = (vs: number[], z: number): Map<number, number> => new Map(vs.map((v) => [v, z]));
const zsOf = (z: Map<number, number> | null): number[] => [0, 1, 2, 3, 4, 5].map((v) => z?.get(v) ?? NaN);

test('z rises with the distance from the shared boundary to zMerge', () => {
  // Sources 1 and 2 start at zFoot 1; zMerge 16: 15 over the farthest distance, d5 = 4.
  const z = smoothMergeZ(TRIS, xs, ys, at([1, 2], 0), { zFoot: 1, zMerge: 16 });
  assert.deepEqual(zsOf(z), [1 + 7.5, 1, 1, 1 + 3.75, 1 + 11.25, 16]);
});

test('a source starts when the winner comes to lie beside it', () => {
  // Source 1 from 1, source 2 only from 5. From 1 alone (d 0 1 2 2 4 5 for vertices 1 2 0 3 4 5)
  // at 3 per unit the front reaches 5 at 16; from 2 it could not before 5 + 3 * 4 = 17.
  // Vertex 2 is reached from 1 at 4, before its own start; 3 at 1 + 3 * 2 = 7, 4 at 13.
  const z = smoothMergeZ(TRIS, xs, ys, new Map([[1, 0], [2, 5]]), { zFoot: 1, zMerge: 16 });
  const want = [7, 1, 4, 7, 13, 16];
  want.forEach((w, v) => assert.ok(Math.abs(zsOf(z)[v]! - w) < 1e-4, `vertex ${v}: ${zsOf(z)[v]}, expected ${w}`));
});

test('the front waits above older surfaces, slows to arrive by zMerge, and stays attached', () => {
  // Vertex 3 may not go below 12: the front waits there, and 4 and 5 beyond it come later.
  const lowest = new Map([[3, 12]]);
  const z = smoothMergeZ(TRIS, xs, ys, at([1, 2], 0), { zFoot: 1, zMerge: 16, lowest });
  const zs = zsOf(z);
  assert.ok(zs[3]! >= 12, `vertex 3 at ${zs[3]}`);
  assert.ok(Math.max(...zs) <= 16 && Math.max(...zs) > 16 - 1e-4, `last vertex at ${Math.max(...zs)}, not zMerge`);
  // Attached: every vertex but the sources has a neighbour the front reached no later.
  const nbrs: Record<number, number[]> = { 0: [1, 2, 3, 4, 5], 3: [0, 2, 4], 4: [0, 3, 5], 5: [0, 4] };
  for (const [v, ns] of Object.entries(nbrs)) assert.ok(ns.some((n) => zs[n]! <= zs[Number(v)]!), `vertex ${v} is a local minimum`);
  // To arrive by zMerge all the same, the front moves faster where the wait does not hold it.
  const free = zsOf(smoothMergeZ(TRIS, xs, ys, at([1, 2], 0), { zFoot: 1, zMerge: 16 }));
  assert.ok(zs[0]! < free[0]!, `vertex 0 at ${zs[0]}, ${free[0]} without the wait`);
});

test('a face all on the shared boundary is swept from one end of its longest path', () => {
  // From vertex 0 (the first) the farthest is 4 (sqrt 10, straight). From 4: d5 = 1, d3 = 2,
  // d2 = 3, d0 = sqrt 10 and d1 = 4, the largest: z = 1 + 15 d / 4.
  const z = smoothMergeZ(TRIS, xs, ys, at([0, 1, 2, 3, 4, 5], 0), { zFoot: 1, zMerge: 16 });
  const want = [1 + 3.75 * Math.sqrt(10), 16, 12.25, 8.5, 1, 4.75];
  want.forEach((w, v) => assert.ok(Math.abs((z?.get(v) ?? NaN) - w) < 1e-12, `vertex ${v}: ${z?.get(v)}, expected ${w}`));
});

test('a face all on the shared boundary with a vertex beside the winner only after zMerge is swept toward that vertex', () => {
  // Vertex 1 lies beside the winner from z 20 only (a face held back shows there): no start.
  // Farthest from 1 along the edges: 5 (d 5, round 2, 3, 4 or along 0). From 5: d4 = 1,
  // d0 = 3, d3 = 3, d2 = 4, d1 = 5, the largest: z = 1 + 15 d / 5.
  const shared = at([0, 2, 3, 4, 5], 0);
  shared.set(1, 20);
  const z = smoothMergeZ(TRIS, xs, ys, shared, { zFoot: 1, zMerge: 16 });
  const want = [10, 16, 13, 10, 4, 1];
  want.forEach((w, v) => assert.ok(Math.abs((z?.get(v) ?? NaN) - w) < 1e-12, `vertex ${v}: ${z?.get(v)}, expected ${w}`));
});

test('without a shared boundary or room in z it does not tilt', () => {
  assert.equal(smoothMergeZ(TRIS, xs, ys, new Map(), { zFoot: 0, zMerge: 16 }), null);
  assert.equal(smoothMergeZ(TRIS, xs, ys, at([1, 2], 0), { zFoot: 16, zMerge: 16 }), null);
  assert.equal(smoothMergeZ(TRIS, xs, ys, at([1, 2], 16), { zFoot: 0, zMerge: 16 }), null);
});

test('areaShare: the share of the area a front has passed, and its inverse', () => {
  // Square (0,0)-(2,2) as two triangles, distances from the left side x = 0: d = x.
  const sx = Float64Array.of(0, 2, 2, 0), sy = Float64Array.of(0, 0, 2, 2);
  const d = new Map([[0, 0], [1, 2], [2, 2], [3, 0]]);
  const share = areaShare([0, 1, 2, 0, 2, 3], sx, sy, d, 2);
  // Each triangle's area is spread evenly over x in [0, 2]: half the area by x = 1.
  assert.ok(Math.abs(share.at(0.5) - 0.5) < 1e-12);
  assert.equal(share.at(0), 0);
  assert.equal(share.at(1), 1);
  for (const x of [0.1, 0.37, 0.9]) assert.ok(Math.abs(share.inverse(share.at(x)) - x) < 1e-12);
});

test('areaShare: each triangle\'s area is spread between its nearest and farthest corner, mixed with distance', () => {
  // (0,0) (0,4) (1,2) (4,2); sources 0 and 1 (x = 0). Triangle 0 1 2 has area 2 over d 0..1,
  // triangle 0 2 3 area 3 over d 0..4. Passed by d = 1: 2 + 3 / 4 = 2.75 of 5 = 0.55; mixed 3:1
  // with the distance share 1/4: 0.75 * 0.55 + 0.25 * 0.25 = 0.475. The front gets more time
  // where more area lies (0.475 of it for the first quarter of the distance).
  const wedge = areaShare([0, 1, 2, 0, 2, 3], Float64Array.of(0, 0, 1, 4), Float64Array.of(0, 4, 2, 2), new Map([[0, 0], [1, 0], [2, 1], [3, 4]]), 4);
  assert.ok(Math.abs(wedge.at(0.25) - 0.475) < 1e-12, `${wedge.at(0.25)}`);
  assert.ok(Math.abs(wedge.inverse(0.475) - 0.25) < 1e-12);
});
