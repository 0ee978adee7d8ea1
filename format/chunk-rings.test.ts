// The chunk file's ring pieces: which level triangles go as rings, the rings they go as (round
// the triangles, the same whatever order the triangles come in), and that the reader's cut of
// those rings covers each point as often as the triangles did (sampled).
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { cutRingPieces, findRingPieces, type PieceInput } from './chunk-rings.js';
import { cover } from '../testing/triangle-cover.js';

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

  test("the reader's cut covers each point as often as the triangles: a frame, two squares touching at a corner, an island in a hole", () => {
    const sq = (x: number, y: number, w: number, upper = 5): { pts: [number, number][]; z: number; upper: number }[] => [
      { pts: [[x, y], [x + w, y], [x + w, y + w]], z: 2, upper },
      { pts: [[x, y], [x + w, y + w], [x, y + w]], z: 2, upper },
    ];
    // A frame round a 4 x 4 hole, and a 2 x 2 square of the same piece inside the hole.
    const big: { pts: [number, number][]; z: number; upper: number }[] = [];
    const o: [number, number][] = [[0, 0], [6, 0], [6, 6], [0, 6]], h: [number, number][] = [[1, 1], [5, 1], [5, 5], [1, 5]];
    for (let k = 0; k < 4; k++) {
      big.push({ pts: [o[k]!, o[(k + 1) % 4]!, h[(k + 1) % 4]!], z: 2, upper: 5 }, { pts: [o[k]!, h[(k + 1) % 4]!, h[k]!], z: 2, upper: 5 });
    }
    const cases = { frame: frame(), touching: [...sq(0, 0, 2), ...sq(2, 2, 2)], island: [...big, ...sq(2, 2, 2)] };
    for (const [name, tris] of Object.entries(cases)) {
      const c = input(tris);
      const { pieces, ringed } = findRingPieces(c);
      assert.equal(pieces.length, 1, name);
      assert.ok(ringed.every((r) => r === 1), name);
      const cut = cutRingPieces([pieces[0]!.rings.length], pieces[0]!.rings.map((r) => r.length), Uint32Array.from(pieces[0]!.rings.flat()), c.xs, c.ys, (why) => new Error(why));
      const triangles = (ids: number[]): number[][] => ids.flatMap((_, i) => (i % 3 ? [] : [[ids[i]!, ids[i + 1]!, ids[i + 2]!].flatMap((p) => [c.xs[p]!, c.ys[p]!])]));
      const got = triangles(cut.triangles.map((v) => cut.vertexPoints[v]!)), want = triangles(Array.from(c.indices, (v) => c.pointOf[v]!));
      // Off every line through two points of the grid that the cut could use.
      for (let x = 0.3137; x < 6; x += 0.5) for (let y = 0.2718; y < 6; y += 0.5) assert.equal(cover(got, x, y), cover(want, x, y), `${name}: (${x}, ${y})`);
    }
  });

  test('a piece with a point on a straight side keeps it, or stays as triangles', () => {
    // A 2 x 1 rectangle whose lower side has a point at (1, 0) where a neighbour's corner is.
    const c = input([
      { pts: [[0, 0], [1, 0], [0, 1]], z: 2, upper: 5 },
      { pts: [[1, 0], [2, 0], [2, 1]], z: 2, upper: 5 },
      { pts: [[1, 0], [2, 1], [0, 1]], z: 2, upper: 5 },
    ]);
    const { pieces, ringed } = findRingPieces(c);
    if (pieces.length === 0) {
      assert.ok(ringed.every((r) => r === 0));
      return;
    }
    const cut = cutRingPieces([1], [pieces[0]!.rings[0]!.length], Uint32Array.from(pieces[0]!.rings[0]!), c.xs, c.ys, (why) => new Error(why));
    assert.ok(cut.vertexPoints.some((p) => c.xs[p] === 1 && c.ys[p] === 0), 'the point on the side is a corner of the cut');
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

  test('a piece stays as triangles where two use a side the same way, one is turned over or of no area', () => {
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
