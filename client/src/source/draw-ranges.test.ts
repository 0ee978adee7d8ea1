// Draw runs: every triangle a slice range needs is in them (checked triangle by triangle
// against its own z range), the reordering keeps every triangle with its winding, and on a
// stack of states like a cube's only a small part of the chunk is drawn.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { drawRuns, orderForDrawing } from './draw-ranges.js';

function random(seed: number): () => number {
  let s = seed >>> 0;
  return () => {
    s = (Math.imul(s, 1664525) + 1013904223) >>> 0;
    return s / 2 ** 32;
  };
}

/**
 * `n` triangles of three vertices each, in random order: triangle t lies from z `t * h / n`
 * (one corner; the others up to `tilt` higher) and its upper face ends `life` later, as states
 * stacked over one ground would.
 */
function stack(n: number, h: number, life: number, tilt: number, seed: number): { positions: Float32Array; upperEnd: Float32Array; indices: Uint32Array; low: number[]; end: number[] } {
  const r = random(seed);
  const positions = new Float32Array(9 * n), upperEnd = new Float32Array(3 * n), indices = new Uint32Array(3 * n);
  const low: number[] = [], end: number[] = [];
  const order = Array.from({ length: n }, (_, t) => t).sort(() => r() - 0.5);
  order.forEach((t, i) => {
    const z0 = Math.fround((t * h) / n);
    const zs = [z0, Math.fround(z0 + tilt * r()), Math.fround(z0 + tilt * r())];
    const e = Math.fround(z0 + tilt + life);
    for (let j = 0; j < 3; j++) {
      const v = 3 * i + j;
      positions.set([j === 1 ? 1 : 0, j === 2 ? 1 : 0, zs[j]!], 3 * v);
      upperEnd[v] = e;
      indices[v] = v;
    }
    low[i] = Math.min(...zs);
    end[i] = e;
  });
  return { positions, upperEnd, indices, low, end };
}

/** The triangles (as their first vertex / 3, i.e. their original number) that the runs cover. */
function drawn(indices: Uint32Array, runs: number[]): Set<number> {
  const out = new Set<number>();
  for (let k = 0; k < runs.length; k += 2) for (let t = runs[k]!; t < runs[k]! + runs[k + 1]!; t++) out.add(indices[3 * t]! / 3);
  return out;
}

test('every triangle a slice range needs is drawn, and triangles keep their corners', () => {
  for (const [n, seed] of [[4096, 1], [100, 2], [1, 3], [0, 4]] as const) {
    const s = stack(n, 100, 5, 0.8, seed);
    const before = new Set<string>();
    for (let t = 0; t < n; t++) before.add([...s.indices.subarray(3 * t, 3 * t + 3)].join());
    const blocks = orderForDrawing(s.positions, s.upperEnd, s.indices, n);
    const after = new Set<string>();
    for (let t = 0; t < n; t++) after.add([...s.indices.subarray(3 * t, 3 * t + 3)].join());
    assert.deepEqual(after, before, `n=${n}: the same triangles, each with its own corners in order`);
    assert.equal(blocks.first[blocks.first.length - 1], n);
    const runs: number[] = [];
    for (const [zMin, zMax] of [[0, 0], [50, 50], [49.5, 50.3], [99.9, 99.9], [0, 200], [-1, -1], [105.9, 120], [30, 30.0001]] as const) {
      const count = drawRuns(blocks, zMin, zMax, runs);
      const got = drawn(s.indices, runs);
      assert.equal(count, got.size, 'runs do not overlap');
      for (let t = 0; t < n; t++) {
        if (s.low[t]! <= zMax && s.end[t]! > zMin) assert.ok(got.has(t), `n=${n}, slice ${zMin}..${zMax}: triangle ${t} (${s.low[t]}..${s.end[t]}) is needed`);
      }
    }
  }
});

test('a flat slice through a stack of states draws a small part of the chunk', () => {
  const n = 4096;
  const s = stack(n, 100, 5, 0.8, 5);
  const blocks = orderForDrawing(s.positions, s.upperEnd, s.indices, n);
  const runs: number[] = [];
  for (const z of [1, 25, 50, 75, 99]) {
    const needed = s.low.filter((l, t) => l <= z && s.end[t]! > z).length;
    const count = drawRuns(blocks, z, z, runs);
    // 16 groups of 256 by lowest z, 8 blocks of 32 in each: at most the group the slice is in,
    // and a block in each group below it, more than needed.
    assert.ok(count <= needed + 256 + 16 * 32, `z ${z}: ${count} drawn for ${needed} needed`);
    assert.ok(runs.length / 2 <= 16, `z ${z}: ${runs.length / 2} draw calls, at most one a group`);
  }
});
