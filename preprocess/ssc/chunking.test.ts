// planChunks on hand-made surfaces: a 16 x 16 grid of unit cells, one triangle a cell.
// A triangle that is a piece of its own costs 6 bytes of indices and 3 vertices of 24 bytes:
// 78 bytes (docs/FORMAT.md), so 256 of them are 19,968 bytes.
import test from 'node:test';
import assert from 'node:assert/strict';
import { floorTop, floorTriangles, planChunks, planFloorChunks, type ChunkPlan } from './chunking.js';
import { Surfaces } from './surfaces.js';

const N = 16;
const TRI_BYTES = 78;

interface Grid {
  surfaces: Surfaces;
  xs: Float64Array;
  ys: Float64Array;
}

/** One triangle in each cell of an N x N grid, each a piece of its own, at z = 0 and covered from z = 10. */
function grid(): Grid {
  const xs = new Float64Array((N + 1) * (N + 1)), ys = new Float64Array((N + 1) * (N + 1));
  for (let y = 0; y <= N; y++) for (let x = 0; x <= N; x++) {
    xs[y * (N + 1) + x] = x;
    ys[y * (N + 1) + x] = y;
  }
  const surfaces = new Surfaces();
  for (let cy = 0; cy < N; cy++) for (let cx = 0; cx < N; cx++) {
    const v = cy * (N + 1) + cx;
    surfaces.add(v, v + 1, v + N + 1, 0, 1 + cy * N + cx, 0);
    surfaces.zEnd[surfaces.count - 1] = 10;
  }
  return { surfaces, xs, ys };
}

const input = (g: Grid, targetBytes: number): Parameters<typeof planChunks>[0] => ({
  ...g,
  extent: [0, 0, N, N],
  scaleAt: (z) => 1000 * (1 + z),
  viewPerScale: [0.3584, 0.2016],
  targetBytes,
});

/** The plan, with no first cut for the whole extent unless `wholeExtentZ` is given. */
function plan(g: Grid, targetBytes: number, wholeExtentZ = Infinity): ChunkPlan {
  return planChunks(input(g, targetBytes), [wholeExtentZ]);
}

/** The triangles of chunk c. */
const chunk = (p: ChunkPlan, c: number): number[] => [...p.order.subarray(p.start[c], p.start[c + 1])];
const chunkCount = (p: ChunkPlan): number => p.start.length - 1;

/** The sum of the chunks' ground box areas (each triangle's cell counted whole). */
function boxArea(g: Grid, p: ChunkPlan): number {
  let area = 0;
  for (let c = 0; c < chunkCount(p); c++) {
    let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
    for (const t of chunk(p, c)) {
      const v = g.surfaces.v[3 * t]!;
      x0 = Math.min(x0, g.xs[v]!);
      y0 = Math.min(y0, g.ys[v]!);
      x1 = Math.max(x1, g.xs[v]! + 1);
      y1 = Math.max(y1, g.ys[v]! + 1);
    }
    area += (x1 - x0) * (y1 - y0);
  }
  return area;
}

test('every triangle is in exactly one chunk, and the chunks are evenly sized', () => {
  const p = plan(grid(), 32 * TRI_BYTES);
  // 19,968 bytes at 2,496 a chunk: 8 chunks.
  assert.equal(chunkCount(p), 8);
  assert.deepEqual([...p.order].sort((a, b) => a - b), Array.from({ length: N * N }, (_, i) => i));
  for (let c = 0; c < chunkCount(p); c++) {
    const n = chunk(p, c).length;
    // Each cut must leave each side within 15% of its chunks' worth: with equal triangles the
    // cuts fall at whole multiples of 32.
    assert.equal(n, 32, `chunk ${c} holds ${n} triangles`);
  }
});

test('the chunks are compact: their ground boxes tile the grid without overlap', () => {
  const g = grid();
  const p = plan(g, 32 * TRI_BYTES);
  // 8 blocks of 32 cells cover the 256 cells exactly; any block that is not a rectangle, or
  // chunks that interleave, would add area.
  assert.equal(boxArea(g, p), N * N);
});

