// The importance queue on the three faces of SMALL_BETWEEN_TWO: X (area 24), S (1), Y (15).
import test from 'node:test';
import assert from 'node:assert/strict';
import { planarStateOf, SMALL_BETWEEN_TWO } from '../../testing/planar-fixtures.js';
import { ImportanceQueue } from './importance-queue.js';

const X = 1, S = 2, Y = 3;

function queue(weights: number[]): { q: ImportanceQueue; st: ReturnType<typeof planarStateOf> } {
  const st = planarStateOf(SMALL_BETWEEN_TWO, ['x', 's', 'y']);
  const q = new ImportanceQueue(st, weights, 16);
  for (const f of [X, S, Y]) q.update(f);
  return { q, st };
}

test('faces come out by area x class weight, least important first', () => {
  const plain = queue([1, 1, 1]).q;
  assert.deepEqual([plain.pop(), plain.pop(), plain.pop()], [S, Y, X]);
  assert.equal(plain.length, 0);
  // S weighs 100 (importance 100): after Y (15) and X (24).
  const heavy = queue([1, 100, 1]).q;
  assert.deepEqual([heavy.pop(), heavy.pop(), heavy.pop()], [Y, X, S]);
});

test('an entry whose importance changed, or whose face ended, comes out as -1', () => {
  const { q, st } = queue([1, 1, 1]);
  st.faceArea2[S] = 2 * 20;
  q.update(S); // S now 20: its old entry (1) is stale
  assert.equal(q.pop(), -1);
  st.step = 1;
  st.endFace(Y, X);
  assert.equal(q.pop(), -1, 'Y has ended');
  assert.deepEqual([q.pop(), q.pop()], [S, X]);
});

test('a face put back keeps its importance and its place', () => {
  const { q } = queue([1, 1, 1]);
  assert.equal(q.pop(), S);
  q.requeue(S);
  assert.deepEqual([q.pop(), q.pop(), q.pop()], [S, Y, X]);
});

test('face ids beyond the first table size are queued all the same', () => {
  const st = planarStateOf(SMALL_BETWEEN_TWO, ['x', 's', 'y']);
  const q = new ImportanceQueue(st, [1, 1, 1], 1);
  for (const f of [X, S, Y]) q.update(f);
  assert.deepEqual([q.pop(), q.pop(), q.pop()], [S, Y, X]);
});
