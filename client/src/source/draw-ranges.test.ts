// The drawing order: every triangle a slice up to some z over some ground can show is in a range
// drawn (checked triangle by triangle against its own lowest z and ground box), the reordering
// keeps every triangle with its corners in order, on a stack of states like a chunk's a slice
// low in the stack draws a small part of it, and a view over a corner of a chunk's ground draws
// little more than the triangles there.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { drawingOrder, drawRanges, orderForDrawing, rangesFor, type DrawBlocks } from './draw-ranges.js';

function random(seed: number): () => number {
  let s = seed >>> 0;
  return () => {
    s = (Math.imul(s, 1664525) + 1013904223) >>> 0;
    return s / 2 ** 32;
  };
}

/** `n` triangles of their own three vertices, in random order: triangle t from z `t * h / n` (one corner; the others up to `tilt` higher). */
function stack(n: number, h: number, tilt: number, seed: number): { positions: Float32Array; indices: Uint32Array; low: number[] } {
  const r = random(seed);
  const positions = new Float32Array(9 * n), indices = new Uint32Array(3 * n);
  const low: number[] = [];
  const order = Array.from({ length: n }, (_, t) => t).sort(() => r() - 0.5);
  order.forEach((t, i) => {
    const z0 = Math.fround((t * h) / n);
    const zs = [Math.fround(z0 + tilt * r()), z0, Math.fround(z0 + tilt * r())];
    for (let j = 0; j < 3; j++) {
      positions.set([j === 1 ? 1 : 0, j === 2 ? 1 : 0, zs[j]!], 3 * (3 * i + j));
      indices[3 * i + j] = 3 * i + j;
    }
    low[i] = z0;
  });
  return { positions, indices, low };
}

const everywhere = [-Infinity, -Infinity, Infinity, Infinity];

/** The triangles drawn for slices up to `zMax` over `rect`. */
function drawn(b: DrawBlocks, zMax: number, rect: ArrayLike<number>): number[] {
  const r = rangesFor(b, zMax, rect, drawRanges(b));
  const out: number[] = [];
  for (let i = 0; i < r.n; i++) for (let t = r.first[i]!; t < r.first[i]! + r.count[i]!; t++) out.push(t);
  assert.equal(out.length, r.triangles);
  return out;
}

test('every triangle at or below the slice is in a range, and triangles keep their corners', () => {
  for (const [n, seed] of [[4096, 1], [100, 2], [64, 6], [1, 3], [0, 4]] as const) {
    const s = stack(n, 100, 0.8, seed);
    const before = new Set<string>();
    for (let t = 0; t < n; t++) before.add([...s.indices.subarray(3 * t, 3 * t + 3)].join());
    const blocks = orderForDrawing(s.positions, s.indices, n);
    const after = new Set<string>();
    for (let t = 0; t < n; t++) after.add([...s.indices.subarray(3 * t, 3 * t + 3)].join());
    assert.deepEqual(after, before, `n=${n}: the same triangles, each with its own corners in order`);
    for (const z of [-1, 0, 0.5, 30, 50, 99.9, 100, 200]) {
      const ts = drawn(blocks, z, everywhere);
      const got = new Set(ts.map((t) => s.indices[3 * t]! / 3));
      for (let t = 0; t < n; t++) {
        if (s.low[t]! <= z) assert.ok(got.has(t), `n=${n}, slice ${z}: triangle ${t} (from ${s.low[t]}) is drawn`);
      }
      const needed = s.low.filter((l) => l <= z).length;
      // One ground cell (every triangle over the same square): at most a block of 16 more.
      assert.ok(ts.length - needed < 16, `n=${n}, slice ${z}: ${ts.length} drawn for ${needed}, at most a block more`);
    }
  }
});

test('ties in lowest z keep the file order', () => {
  // Three flat triangles at z 2, 1 and 2: the one at 1 first, then the two at 2 as they were.
  const positions = Float32Array.from([2, 2, 2, 1, 1, 1, 2, 2, 2].flatMap((z, v) => [v % 3 === 1 ? 1 : 0, v % 3 === 2 ? 1 : 0, z]));
  const indices = Uint16Array.from({ length: 9 }, (_, v) => v);
  orderForDrawing(positions, indices, 3);
  assert.deepEqual([...indices], [3, 4, 5, 0, 1, 2, 6, 7, 8]);
});

