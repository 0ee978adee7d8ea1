import test from 'node:test';
import assert from 'node:assert/strict';
import { cutLines, joinAdjacency, lineGraphComponents } from './line-graph.js';

/** Lines with joins to the given others (each join written on one side only, as a port may be). */
const linesOf = (edges: [number, number][], n: number): { joins: { x: number; y: number; line: number; bridge: boolean }[] }[] => {
  const out = Array.from({ length: n }, () => ({ joins: [] as { x: number; y: number; line: number; bridge: boolean }[] }));
  for (const [a, b] of edges) out[a]!.joins.push({ x: 0, y: 0, line: b, bridge: false });
  return out;
};

const count = (comp: Int32Array): number => new Set([...comp].filter((c) => c >= 0)).size;

test('joins become an undirected graph; the cut lines of a loop with a tail and a pendant square', () => {
  //   0 - 1 - 2 - 3        a loop 0-1-2-3-0, a tail 3-4-5, and 5 holding a second loop 5-6-7-5,
  //   |_______|  \         line 8 alone, a join to nothing (-1) on line 8
  //   4 - 5 - 6
  //       \ /
  //        7
  const lines = linesOf([[0, 1], [1, 2], [2, 3], [3, 0], [3, 4], [4, 5], [5, 6], [6, 7], [7, 5]], 9);
  lines[8]!.joins.push({ x: 0, y: 0, line: -1, bridge: false });
  lines[1]!.joins.push({ x: 0, y: 0, line: 0, bridge: false }); // the same join written from both sides
  const adj = joinAdjacency(lines);
  assert.deepEqual(adj[0], [1, 3]);
  assert.deepEqual(adj[3], [0, 2, 4]);
  assert.deepEqual(adj[8], []);
  const all = new Uint8Array(9).fill(1);
  assert.deepEqual([...cutLines(adj, all)].flatMap((c, i) => (c ? [i] : [])), [3, 4, 5]);
  assert.deepEqual([...lineGraphComponents(adj, all)], [0, 0, 0, 0, 0, 0, 0, 0, 1]);
  // Without line 4 the tail is gone: 3 and 5 no longer cut anything, and there are three pieces.
  const no4 = Uint8Array.from(all, (_, i) => (i === 4 ? 0 : 1));
  assert.deepEqual([...cutLines(adj, no4)].flatMap((c, i) => (c ? [i] : [])), []);
  assert.deepEqual([...lineGraphComponents(adj, no4)], [0, 0, 0, 0, -1, 1, 1, 1, 2]);
  assert.throws(() => joinAdjacency(linesOf([[0, 5]], 2)), /line 0: a join names line 5, but there are 2 lines/);
});

test('a line is cut exactly when taking it away leaves more pieces (random graphs, checked by removal)', () => {
  let seed = 12345;
  const rand = (): number => ((seed = (seed * 1103515245 + 12345) % 2147483648) / 2147483648);
  for (let trial = 0; trial < 60; trial++) {
    const n = 3 + Math.floor(rand() * 30);
    const edges: [number, number][] = [];
    const m = Math.floor(rand() * n * 1.6);
    for (let k = 0; k < m; k++) edges.push([Math.floor(rand() * n), Math.floor(rand() * n)]);
    const adj = joinAdjacency(linesOf(edges, n));
    const alive = Uint8Array.from({ length: n }, () => (rand() < 0.85 ? 1 : 0));
    const before = count(lineGraphComponents(adj, alive));
    const cut = cutLines(adj, alive);
    for (let v = 0; v < n; v++) {
      if (!alive[v]) {
        assert.equal(cut[v], 0);
        continue;
      }
      const without = Uint8Array.from(alive, (a, i) => (i === v ? 0 : a));
      const after = count(lineGraphComponents(adj, without));
      assert.equal(cut[v] === 1, after > before, `trial ${trial}, line ${v}: ${before} pieces, ${after} without it`);
    }
  }
});
