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
// Neighbouring triangles are cut as one where the midpoints they skip stay near the cut: here
// all of them lie on y = 0.5.
import test from 'node:test';
import assert from 'node:assert/strict';
import { EventKind } from '../../format/tgap-model.js';
import { pointSegmentDistance } from '../../format/point-segment.js';
import { assertNear, classIndexOf, edgePoints, edgesBetween, fixtureStyle, planarStateOf, topologyOf, type FixtureFace } from '../../testing/planar-fixtures.js';
import { generalize } from './generalize.js';
import { handOver, splitFace } from './split.js';
import type { PlanarState } from './planar-state.js';

const A = 1, R = 2, B = 3;
const CLASSES = ['a', 'road', 'b'];
const FACES: FixtureFace[] = [
  { cls: 'a', rings: [[[0, -5], [10, -5], [10, 0.5], [8, 0], [6, 0], [4, 0], [2, 0], [0, 0.5]]] },
  { cls: 'road', rings: [[[0, 0.5], [2, 0], [4, 0], [6, 0], [8, 0], [10, 0.5], [8, 1], [6, 1], [4, 1], [2, 1]]] },
  { cls: 'b', rings: [[[0, 0.5], [2, 1], [4, 1], [6, 1], [8, 1], [10, 0.5], [10, 6], [0, 6]]] },
];

/** Twice the signed area of triangle a b c (vertex ids of st): positive when counterclockwise. */
const twiceArea = (st: PlanarState, a: number, b: number, c: number): number =>
  (st.xs[b]! - st.xs[a]!) * (st.ys[c]! - st.ys[a]!) - (st.xs[c]! - st.xs[a]!) * (st.ys[b]! - st.ys[a]!);

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
    covered += twiceArea(st, a, b, c) / 2;
  }
  assertNear(covered, 8, 'area of the triangles');
  // Each piece lies on its receiver's side of the centre line and is counterclockwise.
  for (let t = 0; t < res.triFaces.length; t++) {
    const c = [0, 1, 2].map((j) => res.tris[3 * t + j]!);
    const ys = c.map((v) => st.ys[v]!);
    assert.ok(res.triFaces[t] === A ? ys.every((y) => y <= 0.5) : ys.every((y) => y >= 0.5), `triangle ${t} on its side`);
    const [a, b, d] = c as [number, number, number];
    assert.ok(twiceArea(st, a, b, d) > 0, `triangle ${t} counterclockwise`);
  }
  // The road's 8 triangles, each cut alone, make 22 pieces (a tip 2, a triangle of the strip
  // 3). Every midpoint lies on y = 0.5, so all 8 are cut as one, from tip to tip: each side is
  // a hexagon, 4 triangles.
  assert.equal(res.triFaces.length, 8);

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

/** Distance from (x, y) to the polyline `line`. */
const polylineDistance = (x: number, y: number, line: [number, number][]): number =>
  Math.min(...line.slice(1).map(([bx, by], i) => pointSegmentDistance(x, y, line[i]![0], line[i]![1], bx, by)));

/**
 * Splits the road (face R) of `faces`, whose ends lie on the map's edge (`onEdge`), and checks
 * that every piece is counterclockwise, that together they cover `area`, and that the new
 * boundary between A and B keeps within a quarter of the road's width (1) of `centre`. Where
 * the road's end meets the map's edge the boundary may end at a corner of the road (those
 * corners go to the face of their side): half the width.
 */
