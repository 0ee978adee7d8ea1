// One chunk from a (fake) server: real chunk files from format/chunk.ts, named by their SHA-256
// as the build names them. What arrives is the decoded chunk with only its upward triangles;
// bytes that differ from the name (or from a version 1 index's SHA-256), or that are not a
// chunk, are refused as corrupt.
import assert from 'node:assert/strict';
import { gzipSync } from 'node:zlib';
import { describe, test } from 'node:test';
import { installFakeFetch, body, status } from '../../../testing/fake-fetch.js';
import { leafFor, namedLeaf, sha256, squareChunk } from '../../../testing/hand-made-cube.js';
import { ChunkCorrupt, fetchChunk } from './chunk-fetch.js';
import { FetchFailure } from './fetch-retry.js';
import type { ChunkPayload } from './worker-protocol.js';

const retry = { retries: 0, backoffMs: 0, maxBackoffMs: 0 };
const leaf = namedLeaf([0, 0, 0, 1, 1, 10], squareChunk(1));
const URL_C = `https://maps.test/cube/${leaf.file}`;
const NAME = leaf.file.replace('.', '\\.');

/**
 * The triangles the payload says to draw, as vertex index triples, each from its smallest
 * vertex (the chunk file's index codec may start a triangle at another corner; the winding stays).
 */
function drawn(p: ChunkPayload): number[] {
  assert.equal(p.indexSize, 2);
  const idx = [...new Uint16Array(p.buffer, p.indexByteOffset, 3 * p.triangleCount)];
  return idx.flatMap((_, t) => {
    if (t % 3) return [];
    const v = idx.slice(t, t + 3), m = v.indexOf(Math.min(...v));
    return [v[m]!, v[(m + 1) % 3]!, v[(m + 2) % 3]!];
  });
}

/** The ChunkCorrupt the fetch of `of` rejects with. */
async function corruption(of = leaf): Promise<ChunkCorrupt> {
  const err = await fetchChunk(of, URL_C, retry, new AbortController().signal).then(
    () => assert.fail('the chunk was accepted'),
    (e: unknown) => e,
  );
  assert.ok(err instanceof ChunkCorrupt, `ChunkCorrupt, not ${String(err)}`);
  return err;
}

describe('fetching a chunk', () => {
  test('a chunk whose bytes match its name arrives decoded and verified, with its upward triangle only', async (t) => {
    installFakeFetch(t, () => body(squareChunk(1)));
    const p = await fetchChunk(leaf, URL_C, retry, new AbortController().signal);
    assert.equal(p.file, leaf.file);
    assert.equal(p.verified, true);
    assert.equal(p.vertexCount, 4);
    assert.equal(p.originX, 1001);
    assert.equal(p.originY, 2000);
    assert.deepEqual(p.bbox, leaf.bbox);
    // [0, 2, 1] is clockwise seen from above: the inside of the cube never shows it.
    assert.deepEqual(drawn(p), [0, 2, 3]);
    // The vertex columns are where the renderer binds them: z of vertex 2 is 10.
    assert.equal(new Float32Array(p.buffer, p.vertexByteOffset, 12)[8], 10);
  });

  test('a chunk the host sends still gzip-compressed arrives the same', async (t) => {
    installFakeFetch(t, () => body(new Uint8Array(gzipSync(squareChunk(1)))));
    const p = await fetchChunk(leaf, URL_C, retry, new AbortController().signal);
    assert.equal(p.verified, true);
    assert.deepEqual(drawn(p), [0, 2, 3]);
  });

  test('a valid chunk whose bytes are not the ones its name names is refused as corrupt', async (t) => {
    // Another build's chunk under the same name: a good chunk, the wrong hash.
    installFakeFetch(t, () => body(squareChunk(2)));
    const err = await corruption();
    assert.match(err.message, new RegExp(`^${NAME}: SHA-256 ${sha256(squareChunk(2))} does not match its name \\(${sha256(squareChunk(1)).slice(0, 16)}\\)$`));
  });

  test('an index of version 1: any name, checked against the whole SHA-256 beside it', async (t) => {
    const v1 = leafFor('c-1.bin', [0, 0, 0, 1, 1, 10], squareChunk(1));
    installFakeFetch(t, () => body(squareChunk(1)));
    assert.equal((await fetchChunk(v1, URL_C, retry, new AbortController().signal)).verified, true);
    installFakeFetch(t, () => body(squareChunk(2)));
    assert.match((await corruption(v1)).message, new RegExp(`^c-1\\.bin: SHA-256 [0-9a-f]{64} does not match the index \\(${v1.sha256}\\)$`));
  });

  test('one flipped byte is enough to refuse it', async (t) => {
    const bytes = squareChunk(1);
    bytes[16]! ^= 1; // the lowest bit of the origin x: still decodes
    installFakeFetch(t, () => body(bytes));
    assert.match((await corruption()).message, /does not match its name/);
  });

  test('a truncated chunk is corrupt, and the message says why', async (t) => {
    const whole = squareChunk(1);
    installFakeFetch(t, () => body(whole.subarray(0, 130)));
    assert.match((await corruption()).message, new RegExp(`^${NAME}: 130 bytes, its header \\(2 faces, .*\\) needs ${whole.length}`));
  });

  test('a body that starts like gzip but is not is corrupt', async (t) => {
    const bytes = new Uint8Array([0x1f, 0x8b, 1, 2, 3, 4, 5, 6]);
    installFakeFetch(t, () => body(bytes));
    assert.match((await corruption()).message, new RegExp(`^${NAME}: bad gzip body`));
  });

  test('an HTTP error is a fetch failure, not a corrupt chunk', async (t) => {
    installFakeFetch(t, () => status(404));
    await assert.rejects(fetchChunk(leaf, URL_C, retry, new AbortController().signal), (e: unknown) => e instanceof FetchFailure && e.status === 404);
  });

  test('without crypto.subtle (a page not served securely) the chunk arrives, marked unverified', async (t) => {
    const had = Object.getOwnPropertyDescriptor(globalThis, 'crypto');
    assert.ok(had);
    Object.defineProperty(globalThis, 'crypto', { value: undefined, configurable: true });
    t.after(() => Object.defineProperty(globalThis, 'crypto', had));
    // Even bytes the index would refuse: there is nothing to check them with.
    installFakeFetch(t, () => body(squareChunk(2)));
    const p = await fetchChunk(leaf, URL_C, retry, new AbortController().signal);
    assert.equal(p.verified, false);
    assert.equal(p.originX, 1002);
  });
});
