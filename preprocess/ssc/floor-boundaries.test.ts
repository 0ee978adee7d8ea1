// The floor as boundaries on a hand-made floor: a 4 x 4 grid of unit cells, two triangles a
// cell, face 1 on the left half (x < 2), face 2 on the right, and face 3 in the cell [2, 3] x [1, 2].
import test from 'node:test';
import assert from 'node:assert/strict';
import { decodeFloorChunk } from '../../format/floor-chunk.js';
import { floorBoundaries, type FloorBoundary } from './floor-boundaries.js';
import { floorChunks } from './floor-chunks.js';
import { Surfaces } from './surfaces.js';

const N = 4;

function floor(): { s: Surfaces; xs: Float64Array; ys: Float64Array } {
  const xs = new Float64Array((N + 1) * (N + 1)), ys = new Float64Array((N + 1) * (N + 1));
  for (let y = 0; y <= N; y++) for (let x = 0; x <= N; x++) {
    xs[y * (N + 1) + x] = 100 + x;
    ys[y * (N + 1) + x] = 200 + y;
  }
  const s = new Surfaces();
  for (let cy = 0; cy < N; cy++) for (let cx = 0; cx < N; cx++) {
    const v = cy * (N + 1) + cx, face = cx === 2 && cy === 1 ? 3 : cx < 2 ? 1 : 2;
    s.add(v, v + 1, v + N + 2, 0, face, 0);
    s.add(v, v + N + 2, v + N + 1, 0, face, 0);
    s.zEnd[s.count - 2] = s.zEnd[s.count - 1] = 10;
  }
  return { s, xs, ys };
}

const all = (s: Surfaces): Uint32Array => Uint32Array.from({ length: s.count }, (_, i) => i);

/** Each side of the edges as "x0,y0>x1,y1 left|right" (ground coordinates, in order). */
function sides(edges: FloorBoundary[], xs: Float64Array, ys: Float64Array): string[] {
  const out: string[] = [];
  for (const e of edges) {
    for (let k = 0; k + 1 < e.verts.length; k++) {
      const a = e.verts[k]!, b = e.verts[k + 1]!;
      out.push(`${xs[a]! - 100},${ys[a]! - 200}>${xs[b]! - 100},${ys[b]! - 200} ${e.left}|${e.right}`);
    }
  }
  return out.sort();
}

/** The face whose cell lies left of the side a -> b (by hand: the cell's centre), or 0 outside. */
function faceLeftOf(side: string): number {
  const [from, to] = side.split(' ')[0]!.split('>').map((p) => p.split(',').map(Number)) as [[number, number], [number, number]];
  const mx = (from[0] + to[0]) / 2, my = (from[1] + to[1]) / 2, dx = to[0] - from[0], dy = to[1] - from[1];
  const x = mx - dy / 2, y = my + dx / 2;
  if (x < 0 || y < 0 || x > N || y > N) return 0;
  return Math.floor(x) === 2 && Math.floor(y) === 1 ? 3 : x < 2 ? 1 : 2;
}

test('every side between two faces, or at the edge of the data, is in one edge, with the faces on its left and right', () => {
  const { s, xs, ys } = floor();
  const f = floorBoundaries(s, all(s), xs, ys);
  assert.deepEqual(f.faces, [1, 2, 3]);
  const got = sides(f.edges, xs, ys);
  // 16 sides around the grid, 4 along x = 2 (between face 1 and faces 2 and 3), 3 more around face 3.
  assert.equal(got.length, 23);
  for (const side of got) {
    const [left, right] = side.split(' ')[1]!.split('|').map(Number) as [number, number];
    const turned = side.split(' ')[0]!.split('>').reverse().join('>');
    assert.equal(left, faceLeftOf(side), `${side}: the face on its left`);
    assert.equal(right, faceLeftOf(turned), `${side}: the face on its right`);
  }
  assert.deepEqual([...f.trianglesOf].map(([face, t]) => [face, t.length]), [[1, 16], [2, 14], [3, 2]]);
});

test('the edges come in an order in which each starts where the one before it ended, where it can', () => {
  const { s, xs, ys } = floor();
  const { edges } = floorBoundaries(s, all(s), xs, ys);
  let joined = 0;
  for (let k = 1; k < edges.length; k++) if (edges[k]!.verts[0] === edges[k - 1]!.verts[edges[k - 1]!.verts.length - 1]) joined++;
  // Face 1's outline, the three runs along x = 2 (faces 2, 3, 2 on their right), face 2's
  // outline, then the sides between faces 2 and 3, which meet the rest only in the middle of x = 2.
  assert.equal(edges.length, 6);
  assert.equal(joined, 4);
});

test('a triangle off the floor, or over a face, is refused', () => {
  const { s, xs, ys } = floor();
  s.addTilted(0, 1, 6, 0, 0, 0.5, 1, 0, 'ramp');
  assert.throws(() => floorBoundaries(s, Uint32Array.of(s.count - 1), xs, ys), /triangle 32 \(face 1\) is not at z = 0 over face 0/);
  s.add(0, 1, 6, 0, 1, 2);
  assert.throws(() => floorBoundaries(s, Uint32Array.of(s.count - 1), xs, ys), /triangle 33 \(face 1\) is not at z = 0 over face 0/);
});

test('over part of the triangles, a face cut by the chunk\'s border has none on the other side of the cut', () => {
  const { s, xs, ys } = floor();
  // The bottom row of cells.
  const f = floorBoundaries(s, Uint32Array.from({ length: 2 * N }, (_, i) => i), xs, ys);
  const got = sides(f.edges, xs, ys);
  assert.ok(got.includes('1,1>0,1 1|0'), 'the cut through face 1');
  assert.ok(got.includes('2,0>2,1 1|2'));
  assert.equal(got.length, 2 * N + 2 + 1);
});

