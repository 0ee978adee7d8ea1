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
  // A hexagon 0..5 of ears around a middle triangle 0 2 4, every vertex on the boundary, its
  // outline the only segments: the middle triangle's three edges are chords.
  //      3
  //   4     2
  //   5     1
  //      0
  const HX = [0, 2, 2, 0, -2, -2], HY = [0, 1, 3, 4, 3, 1];
  const HEX = [0, 1, 2, 2, 3, 4, 4, 5, 0, 0, 2, 4];
  const outline = new Set(['0 1', '1 2', '2 3', '3 4', '4 5', '0 5']);
  const X = [...HX], Y = [...HY];
  const out = splitChords(HEX, X, Y, () => true, (a, b) => outline.has(a < b ? `${a} ${b}` : `${b} ${a}`), (x, y) => {
    X.push(x);
    Y.push(y);
    return X.length - 1;
  });
  assert.equal(X.length - HX.length, 3, 'a midpoint on each chord');
  assert.equal(out.length / 3, 3 * 2 + 4, 'each ear in two, the middle triangle in four');
  const after = area2(out, X, Y);
  assert.ok(after.every((a) => a > 0), `${after}`);
  assert.equal(after.reduce((a, b) => a + b, 0), area2(HEX, X, Y).reduce((a, b) => a + b, 0));
  for (let i = 0; i < out.length; i += 3) assert.ok(out.slice(i, i + 3).some((v) => v >= HX.length), `triangle ${out.slice(i, i + 3)}`);

  // The pentagon with every vertex on the boundary: triangle 0 2 3 has two chords (0-2, 0-3).
  const all = (v: number): boolean => v < xs.length;
  const p = run(TRIS, all);
  assert.equal(p.xs.length - xs.length, 2);
  assert.equal(p.out.length / 3, 2 + 3 + 2);
  const pa = area2(p.out, p.xs, p.ys);
  assert.ok(pa.every((a) => a > 0), `${pa}`);
  assert.equal(pa.reduce((a, b) => a + b, 0), area2(TRIS, p.xs, p.ys).reduce((a, b) => a + b, 0));
});

test('an edge on the outline of the area is not split, though both its ends are on the boundary: the surface beyond it would not take the midpoint', () => {
  // With every vertex on the boundary, 2-3 and 3-4 end on it but are no segment of it: the
  // pentagon's outline there borders another face, whose surfaces meet these edges whole.
  const { out, xs: X, ys: Y } = run(TRIS, (v) => v < xs.length);
  const edges = new Set<string>();
  for (let i = 0; i < out.length; i += 3) for (let j = 0; j < 3; j++) edges.add(`${out[i + j]} ${out[i + ((j + 1) % 3)]}`);
  assert.ok(edges.has('2 3') && edges.has('3 4'), `the outline edges whole: ${[...edges].join(', ')}`);
  // The two midpoints are those of the chords 0-2 and 0-3, none on the outline.
  assert.deepEqual([X.slice(xs.length), Y.slice(ys.length)], [[2, 1], [1.5, 2]]);
});

test('a flat triangle along the outline does not make an outline edge a chord', () => {
  // Vertex 5 on the outline 0-1, between them: the flat triangle 0 5 1 has the side 1-0 that
  // triangle 0 1 2 has the other way, but nothing lies beyond it.
  const X = [...xs, 2], Y = [...ys, 0];
  const tris = [0, 5, 1, ...TRIS];
  const out = splitChords(tris, X, Y, () => true, () => false, (x, y) => {
    X.push(x);
    Y.push(y);
    return X.length - 1;
  });
  assert.deepEqual(Y.slice(6).filter((y) => y === 0), [], 'no midpoint on 0-1');
  const edges = new Set<string>();
  for (let i = 0; i < out.length; i += 3) for (let j = 0; j < 3; j++) edges.add(`${out[i + j]} ${out[i + ((j + 1) % 3)]}`);
  assert.ok(edges.has('0 1'), 'the side 0-1 whole');
});

test('without chords nothing changes', () => {
  const { out, xs: X } = run(TRIS, (v) => v === 0 || v === 1);
  assert.deepEqual(out, TRIS);
  assert.equal(X.length, xs.length);
});
