// Re-emitting a face whose drawing has cost too much, on the three faces of merge.test.ts:
// X = [0,6] x [0,4] has 5 segments around it (3 on the outside, 1 with S, 1 with Y: the
// corner (6,1) of S and Y splits its right side), so with factor 2 and slack 8 it may have
// cost 2 x 5 + 8 = 18 vertices.
import test from 'node:test';
import assert from 'node:assert/strict';
import { EventKind, REEMIT_PHASE } from '../../format/tgap-model.js';
import { planarStateOf, SMALL_BETWEEN_TWO } from '../../testing/planar-fixtures.js';
import { ALIVE } from './planar-state.js';
import { reemitCostlyFaces } from './reemit.js';

const X = 1, S = 2;
const FACES = SMALL_BETWEEN_TWO;
const LIMITS = { factor: 2, slack: 8 };

test('a face that cost up to its limit keeps its id', () => {
  const st = planarStateOf(FACES, ['x', 's', 'y']);
  assert.equal(st.faceVerts[X], 5);
  st.faceCost[X] = 18;
  assert.deepEqual(reemitCostlyFaces(st, [X], 1, LIMITS, () => assert.fail('no new face')), []);
});

test('a face that cost more is replaced by a new face of the same class, feature and area', () => {
  const st = planarStateOf(FACES, ['x', 's', 'y']);
  st.step = 3;
  st.faceCost[X] = 19;
  const made: number[] = [];
  // X twice, the outside and S (cost within its limit): X is re-emitted once.
  const events = reemitCostlyFaces(st, [X, 0, S, X], 3, LIMITS, (g) => made.push(g));
  assert.deepEqual(made, [4]);
  assert.deepEqual(events, [{ kind: EventKind.Reemit, step: 3, loser: X, into: 4 }]);
  const [old, now] = [st.faces[X]!, st.faces[4]!];
  assert.deepEqual([old.stepHigh, old.mergedInto, old.endPhase], [3, 4, REEMIT_PHASE]);
  assert.deepEqual([now.classIndex, now.feature, now.stepLow, now.stepHigh], [old.classIndex, old.feature, 3, ALIVE]);
  assert.equal(st.faceArea2[4], 48);
  // The new face has drawn just its current outline.
  assert.equal(st.faceCost[4], 5);
  assert.equal(st.resolve(X), 4);
});