function assertCutAlong(faces: FixtureFace[], area: number, centre: [number, number][], onEdge: (x: number, y: number) => boolean): void {
  const st = planarStateOf(faces, CLASSES);
  st.step = 1;
  const res = splitFace(st, R);
  assert.ok(res, 'the road can be split');
  let covered = 0;
  for (let t = 0; t < res.triFaces.length; t++) {
    const [a, b, c] = [res.tris[3 * t]!, res.tris[3 * t + 1]!, res.tris[3 * t + 2]!];
    const a2 = twiceArea(st, a, b, c);
    assert.ok(a2 > 0, `triangle ${t} counterclockwise`);
    covered += a2 / 2;
  }
  assertNear(covered, area, 'area of the triangles');
  handOver(st, R, res);
  const ab = edgesBetween(st, A, B);
  const points = ab.flatMap((e) => edgePoints(st, e));
  for (const [x, y] of points) {
    const d = polylineDistance(x, y, centre);
    assert.ok(d <= (onEdge(x, y) ? 0.5 : 0.25), `(${x}, ${y}) on the new boundary lies ${d} from the centre line`);
  }
  // Between its points too, every 1/16 of each segment but those from a corner of the road's
  // end; and the centre line's corners lie as near the boundary.
  const boundary = ab.map((e) => edgePoints(st, e));
  for (const pts of boundary) {
    for (let i = 0; i + 1 < pts.length; i++) {
      if (onEdge(...pts[i]!) || onEdge(...pts[i + 1]!)) continue;
      for (let k = 1; k < 16; k++) {
        const x = pts[i]![0] + ((pts[i + 1]![0] - pts[i]![0]) * k) / 16, y = pts[i]![1] + ((pts[i + 1]![1] - pts[i]![1]) * k) / 16;
        const d = polylineDistance(x, y, centre);
        assert.ok(d <= 0.25, `(${x}, ${y}) between points of the new boundary lies ${d} from the centre line`);
      }
    }
  }
  for (const [x, y] of centre.slice(1, -1)) {
    const d = Math.min(...boundary.map((pts) => polylineDistance(x, y, pts)));
    assert.ok(d <= 0.25, `the centre line's corner (${x}, ${y}) lies ${d} from the new boundary`);
  }
  const ends = points.filter(([x, y]) => onEdge(x, y));
  assert.ok(ends.some(([x, y]) => polylineDistance(x, y, centre.slice(0, 2)) <= 0.5) && ends.some(([x, y]) => polylineDistance(x, y, centre.slice(-2)) <= 0.5), 'the boundary runs from end to end');
}

// An L-shaped road 1 wide round the corner (9, 1)-(10, 0), its sides cut every 2 units: A
// outside the bend, B inside it, both ends on the map's edge. Cut as one, the boundary would
// run across the bend.
test('a road round a corner is cut along its centre line, not across the corner', () => {
  assertCutAlong([
    { cls: 'a', rings: [[[0, -5], [12, -5], [12, 10], [10, 10], [10, 8], [10, 6], [10, 4], [10, 2], [10, 0], [8, 0], [6, 0], [4, 0], [2, 0], [0, 0]]] },
    { cls: 'road', rings: [[[0, 0], [2, 0], [4, 0], [6, 0], [8, 0], [10, 0], [10, 2], [10, 4], [10, 6], [10, 8], [10, 10], [9, 10], [9, 8], [9, 6], [9, 4], [9, 2], [9, 1], [8, 1], [6, 1], [4, 1], [2, 1], [0, 1]]] },
    { cls: 'b', rings: [[[0, 1], [2, 1], [4, 1], [6, 1], [8, 1], [9, 1], [9, 2], [9, 4], [9, 6], [9, 8], [9, 10], [0, 10]]] },
  ], 19, [[0, 0.5], [9.5, 0.5], [9.5, 10]], (x, y) => x === 0 || y === 10);
});

// A road 1 wide from x = 0 to 20 whose middle rises by 0.4. A straight cut from end to end
// would stay inside it, but 0.4 from its centre line at the bend.
test('a gently bent road is cut along its centre line, not straight from end to end', () => {
  const lower: [number, number][] = Array.from({ length: 11 }, (_, i) => [2 * i, 0.08 * Math.min(i, 10 - i)]);
  const upper = lower.map(([x, y]): [number, number] => [x, y + 1]);
  assertCutAlong([
    { cls: 'a', rings: [[[0, -5], [20, -5], ...lower.slice().reverse()]] },
    { cls: 'road', rings: [[...lower, ...upper.slice().reverse()]] },
    { cls: 'b', rings: [[...upper, [20, 6], [0, 6]]] },
  ], 20, [[0, 0.5], [10, 0.9], [20, 0.5]], (x) => x === 0 || x === 20);
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