test('the same input gives the same plan', () => {
  const a = plan(grid(), 20 * TRI_BYTES);
  const b = plan(grid(), 20 * TRI_BYTES);
  assert.deepEqual([...a.order], [...b.order]);
  assert.deepEqual(a.start, b.start);
});

test('input smaller than one chunk is one chunk', () => {
  const p = plan(grid(), 1 << 20);
  assert.deepEqual(p.start, [0, N * N]);
});

/** A checkerboard: the dark cells' triangles are covered at z 10, the light cells' at z 2. */
function checkerboard(): Grid {
  const g = grid();
  for (let cy = 0; cy < N; cy++) for (let cx = 0; cx < N; cx++) g.surfaces.zEnd[cy * N + cx] = (cx + cy) % 2 === 0 ? 10 : 2;
  return g;
}

/** Whether triangle t is covered above z 5 (a dark cell of the checkerboard). */
const lasting = (g: Grid, t: number): boolean => g.surfaces.zEnd[t]! > 5;

/** The chunks that mix lasting triangles with others. */
const mixed = (g: Grid, p: ChunkPlan): number => Array.from({ length: chunkCount(p) }, (_, c) => chunk(p, c)).filter((ts) => ts.some((t) => lasting(g, t)) && !ts.every((t) => lasting(g, t))).length;

test('the triangles covered above the whole extent\'s z are chunked apart from the rest, each set in compact chunks', () => {
  const g = checkerboard();
  // The premise: this model (the extent fits at the base scale) gives no reason to cut by z.
  assert.ok(mixed(g, plan(g, 32 * TRI_BYTES)) > 0, 'without the cut, chunks mix the two');
  const p = plan(g, 32 * TRI_BYTES, 5);
  assert.equal(mixed(g, p), 0, 'no chunk mixes the two');
  assert.equal(chunkCount(p), 8);
  assert.deepEqual([...p.order].sort((a, b) => a - b), Array.from({ length: N * N }, (_, i) => i));
  // The lasting triangles first, in 4 chunks of 32, then the rest; each set's chunks tile the
  // grid (the checkerboard's cells counted whole: 2 x 256).
  for (let c = 0; c < 8; c++) assert.ok(chunk(p, c).length === 32 && chunk(p, c).every((t) => lasting(g, t) === c < 4), `chunk ${c}`);
  assert.equal(boxArea(g, p), 2 * N * N);
});

test('the triangles above the whole extent\'s z take at most the chunks allowed them, larger ones; the rest keep the chunk size', () => {
  const g = checkerboard();
  // 128 lasting triangles: 4 chunks' worth at 32 a chunk, allowed 2 (and 4, 5: as many as they need).
  const capped = planChunks(input(g, 32 * TRI_BYTES), [5], 2);
  assert.deepEqual(capped.start, [0, 64, 128, 160, 192, 224, 256]);
  assert.equal(mixed(g, capped), 0, 'no chunk mixes the two');
  for (let c = 0; c < 2; c++) assert.ok(chunk(capped, c).every((t) => lasting(g, t)), `chunk ${c} holds lasting triangles only`);
  assert.equal(boxArea(g, capped), 2 * N * N, 'each set\'s chunks tile the grid');
  for (const max of [4, 5]) {
    const p = planChunks(input(g, 32 * TRI_BYTES), [5], max), q = plan(g, 32 * TRI_BYTES, 5);
    assert.deepEqual([[...p.order], p.start], [[...q.order], q.start], `at most ${max}`);
  }
});

