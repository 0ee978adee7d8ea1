// Splitting a road on a hand-drawn partition of [0,10] x [-5,6]:
//
//   B                                       B = above the road             area 51  (face 3)
//  (0,.5) (2,1) (4,1) (6,1) (8,1) (10,.5)   R = the road, pointed ends     area 8   (face 2)
//      <----------------------------->           ([2,8] x [0,1] = 6, and two tips of 1)
//         (2,0) (4,0) (6,0) (8,0)           A = below the road             area 51  (face 1)
//   A
//
// Worked by hand: every vertex on the road's lower side goes to A, on its upper side to B, and
// each tip to A (its two sides are equally long: the lower id). Every triangle of the road's
// triangulation joins its two sides, so its inner edges get midpoints at y = 0.5 and the cut
// runs along y = 0.5; at a tip the cut runs from the midpoint (2,.5) or (8,.5) to the tip. So
// A gets the half below y = 0.5 and B the half above: 4 each, and both end with 55.
import test from 'node:test';
import assert from 'node:assert/strict';
import { EventKind } from '../../format/tgap-model.js';
import { assertNear, classIndexOf, edgePoints, edgesBetween, fixtureStyle, planarStateOf, topologyOf, type FixtureFace } from '../../testing/planar-fixtures.js';
import { generalize } from './generalize.js';
import { handOver, splitFace } from './split.js';

const A = 1, R = 2, B = 3;
const CLASSES = ['a', 'road', 'b'];
const FACES: FixtureFace[] = [
  { cls: 'a', rings: [[[0, -5], [10, -5], [10, 0.5], [8, 0], [6, 0], [4, 0], [2, 0], [0, 0.5]]] },
  { cls: 'road', rings: [[[0, 0.5], [2, 0], [4, 0], [6, 0], [8, 0], [10, 0.5], [8, 1], [6, 1], [4, 1], [2, 1]]] },
  { cls: 'b', rings: [[[0, 0.5], [2, 1], [4, 1], [6, 1], [8, 1], [10, 0.5], [10, 6], [0, 6]]] },
];

test('a road is handed to the faces on either side, split along its centre line, areas preserved', () => {
  const st = planarStateOf(FACES, CLASSES);
  assertNear(st.faceArea2[A]! / 2, 51, 'A before');
  assertNear(st.faceArea2[R]! / 2, 8, 'road before');
  st.step = 1;
  const res = splitFace(st, R);
  assert.ok(res, 'the road can be split');
  assertNear(res.gains.get(A)! / 2, 4, 'A\'s share');
  assertNear(res.gains.get(B)! / 2, 4, 'B\'s share');
  // Every triangle of the road goes to one of its two neighbours, and together they cover it.
  let covered = 0;
  for (let t = 0; t < res.triFaces.length; t++) {
    assert.ok(res.triFaces[t] === A || res.triFaces[t] === B, `triangle ${t} goes to face ${res.triFaces[t]}`);
    const [a, b, c] = [res.tris[3 * t]!, res.tris[3 * t + 1]!, res.tris[3 * t + 2]!];
    covered += ((st.xs[b]! - st.xs[a]!) * (st.ys[c]! - st.ys[a]!) - (st.xs[c]! - st.xs[a]!) * (st.ys[b]! - st.ys[a]!)) / 2;
  }
  assertNear(covered, 8, 'area of the triangles');

  const { receivers } = handOver(st, R, res);
  assert.deepEqual(receivers, [A, B]);
  assertNear(st.faceArea2[A]! / 2, 55, 'A after');
  assertNear(st.faceArea2[B]! / 2, 55, 'B after');
  assert.equal(st.faces[R]!.stepHigh, 1);
  assert.equal(st.faces[R]!.mergedInto, -1, 'a split has no single winner');
  assert.equal(st.aliveFaces, 2);
  // The new boundary between A and B is the centre line, from tip to tip.
  const ab = edgesBetween(st, A, B);
  assert.ok(ab.length > 0);
  const xs: number[] = [];
  for (const e of ab) {
    for (const [x, y] of edgePoints(st, e)) {
      assert.equal(y, 0.5, `(${x}, ${y}) on the new boundary`);
      xs.push(x);
    }
  }
  assert.equal(Math.min(...xs), 0);
  assert.equal(Math.max(...xs), 10);
  assert.equal(edgesBetween(st, A, R).length + edgesBetween(st, B, R).length, 0, 'no edge of the road is left');
});

test('generalize splits a face of a linear class instead of merging it', () => {
  const topo = topologyOf(FACES);
  const classOf = classIndexOf(FACES, CLASSES);
  const style = fixtureStyle([{ key: 'a' }, { key: 'road', linear: true }, { key: 'b' }]);
  const out = generalize(topo, classOf, style, { baseScale: 1000, resolutionMm: 0.28 });
  // The road (8) is the least important. (Then A and B, redrawn as new faces, merge.)
  assert.deepEqual(out.events[0] && [out.events[0].kind, out.events[0].loser, out.events[0].into], [EventKind.Split, R, -1]);
  assert.equal(out.stats.splits, 1);
  assert.equal(out.stats.merges, 1);
  assert.equal(out.stats.splitFallbacks, 0);
  // The same road, not linear, is merged whole into A (the lower id; the shared lengths are equal).
  const merged = generalize(topologyOf(FACES), classOf, fixtureStyle(CLASSES.map((key) => ({ key }))), { baseScale: 1000, resolutionMm: 0.28 });
  assert.deepEqual(merged.events[0] && [merged.events[0].kind, merged.events[0].loser, merged.events[0].into], [EventKind.Merge, R, A]);
});
