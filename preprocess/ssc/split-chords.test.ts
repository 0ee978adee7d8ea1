// A hand-made fan: a pentagon 0..4 triangulated from vertex 0, its boundary with the winner
// along 4 -> 0 -> 1 -> 2 (every vertex but 3 on it). Chords: 0-2 (both ends on the boundary,
// not a segment of it); 0-3 and 2-3 end at 3, which is not on it.
//
//     3 (2,4)
//    /      \
//  4 (0,3)   2 (4,3)
//   |          |
//  0 (0,0) --- 1 (4,0)
import test from 'node:test';
import assert from 'node:assert/strict';
import { splitChords } from './split-chords.js';

const xs = [0, 4, 4, 2, 0];
const ys = [0, 0, 3, 4, 3];
const TRIS = [0, 1, 2, 0, 2, 3, 0, 3, 4];
const onBoundary = (v: number): boolean => v === 0 || v === 1 || v === 2 || v === 4;
const SEGMENTS = new Set(['0 4', '0 1', '1 2']);
const segment = (a: number, b: number): boolean => SEGMENTS.has(a < b ? `${a} ${b}` : `${b} ${a}`);

function run(tris: number[], boundary = onBoundary): { out: number[]; xs: number[]; ys: number[] } {
  const X = [...xs], Y = [...ys];
  const out = splitChords(tris, X, Y, boundary, segment, (x, y) => {
    X.push(x);
    Y.push(y);
    return X.length - 1;
  });
  return { out, xs: X, ys: Y };
}

const area2 = (t: number[], X: number[], Y: number[]): number[] => {
  const out: number[] = [];
  for (let i = 0; i < t.length; i += 3) {
    const [a, b, c] = [t[i]!, t[i + 1]!, t[i + 2]!];
    out.push((X[b]! - X[a]!) * (Y[c]! - Y[a]!) - (X[c]! - X[a]!) * (Y[b]! - Y[a]!));
  }
  return out;
};

test('a chord between two boundary vertices gets one midpoint, shared by both its triangles', () => {
  const { out, xs: X, ys: Y } = run(TRIS);
  assert.equal(X.length, 6, 'one new vertex');
  assert.deepEqual([X[5], Y[5]], [2, 1.5]); // the middle of 0 (0,0) - 2 (4,3)
  assert.equal(out.length / 3, 5, 'the two triangles on the chord become two each');
  assert.equal(out.filter((v) => v === 5).length, 4);
  // Still counterclockwise, and the same area in all.
  const before = area2(TRIS, X, Y).reduce((a, b) => a + b, 0);
  const after = area2(out, X, Y);
  assert.ok(after.every((a) => a > 0), `${after}`);
  assert.equal(after.reduce((a, b) => a + b, 0), before);
  // No triangle has all three corners on the boundary any more.
  for (let i = 0; i < out.length; i += 3) assert.ok(!out.slice(i, i + 3).every(onBoundary), `triangle ${out.slice(i, i + 3)}`);
});

test('a triangle with two or three chords is split at each, counterclockwise, same area', () => {
  // With 3 on the boundary too (4-0, 0-1, 1-2 still the only segments), 0-2, 2-3, 3-0 and 3-4
  // are chords: 4 midpoints; triangle 0 1 2 has one chord (2 triangles), 0 2 3 three (4),
  // 0 3 4 two (3).
  const all = (v: number): boolean => v < xs.length;
  const { out, xs: X, ys: Y } = run(TRIS, all);
  assert.equal(X.length - xs.length, 4);
  assert.equal(out.length / 3, 9);
  const after = area2(out, X, Y);
  assert.ok(after.every((a) => a > 0), `${after}`);
  assert.equal(after.reduce((a, b) => a + b, 0), area2(TRIS, X, Y).reduce((a, b) => a + b, 0));
  for (let i = 0; i < out.length; i += 3) assert.ok(!out.slice(i, i + 3).every(all), `triangle ${out.slice(i, i + 3)}`);
});

test('without chords nothing changes', () => {
  const { out, xs: X } = run(TRIS, (v) => v === 0 || v === 1);
  assert.deepEqual(out, TRIS);
  assert.equal(X.length, xs.length);
});
