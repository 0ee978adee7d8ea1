// The chunk file's ring pieces: which level triangles go as rings, the rings they go as (round
// the triangles, the same whatever order the triangles come in), and that the reader's cut of
// those rings covers what the triangles covered.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { cutRingPiece, findRingPieces, type PieceInput } from './chunk-rings.js';

/** Triangles of points (x, y on whole steps), each vertex its own, at z values and faces given per triangle. */
function input(tris: { pts: [number, number][]; z: number; upper: number; lower?: number }[]): PieceInput {
  const xs: number[] = [], ys: number[] = [], at = new Map<string, number>();
  const indices: number[] = [], pointOf: number[] = [], zOf: number[] = [], upper: number[] = [], lower: number[] = [];
  for (const t of tris) {
    for (const [x, y] of t.pts) {
      let p = at.get(`${x},${y}`);
      if (p === undefined) {
        at.set(`${x},${y}`, (p = xs.length));
        xs.push(x);
        ys.push(y);
      }
      indices.push(pointOf.length);
      pointOf.push(p);
      zOf.push(t.z);
      upper.push(t.upper);
      lower.push(t.lower ?? 0);
    }
  }
  return { indices, pointOf, zOf, upper, lower, xs, ys };
}

/** A 4 x 4 square with a 2 x 2 hole, as 8 counterclockwise triangles. */
function frame(z = 2, upper = 5): { pts: [number, number][]; z: number; upper: number }[] {
  const o: [number, number][] = [[0, 0], [4, 0], [4, 4], [0, 4]], h: [number, number][] = [[1, 1], [3, 1], [3, 3], [1, 3]];
  const out: { pts: [number, number][]; z: number; upper: number }[] = [];
  for (let k = 0; k < 4; k++) {
    out.push({ pts: [o[k]!, o[(k + 1) % 4]!, h[(k + 1) % 4]!], z, upper });
    out.push({ pts: [o[k]!, h[(k + 1) % 4]!, h[k]!], z, upper });
  }
  return out;
}

/** A ring as its points' coordinates. */
const coords = (c: PieceInput, r: number[]): string => r.map((p) => `${c.xs[p]},${c.ys[p]}`).join(' ');

describe('chunk ring pieces', () => {
  test('a level piece goes as its outer ring and its hole, each from its lowest point, outer first', () => {
    const c = input(frame());
    const { pieces, ringed } = findRingPieces(c);
    assert.deepEqual([...ringed], [1, 1, 1, 1, 1, 1, 1, 1]);
    assert.equal(pieces.length, 1);
    assert.deepEqual([pieces[0]!.z, pieces[0]!.upper, pieces[0]!.lower], [2, 5, 0]);
    assert.deepEqual(pieces[0]!.rings.map((r) => coords(c, r)), ['0,0 4,0 4,4 0,4', '1,1 1,3 3,3 3,1']);
  });

  test('the same triangles in another order, turned, give the same rings', () => {
    const turned = frame().reverse().map((t) => ({ ...t, pts: [t.pts[1]!, t.pts[2]!, t.pts[0]!] }));
    const a = input(frame()), b = input(turned);
    assert.deepEqual(findRingPieces(b).pieces[0]!.rings.map((r) => coords(b, r)), findRingPieces(a).pieces[0]!.rings.map((r) => coords(a, r)));
  });

  test("the reader's cut covers the piece: the same area, every triangle counterclockwise", () => {
    const c = input(frame());
    const out: number[] = [];
    // Twice the area: 16 less the hole's 4.
    assert.equal(cutRingPiece(findRingPieces(c).pieces[0]!.rings, c.xs, c.ys, out), 24);
    assert.equal(out.length / 3, 8);
    for (let t = 0; t < out.length; t += 3) {
      const [a, b, d] = [out[t]!, out[t + 1]!, out[t + 2]!];
      assert.ok((c.xs[b]! - c.xs[a]!) * (c.ys[d]! - c.ys[a]!) - (c.xs[d]! - c.xs[a]!) * (c.ys[b]! - c.ys[a]!) > 0);
    }
  });

  test('pieces are told apart by z and faces; tilted triangles stay', () => {
    const c = input([...frame(2, 5), ...frame(3, 5), ...frame(2, 6), { pts: [[10, 0], [12, 0], [10, 2]], z: 2, upper: 7 }]);
    c.zOf = Array.from(c.zOf);
    // The last triangle tilted: one corner higher.
    (c.zOf as number[])[c.zOf.length - 1] = 2.5;
    const { pieces, ringed } = findRingPieces(c);
    assert.deepEqual(pieces.map((p) => [p.z, p.upper]), [[2, 5], [3, 5], [2, 6]]);
    assert.equal(ringed[ringed.length - 1], 0);
  });

  test('a piece stays as triangles where they overlap, one is turned over or of no area', () => {
    const overlap = input([
      { pts: [[0, 0], [2, 0], [0, 2]], z: 1, upper: 9 },
      { pts: [[0, 0], [2, 0], [1, 2]], z: 1, upper: 9 },
    ]);
    const turned = input([{ pts: [[0, 0], [0, 2], [2, 0]], z: 1, upper: 9 }]);
    const flat = input([{ pts: [[0, 0], [1, 0], [2, 0]], z: 1, upper: 9 }]);
    for (const c of [overlap, turned, flat]) {
      const { pieces, ringed } = findRingPieces(c);
      assert.equal(pieces.length, 0);
      assert.ok(ringed.every((r) => r === 0));
    }
  });
});