test('floor chunks cut from the boundaries cover each face as its floor triangles do', async () => {
  const { s, xs, ys } = floor();
  const chunks = floorChunks({ surfaces: s, xs, ys, extent: [100, 200, 104, 204], scaleAt: (z) => 1000 * (1 + z), viewPerScale: [0.3584, 0.2016], targetBytes: 600 }, 0.5, (face) => face * 10, -8);
  assert.ok(chunks.length >= 2, `${chunks.length} chunks`);
  const area = new Map<number, number>();
  let triangles = 0;
  for (const ch of chunks) {
    const c = await decodeFloorChunk(ch.bytes);
    assert.equal(c.triangleCount, ch.triangles);
    triangles += ch.triangles;
    assert.deepEqual([ch.bbox[2], ch.bbox[5]], [0, 0.5]);
    const p = c.positions;
    for (let t = 0; t < c.triangleCount; t++) {
      const [a, b, d] = [0, 1, 2].map((k) => c.indices[3 * t + k]!) as [number, number, number];
      for (const v of [a, b, d]) {
        const x = c.originX + p[3 * v]!, y = c.originY + p[3 * v + 1]!;
        assert.ok(x >= ch.bbox[0] && x <= ch.bbox[3] && y >= ch.bbox[1] && y <= ch.bbox[4], 'in the leaf\'s box');
        assert.equal(c.upperClass[v], c.upper[v]! * 10);
      }
      const ar = ((p[3 * b]! - p[3 * a]!) * (p[3 * d + 1]! - p[3 * a + 1]!) - (p[3 * d]! - p[3 * a]!) * (p[3 * b + 1]! - p[3 * a + 1]!)) / 2;
      assert.ok(ar > 0, 'counterclockwise');
      area.set(c.upper[a]!, (area.get(c.upper[a]!) ?? 0) + ar);
    }
  }
  // Earcut needs no triangle between points in a line: fewer than the floor's 32.
  assert.deepEqual([...area].sort((a, b) => a[0] - b[0]), [[1, 8], [2, 7], [3, 1]]);
  assert.ok(triangles > 0 && triangles <= 2 * N * N, `${triangles} triangles`);
});

/** Faces 1 ([0, 1]^2), 2 ([1, 2] x [0, 1], a corner M at (mx, 0.5) on or beside the side it shares with 1) and 3 ([1, 2]^2, beyond M's side). */
function tJunction(mx: number): { s: Surfaces; xs: Float64Array; ys: Float64Array } {
  const xs = Float64Array.of(100, 101, 102, 102, 101, 100, 100 + mx, 102, 101), ys = Float64Array.of(200, 200, 200, 201, 201, 201, 200.5, 202, 202);
  const [P, A, B, C, D, Q, M, E, G] = [0, 1, 2, 3, 4, 5, 6, 7, 8];
  const s = new Surfaces();
  for (const [a, b, c, face] of [[P, A, D, 1], [P, D, Q, 1], [A, B, M, 2], [M, B, C, 2], [M, C, D, 2], [D, C, E, 3], [D, E, G, 3]] as const) {
    s.add(a, b, c, 0, face, 0);
    s.zEnd[s.count - 1] = 10;
  }
  return { s, xs, ys };
}

test('a corner of one face\'s triangles on another face\'s side (a T-junction) splits that side: one edge between the two faces', async () => {
  const { s, xs, ys } = tJunction(1);
  const got = sides(floorBoundaries(s, all(s), xs, ys).edges, xs, ys);
  assert.ok(got.includes('1,0>1,0.5 1|2') && got.includes('1,0.5>1,1 1|2'), got.join('; '));
  // Face 3's side on the same line, beyond the side's end, splits nothing.
  assert.ok(got.includes('1,2>1,1 3|0'), got.join('; '));
  assert.equal(got.filter((side) => side.startsWith('1,') && side.split('>')[1]!.startsWith('1,')).length, 3, got.join('; '));
  // Written as version 2 (a face per cycle), each face cut whole.
  const [chunk] = floorChunks({ surfaces: s, xs, ys, extent: [100, 200, 102, 202], scaleAt: (z) => 1000 * (1 + z), viewPerScale: [0.3584, 0.2016], targetBytes: 1e6 }, 0.5, (face) => face, -8);
  assert.equal(new DataView(chunk!.bytes.buffer, chunk!.bytes.byteOffset).getUint32(4, true), 2);
  const c = await decodeFloorChunk(chunk!.bytes);
  const area = new Map<number, number>();
  const p = c.positions;
  for (let t = 0; t < c.triangleCount; t++) {
    const [a, b, d] = [0, 1, 2].map((k) => c.indices[3 * t + k]!) as [number, number, number];
    area.set(c.upper[a]!, (area.get(c.upper[a]!) ?? 0) + ((p[3 * b]! - p[3 * a]!) * (p[3 * d + 1]! - p[3 * a + 1]!) - (p[3 * d]! - p[3 * a]!) * (p[3 * b + 1]! - p[3 * a + 1]!)) / 2);
  }
  assert.deepEqual([...area].sort((x, y) => x[0] - y[0]), [[1, 1], [2, 1], [3, 1]]);
});

test('a corner a billionth of a unit beside the side splits nothing', () => {
  const { s, xs, ys } = tJunction(1 + 1e-9);
  const got = sides(floorBoundaries(s, all(s), xs, ys).edges, xs, ys);
  assert.ok(got.includes('1,0>1,1 1|0'), got.join('; '));
});
