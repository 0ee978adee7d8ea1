// A tilted triangle cut at levels, checked by area: the parts cover the triangle exactly, each
// lies between its levels, and the part below each level is the triangle's share below it
// (z is linear over the triangle, so that share follows from the corners' z by hand).
import test from 'node:test';
import assert from 'node:assert/strict';
import { cutAtLevels } from './level-cuts.js';

// Right triangle (0,0) (4,0) (0,4) with z = x: z 0, 4, 0; vertex 3 at (4,4), z 4.
const zOfXY = (x: number): number => x;

function setup(): { xs: number[]; ys: number[]; cut: (p: number, q: number, l: number) => number; hasArea: (o: readonly number[]) => boolean; area: (o: readonly number[]) => number } {
  const xs = [0, 4, 0, 4], ys = [0, 0, 4, 4];
  const made = new Map<string, number>();
  // As surfaces.ts does: one vertex per edge and level, where z = level along the edge.
  const cut = (p: number, q: number, l: number): number => {
    const [u, w] = p < q ? [p, q] : [q, p];
    const key = `${u}:${w}:${l}`;
    if (!made.has(key)) {
      const t = (l - zOfXY(xs[u]!)) / (zOfXY(xs[w]!) - zOfXY(xs[u]!));
      xs.push(xs[u]! + t * (xs[w]! - xs[u]!));
      ys.push(ys[u]! + t * (ys[w]! - ys[u]!));
      made.set(key, xs.length - 1);
    }
    return made.get(key)!;
  };
  const area = (o: readonly number[]): number => {
    let twice = 0;
    for (let i = 0; i < o.length; i++) twice += xs[o[i]!]! * ys[o[(i + 1) % o.length]!]! - xs[o[(i + 1) % o.length]!]! * ys[o[i]!]!;
    return twice / 2;
  };
  return { xs, ys, cut, hasArea: (o) => area(o) !== 0, area };
}

test('parts between levels cover the triangle, each with the id group of the levels below it', () => {
  const { xs, cut, hasArea, area } = setup();
  const { parts, below } = cutAtLevels([0, 1, 2], [0, 4, 0], [1, 3], cut, hasArea);
  assert.deepEqual(parts.map((p) => p.group), [0, 1, 2]);
  // Area with x <= t in this triangle: 8 - (4 - t)^2 / 2.
  const under = (t: number): number => 8 - ((4 - t) ** 2) / 2;
  const areas = parts.map((p) => area(p.verts));
  assert.ok(areas.every((a) => a > 0), 'the triangle turns counter-clockwise, so do its parts');
  assert.ok(Math.abs(areas[0]! - under(1)) < 1e-12);
  assert.ok(Math.abs(areas[1]! - (under(3) - under(1))) < 1e-12);
  assert.ok(Math.abs(areas[2]! - (8 - under(3))) < 1e-12);
  for (const p of parts) {
    const [lo, hi] = [[-Infinity, 1], [1, 3], [3, Infinity]][p.group]!;
    p.verts.forEach((v, i) => {
      assert.equal(p.zs[i], zOfXY(xs[v]!), 'a cut vertex carries its level as z');
      assert.ok(p.zs[i] >= lo! && p.zs[i] <= hi!);
    });
  }
  assert.ok(Math.abs(area(below[0]!) - under(1)) < 1e-12);
  assert.ok(Math.abs(area(below[1]!) - under(3)) < 1e-12);
});

test('a triangle off the levels is one part; touching a level from above counts it as below', () => {
  const { cut, hasArea } = setup();
  const above = cutAtLevels([0, 1, 2], [0, 4, 0], [0], cut, hasArea);
  assert.deepEqual(above.parts.map((p) => [p.group, p.verts.length]), [[1, 3]]);
  assert.deepEqual(above.below, [undefined]);
  const under = cutAtLevels([0, 1, 2], [0, 4, 0], [5], cut, hasArea);
  assert.deepEqual(under.parts.map((p) => [p.group, p.verts.length]), [[0, 3]]);
  assert.deepEqual(under.below, [[0, 1, 2]]);
});

test('two triangles sharing an edge are cut at the same point of it, where z is the level', () => {
  const { xs, ys, cut, hasArea } = setup();
  // Triangles 0 1 2 and 1 3 2 share edge 1-2, from (4,0) z 4 to (0,4) z 0: z 2 at (2,2).
  const a = cutAtLevels([0, 1, 2], [0, 4, 0], [2], cut, hasArea);
  const b = cutAtLevels([1, 3, 2], [4, 4, 0], [2], cut, hasArea);
  const onEdge = (r: typeof a): number[] => [...new Set(r.parts.flatMap((p) => p.verts).filter((v) => v > 3 && Math.abs(xs[v]! + ys[v]! - 4) < 1e-12))];
  assert.deepEqual(onEdge(a), onEdge(b));
  assert.equal(onEdge(a).length, 1);
  const v = onEdge(a)[0]!;
  assert.deepEqual([xs[v], ys[v]], [2, 2]);
  // In the second triangle z is not x: its parts still meet the level at their cut vertices.
  for (const p of b.parts) p.verts.forEach((w, i) => { if (w > 3) assert.equal(p.zs[i], 2); });
});
