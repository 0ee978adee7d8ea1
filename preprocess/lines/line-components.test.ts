import test from 'node:test';
import assert from 'node:assert/strict';
import { lineComponentLabels, lineComponents, mainPiece, pieceLabels, pointIds } from './line-components.js';

test('polylines sharing a point are one piece; a near miss is not', () => {
  const a = [0, 0, 10, 0];
  const b = [10, 0, 10, 10]; // starts where a ends
  const c = [5, 5, 5, 20, 20, 20]; // apart from a and b
  const d = [20, 20, 30, 30]; // meets c at its last point
  const e = [10, 10.000001, 0, 10]; // misses b's end by a micrometre
  assert.equal(lineComponents([a, b, c, d, e]), 3);
  assert.equal(lineComponents([a, c]), 2);
  assert.equal(lineComponents([]), 0);
  // A crossing without a shared vertex does not join: lines meet only where they say so.
  assert.equal(lineComponents([[0, 0, 10, 10], [0, 10, 10, 0]]), 2);
});

test('each polyline gets its piece, numbered in order of first appearance', () => {
  const a = [0, 0, 10, 0];
  const b = [50, 50, 60, 60];
  const c = [10, 0, 10, 10]; // meets a
  const d = [60, 60, 70, 70, 0, 0]; // meets b, and a at its last point: all one piece
  assert.deepEqual([...lineComponentLabels([a, b, c])], [0, 1, 0]);
  assert.deepEqual([...lineComponentLabels([a, b, c, d])], [0, 0, 0, 0]);
  assert.deepEqual([...lineComponentLabels([b, a])], [0, 1]);
});

test('the main piece is the longest, whatever its number of lines', () => {
  const line = (coords: number[][]): { paths: number[][]; length: number } => {
    let length = 0;
    for (const p of coords) for (let k = 2; k < p.length; k += 2) length += Math.hypot(p[k]! - p[k - 2]!, p[k + 1]! - p[k - 1]!);
    return { paths: coords, length };
  };
  const short1 = line([[0, 0, 1, 0]]);
  const short2 = line([[1, 0, 2, 0], [1, 0, 1, 1]]); // meets short1; two polylines of one line
  const short3 = line([[2, 0, 3, 0]]); // meets short2: 4 m in three lines
  const long = line([[10, 10, 20, 10]]); // 10 m alone
  assert.deepEqual(mainPiece([short1, short2, short3, long]), [long]);
  assert.deepEqual(mainPiece([short1, short2, short3]), [short1, short2, short3]);
  assert.deepEqual(mainPiece([]), []);
});

test('point ids computed once count the pieces of any subset as the coordinates do', () => {
  const paths = [[0, 0, 10, 0], [10, 0, 10, 10], [10, 10, 20, 20], [50, 50, 60, 60], [60, 60, 0, 0]];
  const ids = pointIds(paths);
  assert.deepEqual(ids.map((p) => [...p]), [[0, 1], [1, 2], [2, 3], [4, 5], [5, 0]]);
  assert.deepEqual([...pieceLabels(ids)], [0, 0, 0, 0, 0], 'the last polyline closes the chain');
  assert.deepEqual([...pieceLabels([ids[0]!, ids[2]!, ids[3]!])], [0, 1, 2], 'without their links, three pieces');
  // Ids numbered over all the polylines give the pieces of every subset its own coordinates give.
  for (let mask = 0; mask < 32; mask++) {
    const pick = <T>(xs: T[]): T[] => xs.filter((_, i) => mask & (1 << i));
    assert.deepEqual([...pieceLabels(pick(ids))], [...lineComponentLabels(pick(paths))], `subset ${mask.toString(2)}`);
  }
});
