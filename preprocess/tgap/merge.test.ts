// Merging on a hand-drawn partition of [0,10] x [0,4]:
//
//   +-----------+---------+
//   |           |         |      X = [0,6] x [0,4]          area 24   (face 1)
//   |     X     |    Y    |      S = [6,7] x [0,1]          area 1    (face 2)
//   |           +--+      |      Y = the rest of [6,10]     area 15   (face 3)
//   |           |S |      |
//   +-----------+--+------+
//
// S shares 1 with X (x = 6, y 0..1) and 2 with Y (its top and its right side).
// Y shares 3 with X (x = 6, y 1..4).
import test from 'node:test';
import assert from 'node:assert/strict';
import { ALIVE } from './planar-state.js';
import { EventKind } from '../../format/tgap-model.js';
import { classIndexOf, edgePoints, edgesBetween, fixtureStyle, planarStateOf, SMALL_BETWEEN_TWO, topologyOf } from '../../testing/planar-fixtures.js';
import { generalize } from './generalize.js';
import { mergeFace, mostCompatibleNeighbour } from './merge.js';

const X = 1, S = 2, Y = 3;
const CLASSES = ['x', 's', 'y'];
const FACES = SMALL_BETWEEN_TWO;

/** compat[loser][neighbour] with 1 on the diagonal, the given overrides, else 1. */
function compat(over: Record<string, Record<string, number>>): Float64Array[] {
  return fixtureStyle(CLASSES.map((key) => ({ key })), over).compat;
}

test('the merge target is the neighbour with the highest shared length x compatibility', () => {
  const st = planarStateOf(FACES, CLASSES);
  // Equal compatibility: the longer boundary, Y (2 against 1).
  assert.deepEqual(mostCompatibleNeighbour(st, S, compat({})), { best: Y, count: 2 });
  // Y a quarter as compatible: 2 x 0.25 = 0.5 against X's 1.
  assert.deepEqual(mostCompatibleNeighbour(st, S, compat({ s: { y: 0.25 } })), { best: X, count: 2 });
  // A tie (2 x 0.5 = 1 x 1) goes to the lower id.
  assert.deepEqual(mostCompatibleNeighbour(st, S, compat({ s: { y: 0.5 } })), { best: X, count: 2 });
});

test('a merge gives the loser\'s area to the winner and joins the edges it leaves between the same faces', () => {
  const st = planarStateOf(FACES, CLASSES);
  st.step = 1;
  mergeFace(st, S, Y);
  assert.equal(st.faceArea2[Y]! / 2, 15 + 1);
  assert.equal(st.faces[S]!.stepHigh, 1);
  assert.equal(st.faces[S]!.mergedInto, Y);
  assert.equal(st.faceEdges[S], null);
  assert.equal(st.aliveFaces, 2);
  assert.equal(st.resolve(S), Y);
  // X|S and X|Y met at (6,1); both are now X|Y: one edge from (6,0) to (6,4).
  const xy = edgesBetween(st, X, Y);
  assert.equal(xy.length, 1);
  const pts = edgePoints(st, xy[0]!).map(([x, y]) => `${x},${y}`);
  assert.deepEqual(pts[0] === '6,0' ? pts : pts.reverse(), ['6,0', '6,1', '6,4']);
  // S's bottom and Y's outline met at (7,0): one edge around Y's outside now.
  assert.equal(edgesBetween(st, Y, 0).length, 1);
  assert.equal(st.faceEdges[Y]!.size, 2);
  assert.equal(edgesBetween(st, S, Y).length, 0);
});

test('generalize merges the least important face first, into its most compatible neighbour', () => {
  const topo = topologyOf(FACES);
  const classOf = classIndexOf(FACES, CLASSES);
  // Equal weights: S (area 1) goes first, into Y (the longer boundary); then Y, now 16, before
  // X (24), into X, its only neighbour.
  const plain = generalize(topo, classOf, fixtureStyle(CLASSES.map((key) => ({ key }))), { baseScale: 1000, resolutionMm: 0.28 });
  assert.deepEqual(plain.events.map((e) => [e.kind, e.loser, e.into]), [[EventKind.Merge, S, Y], [EventKind.Merge, Y, X]]);
  assert.deepEqual(plain.facesAlive, [3, 2, 1]);
  assert.equal(plain.stats.merges, 2);
  // S weighs 100 (importance 100): Y (15) goes first, into X (shares 3 with it, 2 with S);
  // then X + Y (39) into S, whose importance is 100.
  const heavy = generalize(topologyOf(FACES), classOf, fixtureStyle([{ key: 'x' }, { key: 's', weight: 100 }, { key: 'y' }]), { baseScale: 1000, resolutionMm: 0.28 });
  assert.deepEqual(heavy.events.map((e) => [e.kind, e.loser, e.into]), [[EventKind.Merge, Y, X], [EventKind.Merge, X, S]]);
  // What is left lives on to the end (two steps, so 3).
  assert.equal(heavy.faces[S]!.stepHigh, 3);
  assert.notEqual(heavy.faces[S]!.stepHigh, ALIVE);
});
