// The drawing order: every triangle a slice up to some z can show is in the prefix drawn
// (checked triangle by triangle against its own lowest z), the reordering keeps every triangle
// with its corners in order, and on a stack of states like a chunk's a slice low in the stack
// draws a small part of it.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { orderForDrawing, trianglesUpTo } from './draw-ranges.js';

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

test('every triangle at or below the slice is in the prefix, and triangles keep their corners', () => {
  for (const [n, seed] of [[4096, 1], [100, 2], [64, 6], [1, 3], [0, 4]] as const) {
    const s = stack(n, 100, 0.8, seed);
    const before = new Set<string>();
    for (let t = 0; t < n; t++) before.add([...s.indices.subarray(3 * t, 3 * t + 3)].join());
    const blocks = orderForDrawing(s.positions, s.indices, n);
    const after = new Set<string>();
    for (let t = 0; t < n; t++) after.add([...s.indices.subarray(3 * t, 3 * t + 3)].join());
    assert.deepEqual(after, before, `n=${n}: the same triangles, each with its own corners in order`);
    for (const z of [-1, 0, 0.5, 30, 50, 99.9, 100, 200]) {
      const k = trianglesUpTo(blocks, z);
      const drawn = new Set<number>();
      for (let t = 0; t < k; t++) drawn.add(s.indices[3 * t]! / 3);
      for (let t = 0; t < n; t++) {
        if (s.low[t]! <= z) assert.ok(drawn.has(t), `n=${n}, slice ${z}: triangle ${t} (from ${s.low[t]}) is drawn`);
      }
      const needed = s.low.filter((l) => l <= z).length;
      assert.ok(k - needed < 64, `n=${n}, slice ${z}: ${k} drawn for ${needed}, at most a block more`);
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
