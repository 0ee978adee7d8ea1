// A face's rings and triangles from its edges (face-rings.ts), on hand-made faces whose areas are
// known: few edges (found by a scan) and many (found by a map), in either direction, with a hole,
// and touching itself at a corner (two rings).
import test from 'node:test';
import assert from 'node:assert/strict';
import { assembleRings, earcutFace, faceArea2, type FaceEdge } from './face-rings.js';

/** Vertices of a closed polyline, each point once: xs, ys and the ids in order. */
function points(coords: [number, number][]): { xs: number[]; ys: number[] } {
  return { xs: coords.map((c) => c[0]), ys: coords.map((c) => c[1]) };
}

/** The ring 0..n-1 (closed) cut into `pieces` edges, each read forward or, when `reverse`, stored backwards. */
function edgesOfRing(ids: number[], pieces: number, reverse: boolean): FaceEdge[] {
  const n = ids.length, out: FaceEdge[] = [];
  for (let p = 0; p < pieces; p++) {
    const from = Math.floor((p * n) / pieces), to = Math.floor(((p + 1) * n) / pieces);
    const verts: number[] = [];
    for (let k = from; k <= to; k++) verts.push(ids[k % n]!);
    out.push(reverse ? { verts: verts.reverse(), forward: false } : { verts, forward: true });
  }
  return out;
}

/** Twice the area of counterclockwise triangles, checking each is counterclockwise. */
function trianglesArea2(tris: number[], xs: number[], ys: number[]): number {
  let a2 = 0;
  for (let t = 0; t < tris.length; t += 3) {
    const [a, b, c] = [tris[t]!, tris[t + 1]!, tris[t + 2]!];
    const cross = (xs[b]! - xs[a]!) * (ys[c]! - ys[a]!) - (xs[c]! - xs[a]!) * (ys[b]! - ys[a]!);
    assert.ok(cross > 0, `triangle ${t / 3} is counterclockwise`);
    a2 += cross;
  }
  return a2;
}

// A 40 x 40 square, its boundary on a point every 1 unit (160 points), with a 10 x 10 hole at
// [10, 20]^2 whose ring runs clockwise (4 points).
const outer: [number, number][] = [];
for (let i = 0; i < 40; i++) outer.push([i, 0]);
for (let i = 0; i < 40; i++) outer.push([40, i]);
for (let i = 40; i > 0; i--) outer.push([i, 40]);
for (let i = 40; i > 0; i--) outer.push([0, i]);
const hole: [number, number][] = [[10, 10], [10, 20], [20, 20], [20, 10]];
const sq = points([...outer, ...hole]);
const outerIds = outer.map((_, i) => i), holeIds = hole.map((_, i) => outer.length + i);

for (const pieces of [3, 40]) {
  for (const reverse of [false, true]) {
    test(`a square with a hole in ${pieces} + 1 edges${reverse ? ', stored backwards' : ''}: two rings, its area, ccw triangles covering it`, () => {
      const edges = [...edgesOfRing(outerIds, pieces, reverse), ...edgesOfRing(holeIds, 1, false)];
      const rings = assembleRings(edges, sq.xs, sq.ys);
      assert.equal(rings.length, 2);
      assert.deepEqual(new Set(rings[0]), new Set(outerIds));
      assert.deepEqual(new Set(rings[1]), new Set(holeIds));
      assert.equal(faceArea2(edges, sq.xs, sq.ys), 2 * (1600 - 100));
      const tris: number[] = [];
      assert.ok(earcutFace(edges, sq.xs, sq.ys, tris));
      assert.equal(trianglesArea2(tris, sq.xs, sq.ys), 2 * (1600 - 100));
    });
  }
}

for (const pieces of [4, 20]) test(`a face touching itself at a corner, in ${pieces} edges: two rings, both squares cut`, () => {
  // Two 10 x 10 squares meeting at (10, 10), a point every unit: one walk around both passes it twice.
  const ring: [number, number][] = [];
  for (let i = 0; i < 10; i++) ring.push([i, 0]);
  for (let i = 0; i < 10; i++) ring.push([10, i]);
  for (let i = 10; i < 20; i++) ring.push([i, 10]);
  for (let i = 10; i < 20; i++) ring.push([20, i]);
  for (let i = 20; i > 10; i--) ring.push([i, 20]);
  for (let i = 20; i > 10; i--) ring.push([10, i]);
  for (let i = 10; i > 0; i--) ring.push([i, 10]);
  for (let i = 10; i > 0; i--) ring.push([0, i]);
  const pts = points(ring);
  // The corner is one vertex: its second visit names the first's id.
  const ids = ring.map(([x, y]) => ring.findIndex(([u, w]) => u === x && w === y));
  assert.equal(new Set(ids).size, ring.length - 1);
  const edges = edgesOfRing(ids, pieces, false);
  const rings = assembleRings(edges, pts.xs, pts.ys);
  assert.equal(rings.length, 2);
  for (const r of rings) assert.equal(r.length, 40);
  const tris: number[] = [];
  assert.ok(earcutFace(edges, pts.xs, pts.ys, tris));
  assert.equal(trianglesArea2(tris, pts.xs, pts.ys), 2 * 200);
});
