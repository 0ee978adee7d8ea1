// simplifyEdge on a hand-drawn boundary between two faces A (below) and B (above):
//
//   B      (7,0.5)
//  (0,0)  /      \
//    \___/        (10,0)        the boundary (0,0) - (3,-0.2) - (7,0.5) - (10,0)
//  (3,-0.2)                     in the square [0,10] x [-4,4]
//   A
//
// Areas of the triangles a removal takes away (worked by hand, cross products / 2):
//   (3,-0.2) between (0,0) and (7,0.5): |3*0.5 + 0.2*7| / 2 = 1.45
//   (7,0.5) between (3,-0.2) and (10,0): |4*0.2 - 0.7*7| / 2 = 2.05
//   (7,0.5) between (0,0) and (10,0), once (3,-0.2) is gone: 10*0.5 / 2 = 2.5
//   (3,-0.2) between (0,0) and (10,0), once (7,0.5) is gone: 10*0.2 / 2 = 1
// The threshold is tol^2 / 2. A's area: 40 below y = 0, plus what the boundary encloses above
// it: -0.3 + 0.6 + 0.75 = 1.05, so 41.05; B's is 80 - 41.05 = 38.95.
import test from 'node:test';
import assert from 'node:assert/strict';
import { assertNear, edgePoints, edgesBetween, planarStateOf, vertexAt, type FixtureFace, type XY } from '../../testing/planar-fixtures.js';
import { simplifyEdge, StepTriangles } from './simplify.js';

const A = 1, B = 2;
const below: XY[] = [[0, -4], [10, -4], [10, 0], [7, 0.5], [3, -0.2], [0, 0]];
const above: XY[] = [[0, 0], [3, -0.2], [7, 0.5], [10, 0], [10, 4], [0, 4]];
/** A small island in B, inside the triangle (0,0), (3,-0.2), (7,0.5) but above the line y = 0. */
const island: XY[] = [[2.5, 0.1], [3.5, 0.1], [3, 0.15]];

function fixture(withIsland: boolean): ReturnType<typeof planarStateOf> {
  const faces: FixtureFace[] = [
    { cls: 'a', rings: [below] },
    { cls: 'b', rings: withIsland ? [above, island] : [above] },
  ];
  if (withIsland) faces.push({ cls: 'c', rings: [island] });
  return planarStateOf(faces, ['a', 'b', 'c']);
}

function boundary(st: ReturnType<typeof planarStateOf>): number {
  const edges = edgesBetween(st, A, B);
  assert.equal(edges.length, 1, 'one edge between A and B');
  return edges[0]!;
}

test('the vertex with the smaller triangle goes first, and removals stop at the tolerance', () => {
  const st = fixture(false);
  const e = boundary(st);
  // threshold 1.8^2 / 2 = 1.62: (3,-0.2) at 1.45 goes; (7,0.5) at 2.05, then 2.5, stays.
  const id = simplifyEdge(st, e, 1.8, new StepTriangles());
  assert.notEqual(id, e, 'a new version of the edge');
  assert.equal(st.edgeAlive[e], 0);
  assert.deepEqual([...st.edges[id]!.parents], [e]);
  assert.deepEqual([...st.edges[id]!.removed], [vertexAt(st, 3, -0.2)]);
  const pts = edgePoints(st, id).map(([x, y]) => `${x},${y}`).sort();
  assert.deepEqual(pts, ['0,0', '10,0', '7,0.5']);
  // The triangle under the chord (0,0)-(7,0.5) was B's and is now A's.
  assertNear(st.faceArea2[A]! / 2, 41.05 + 1.45, 'area of A');
  assertNear(st.faceArea2[B]! / 2, 38.95 - 1.45, 'area of B');
});

test('with a larger tolerance both vertices go, smallest triangle first, and the areas still add up', () => {
  const st = fixture(false);
  const e = boundary(st);
  // threshold 4.5: 1.45 first, then (7,0.5) at 2.5.
  const id = simplifyEdge(st, e, 3, new StepTriangles());
  assert.deepEqual([...st.edges[id]!.removed], [vertexAt(st, 3, -0.2), vertexAt(st, 7, 0.5)]);
  // Both triangles lie under the chord (0,0)-(7,0.5) (so does (10,0)): they overlap, and the
  // second removal of the step comes in the next phase.
  assert.deepEqual([...st.edges[id]!.removedPhase], [1, 2]);
  assert.equal(st.edges[id]!.verts.length, 2, 'a straight edge is left');
  assertNear(st.faceArea2[A]! / 2, 40, 'area of A');
  assertNear(st.faceArea2[B]! / 2, 40, 'area of B');
});

test('a removal whose chord would cross another boundary is refused', () => {
  const st = fixture(true);
  const e = boundary(st);
  const areaA = st.faceArea2[A]!;
  // Only (3,-0.2) is under the threshold, and its chord (0,0)-(7,0.5) would pass above the
  // island (y = 0.21 at x = 3): the island would end up on A's side.
  assert.equal(simplifyEdge(st, e, 1.8, new StepTriangles()), e, 'nothing removed');
  assert.equal(st.edgeAlive[e], 1);
  assert.equal(st.faceArea2[A], areaA);
  assert.equal(st.alive[vertexAt(st, 3, -0.2)], 1);
});

test('a refused vertex goes once its new chord no longer crosses', () => {
  const st = fixture(true);
  const e = boundary(st);
  // (3,-0.2) is refused first; (7,0.5) goes; then (3,-0.2)'s chord is (0,0)-(10,0), under the island.
  const id = simplifyEdge(st, e, 3, new StepTriangles());
  assert.deepEqual([...st.edges[id]!.removed], [vertexAt(st, 7, 0.5), vertexAt(st, 3, -0.2)]);
  assertNear(st.faceArea2[A]! / 2, 40, 'area of A');
});

test('removal triangles of one step that overlap get successive phases', () => {
  const tris = new StepTriangles();
  const t1 = Float64Array.of(0, 0, 4, 0, 0, 4);
  assert.equal(tris.phaseFor(t1), 1);
  tris.add(t1, 1);
  // Shares only t1's side (4,0)-(0,4): interiors apart.
  assert.equal(tris.phaseFor(Float64Array.of(4, 0, 4, 4, 0, 4)), 1);
  // Overlaps t1's interior.
  const t2 = Float64Array.of(1, 1, 5, 1, 1, 5);
  assert.equal(tris.phaseFor(t2), 2);
  tris.add(t2, 2);
  // Overlaps t2, which is in phase 2.
  assert.equal(tris.phaseFor(Float64Array.of(2, 2, 3, 2, 2, 3)), 3);
  tris.clear();
  assert.equal(tris.phaseFor(t2), 1, 'a new step starts again at phase 1');
});
