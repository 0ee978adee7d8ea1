// The worker's index tree over a fake server (twoLevelCube: c-a.bin in index.json, c-b.bin in
// the sub-index i-b.json): files are looked for beside index.json, a sub-index file is fetched
// once however many queries wait for it, and one that failed to load is fetched again later.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { eventually } from '../../../testing/event-loop.js';
import { body, installFakeFetch, status } from '../../../testing/fake-fetch.js';
import { serveFiles, twoLevelCube } from '../../../testing/hand-made-cube.js';
import { FetchFailure } from './fetch-retry.js';
import { IndexTree } from './index-tree.js';

const BASE = 'https://maps.test/cubes/otterlo/';
const retry = { retries: 0, backoffMs: 0, maxBackoffMs: 0 };

const files = (): Map<string, Uint8Array> => twoLevelCube().files;

const everything = { ground: [0, 0, 20, 10] as [number, number, number, number], zMin: 0, zMax: 100 };
const chunkFiles = (tree: IndexTree): string[] => tree.query(everything).leaves.map((l) => l.file).sort();

describe('the index tree in the worker', () => {
  test('chunks and sub-indexes are fetched from beside index.json', async (t) => {
    const f = installFakeFetch(t, serveFiles(BASE, files()));
    const tree = await IndexTree.load(`${BASE}index.json?v=3`, retry);
    assert.equal(tree.index.meta.name, 'hand-made');
    assert.equal(tree.url('c-a.bin'), `${BASE}c-a.bin`);
    await tree.loadSub('i-b.json');
    assert.deepEqual(f.urls(), [`${BASE}index.json?v=3`, `${BASE}i-b.json`]);
  });

  test('a sub-index is fetched once, however many queries wait for it', async (t) => {
    const f = installFakeFetch(t, (url) => (url.endsWith('i-b.json') ? 'hold' : serveFiles(BASE, files())(url)));
    const tree = await IndexTree.load(`${BASE}index.json`, retry);
    const first = tree.query(everything);
    assert.deepEqual(first.leaves.map((l) => l.file), ['c-a.bin']);
    assert.deepEqual(first.missing, ['i-b.json']);
    const waits = [Promise.all(first.missing.map((ref) => tree.loadSub(ref))), tree.loadSub('i-b.json'), tree.loadSub('i-b.json')];
    await eventually(() => f.requests.length === 2, 'the sub-index request');
    const sub = files().get('i-b.json');
    assert.ok(sub);
    f.open()[0]!.answer(body(sub));
    await Promise.all(waits);
    await tree.loadSub('i-b.json');
    assert.equal(f.urls().filter((u) => u.endsWith('i-b.json')).length, 1);
    assert.deepEqual(tree.query(everything).missing, []);
    assert.deepEqual(chunkFiles(tree), ['c-a.bin', 'c-b.bin']);
  });

  test('a sub-index that failed to load is fetched again by a later query', async (t) => {
    const serve = serveFiles(BASE, files());
    const f = installFakeFetch(t, (url, n) => (url.endsWith('i-b.json') && n === 1 ? status(503) : serve(url)));
    const tree = await IndexTree.load(`${BASE}index.json`, retry);
    await assert.rejects(tree.loadSub('i-b.json'), (e: unknown) => e instanceof FetchFailure && e.status === 503);
    assert.deepEqual(tree.query(everything).missing, ['i-b.json'], 'still missing, not forgotten');
    await tree.loadSub('i-b.json');
    assert.equal(f.urls().filter((u) => u.endsWith('i-b.json')).length, 2);
    assert.deepEqual(chunkFiles(tree), ['c-a.bin', 'c-b.bin']);
  });

  test('a sub-index that is not one is an error naming the file', async (t) => {
    const bad = files();
    bad.set('i-b.json', new TextEncoder().encode('{"format":"ssc-index","node":{}}'));
    installFakeFetch(t, serveFiles(BASE, bad));
    const tree = await IndexTree.load(`${BASE}index.json`, retry);
    await assert.rejects(tree.loadSub('i-b.json'), /i-b\.json: .*format/);
  });
});
