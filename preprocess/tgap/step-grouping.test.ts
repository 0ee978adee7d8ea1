// Grouping events into steps, on a hand-drawn row of faces, all 1 high:
//
//   | S1 |    X    |    M1    |    M2    |    Y    | S2 |
//   0    1        11         31         51        61   63     (areas 1, 10, 20, 20, 10, 2)
//
// S1 merges into X and S2 into Y (their only neighbours). The faces those merges change or
// reshape are {S1, X, M1} and {S2, Y, M2}: they do not meet, so with grouping both merges
// fit in one step.
import test from 'node:test';
import assert from 'node:assert/strict';
import { classIndexOf, fixtureStyle, planarStateOf, rect, topologyOf, type FixtureFace } from '../../testing/planar-fixtures.js';
import { generalize } from './generalize.js';
import { eventNeighbourhood, StepLocks } from './step-grouping.js';

const [S1, X, M1, M2, Y, S2] = [1, 2, 3, 4, 5, 6];
const CLASSES = ['c'];
const SPANS: [number, number][] = [[0, 1], [1, 11], [11, 31], [31, 51], [51, 61], [61, 63]];
const FACES: FixtureFace[] = SPANS.map(([x0, x1]) => ({ cls: 'c', rings: [rect(x0, 0, x1, 1)] }));
const sorted = (s: Set<number>): number[] => [...s].sort((a, b) => a - b);

test('the neighbourhood of a merge: the loser, its neighbours and the winner\'s neighbours', () => {
  const st = planarStateOf(FACES, CLASSES);
  assert.deepEqual(sorted(eventNeighbourhood(st, S1, X, false)), [S1, X, M1]);
  assert.deepEqual(sorted(eventNeighbourhood(st, X, M1, false)), [S1, X, M1, M2]);
  // A split reshapes every neighbour of the loser: their neighbours too.
  assert.deepEqual(sorted(eventNeighbourhood(st, M1, X, true)), [S1, X, M1, M2, Y]);
});

test('locks claim all of a neighbourhood or none of it', () => {
  const locks = new StepLocks();
  assert.equal(locks.tryLock(new Set([S1, X, M1])), true);
  assert.equal(locks.tryLock(new Set([M1, M2])), false);
  assert.equal(locks.tryLock(new Set([M2, Y])), true, 'M2 was not claimed by the refused lock');
});

test('with grouping, events whose neighbourhoods do not meet share a step', () => {
  const classOf = classIndexOf(FACES, CLASSES);
  const style = fixtureStyle([{ key: 'c' }]);
  const first2 = (group: number): number[][] =>
    generalize(topologyOf(FACES), classOf, style, { baseScale: 1000, resolutionMm: 0.28, group }).events.slice(0, 2).map((e) => [e.step, e.loser, e.into]);
  assert.deepEqual(first2(1), [[1, S1, X], [2, S2, Y]]);
  assert.deepEqual(first2(2), [[1, S1, X], [1, S2, Y]]);
});
