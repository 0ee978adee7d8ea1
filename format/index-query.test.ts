// The index query on a hand-made tree: the z rule of docs/FORMAT.md, sub-index files, priority.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import type { InnerNode } from './cube-index.js';
import { chunkPriority, queryIndex } from './index-query.js';

describe('the index query', () => {
  const leaf = (file: string, bbox: [number, number, number, number, number, number]) => ({ bbox, file, bytes: 1, triangles: 1, sha256: '0'.repeat(64) });
  const sub: InnerNode = { bbox: [10, 0, 0, 20, 10, 50], children: [leaf('c-c', [10, 0, 0, 20, 10, 50])] };
  const root: InnerNode = {
    bbox: [0, 0, 0, 20, 10, 100],
    children: [
      leaf('c-a', [0, 0, 0, 10, 10, 30]),
      leaf('c-b', [0, 0, 30, 10, 10, 100]),
      { bbox: [10, 0, 0, 20, 10, 50], ref: 'i-x.json', chunks: 1 },
    ],
  };

  test('keeps chunks with z0 <= zMax and z1 > zMin over the ground box', () => {
    const files = (zMin: number, zMax: number, g: [number, number, number, number] = [0, 0, 9, 9]) =>
      queryIndex(root, { ground: g, zMin, zMax }, () => undefined).leaves.map((l) => l.file).sort();
    assert.deepEqual(files(10, 10), ['c-a']);
    assert.deepEqual(files(30, 30), ['c-b'], 'a chunk relevant up to z1 = 30 is not needed at 30');
    assert.deepEqual(files(29.9, 30), ['c-a', 'c-b'], 'z0 = 30 <= zMax = 30');
    assert.deepEqual(files(100, 100), []);
  });

  test('reports sub-index files it reaches and reads them once loaded', () => {
    const q = { ground: [12, 2, 13, 3] as [number, number, number, number], zMin: 5, zMax: 5 };
    const first = queryIndex(root, q, () => undefined);
    assert.deepEqual(first.missing, ['i-x.json']);
    assert.deepEqual(first.leaves, []);
    const second = queryIndex(root, q, (r) => (r === 'i-x.json' ? sub : undefined));
    assert.deepEqual(second.leaves.map((l) => l.file), ['c-c']);
  });

  test('puts the chunk under the view centre first', () => {
    const near = chunkPriority([0, 0, 0, 10, 10, 30], 5, 5, 10, 10, 10);
    const far = chunkPriority([100, 0, 0, 110, 10, 30], 5, 5, 10, 10, 10);
    const above = chunkPriority([0, 0, 40, 10, 10, 60], 5, 5, 10, 10, 10);
    assert.equal(near, 0);
    assert.ok(far > above && above > near);
  });
});