test('a higher cut (a phone\'s whole extent) keeps the triangles covered above it apart again, first; all above the lowest share one chunk size', () => {
  // Three bands of 8 columns, 4 and 4: covered at z 2, 6 and 10.
  const g = grid();
  const band = (t: number): number => (t % N < 8 ? 2 : t % N < 12 ? 6 : 10);
  for (let t = 0; t < N * N; t++) g.surfaces.zEnd[t] = band(t);
  const bands = (p: ChunkPlan): number[][] => Array.from({ length: chunkCount(p) }, (_, c) => [...new Set(chunk(p, c).map(band))].sort((a, b) => a - b));
  // The premise: with the one cut, chunks mix the two upper bands.
  assert.ok(bands(plan(g, 32 * TRI_BYTES, 5)).some((b) => b.length > 1), 'one cut mixes z 6 and 10');
  const p = planChunks(input(g, 32 * TRI_BYTES), [8, 5]);
  assert.deepEqual(bands(p), [[10], [10], [6], [6], [2], [2], [2], [2]]);
  assert.equal(boxArea(g, p), N * N, 'each band\'s chunks tile it');
  // Allowed 2 chunks above z 5 (4 chunks' worth): 64 triangles a chunk there, so one a band.
  const capped = planChunks(input(g, 32 * TRI_BYTES), [5, 8], 2);
  assert.deepEqual(capped.start, [0, 64, 128, 160, 192, 224, 256]);
  assert.deepEqual(bands(capped), [[10], [6], [2], [2], [2], [2]]);
  // Cuts in any order, a NaN among them ignored; a lower cut with nothing below it leaves the higher one.
  const same = planChunks(input(g, 32 * TRI_BYTES), [5, Number.NaN, 8, 8]);
  assert.deepEqual([[...same.order], same.start], [[...p.order], p.start]);
  assert.ok(bands(planChunks(input(g, 32 * TRI_BYTES), [8, -1])).every((b) => b.length === 1 || !b.includes(10)), 'z 10 apart from the rest');
});

test('a cut that leaves one side empty, or a cube of one chunk, leaves the plan as it was', () => {
  const g = grid();
  for (let cy = 0; cy < N; cy++) for (let cx = 0; cx < N; cx++) g.surfaces.zEnd[cy * N + cx] = cx < N / 2 ? 10 : 2;
  // 0.7 x the cube's bytes a chunk: splitEvenly makes one chunk of it (it rounds 1.43 chunks down).
  const oneChunk = Math.round(0.7 * N * N * TRI_BYTES);
  for (const [z, target] of [[10, 32 * TRI_BYTES], [-1, 32 * TRI_BYTES], [5, N * N * TRI_BYTES], [5, oneChunk]] as const) {
    const p = plan(g, target, z), q = plan(g, target);
    assert.deepEqual([[...p.order], p.start], [[...q.order], q.start], `cut at z ${z}, ${target} bytes a chunk`);
  }
  assert.deepEqual(plan(g, oneChunk, 5).start, [0, N * N], 'one chunk');
});

/** The grid's floor, and over it one tilted triangle a cell, its lowest corner at z = 0.25 + cell / 1000 (one piece). */
function twoLayers(): Grid {
  const g = grid();
  for (let cy = 0; cy < N; cy++) for (let cx = 0; cx < N; cx++) {
    const v = cy * (N + 1) + cx, z = 0.25 + (cy * N + cx) / 1000;
    g.surfaces.addTilted(v + 1, v + N + 2, v + N + 1, z, z + 1, z + 2, 1000, 1 + cy * N + cx, 'ramp');
    g.surfaces.zEnd[g.surfaces.count - 1] = 10;
  }
  return g;
}

test('the floor chunks hold the floor triangles, each once, in compact chunks; the floor top is the lowest corner of the rest', () => {
  const g = twoLayers();
  // The floor triangles are the first 256 (z = 0); the ramps are the rest.
  assert.deepEqual([...floorTriangles(g.surfaces)], Array.from({ length: N * N }, (_, i) => i));
  assert.equal(floorTop(g.surfaces), 0.25);
  const p = planFloorChunks(input(g, 32 * TRI_BYTES), 0.25);
  assert.equal(chunkCount(p), 8);
  assert.deepEqual([...p.order].sort((a, b) => a - b), Array.from({ length: N * N }, (_, i) => i));
  assert.equal(boxArea(g, p), N * N);
});

test('a cube that is all floor has no floor top', () => {
  assert.equal(floorTop(grid().surfaces), null);
});