test('a view over part of the ground draws the triangles there and few others', () => {
  // A 40 x 40 grid of unit squares, two triangles each, at z from 0 to 10 by a hash of the cell.
  const n = 40, positions: number[] = [], indices: number[] = [];
  const low: number[] = [];
  for (let j = 0; j < n; j++) for (let i = 0; i < n; i++) {
    const z = Math.fround(((i * 7 + j * 13) % 11) * 1);
    const v = positions.length / 3;
    positions.push(i, j, z, i + 1, j, z, i + 1, j + 1, z, i, j + 1, z);
    indices.push(v, v + 1, v + 2, v, v + 2, v + 3);
    low.push(z, z);
  }
  const idx = Uint32Array.from(indices);
  const b = orderForDrawing(positions, idx, idx.length / 3);
  const T = idx.length / 3;
  // Where each triangle is after the reordering: its first corner's square.
  const squareOf = (t: number): [number, number] => [positions[3 * idx[3 * t]!]!, positions[3 * idx[3 * t]! + 1]!];
  for (const [rect, z] of [[[3.5, 2.5, 8.2, 6], 4], [[30, 30, 45, 45], 10], [[-5, 12, 0, 13], 3], [[20, 20, 20, 20], 0]] as const) {
    const ts = drawn(b, z, rect);
    const got = new Set(ts);
    let needed = 0;
    for (let t = 0; t < T; t++) {
      const [x, y] = squareOf(t);
      const zt = positions[3 * idx[3 * t]! + 2]!;
      if (zt <= z && x <= rect[2] && x + 1 >= rect[0] && y <= rect[3] && y + 1 >= rect[1]) {
        needed++;
        assert.ok(got.has(t), `triangle over square ${x}, ${y} at z ${zt} is drawn for a view over ${rect.join(', ')} up to ${z}`);
      }
    }
    // The cells are 10 x 10 squares (200 triangles): a view that meets at most four of them
    // draws at most a quarter of the chunk.
    assert.ok(ts.length <= T / 4, `${ts.length} of ${T} drawn for ${needed} needed over ${rect.join(', ')}`);
  }
  // The whole ground and every z: one range of everything.
  const all = rangesFor(b, 100, everywhere, drawRanges(b));
  assert.deepEqual([all.n, all.first[0], all.count[0]], [1, 0, T]);
  assert.deepEqual(drawn(b, 100, [1000, 1000, 1001, 1001]), [], 'a view beside the chunk draws nothing');
});

test('a chunk all at one z (the floor) has finer cells: a view inside one draws that cell alone', () => {
  // A 40 x 40 grid of unit squares, two triangles each, all at z 0.
  const n = 40, positions: number[] = [], indices: number[] = [];
  for (let j = 0; j < n; j++) for (let i = 0; i < n; i++) {
    const v = positions.length / 3;
    positions.push(i, j, 0, i + 1, j, 0, i + 1, j + 1, 0, i, j + 1, 0);
    indices.push(v, v + 1, v + 2, v, v + 2, v + 3);
  }
  const idx = Uint32Array.from(indices);
  const T = idx.length / 3;
  const b = orderForDrawing(positions, idx, T);
  // 8 x 8 cells of 5 x 5 squares (50 triangles): a view inside one cell draws that cell alone.
  assert.equal(b.cellBlocks.length - 1, 64);
  const ts = drawn(b, 0, [0.5, 0.5, 4.5, 4.5]);
  assert.equal(ts.length, 50);
  for (const t of ts) {
    const x = positions[3 * idx[3 * t]!]!, y = positions[3 * idx[3 * t]! + 1]!;
    assert.ok(x < 5 && y < 5, `triangle over square ${x}, ${y}`);
  }
});

test('the drawing order is that of a sort by cell, lowest z and number, ties and signs included', () => {
  const r = random(11);
  for (const [count, cells, zs] of [[5000, 16, 40], [3000, 64, 1], [777, 16, 3], [1, 16, 1], [0, 16, 1]] as const) {
    const cellOf = Uint8Array.from({ length: count }, () => Math.floor(r() * cells));
    // Few distinct z values (ties), some negative, and both zeros.
    const values = [0, -0, -2.5, 1e-3, 7, 4654.25, -1e-7, 31172.3].map(Math.fround);
    const low = Float64Array.from({ length: count }, () => (zs === 1 ? 3 : values[Math.floor(r() * values.length)]! + Math.fround(Math.floor(r() * zs) / 9)));
    for (let t = 0; t < count; t++) low[t] = Math.fround(low[t]!);
    // A sum never gives -0: some set so (a comparator takes -0 and 0 as equal).
    for (let t = 0; t < count; t += 7) if (low[t] === 0) low[t] = -0;
    if (count > 100 && zs > 1) assert.ok(low.some((z) => Object.is(z, -0)) && low.some((z) => Object.is(z, 0)), 'both zeros');
    const expected = Array.from({ length: count }, (_, t) => t).sort((p, q) => cellOf[p]! - cellOf[q]! || low[p]! - low[q]! || p - q);
    assert.deepEqual([...drawingOrder(cellOf, cells, low, zs === 1)], expected, `${count} triangles in ${cells} cells`);
  }
});
