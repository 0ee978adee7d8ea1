// Gzip bodies (a host serving the .gz copy without Content-Encoding) recognised and decompressed.
import assert from 'node:assert/strict';
import { gzipSync } from 'node:zlib';
import { describe, test } from 'node:test';
import { gunzipIfNeeded, gunzipWithoutStreams, isGzip } from './gunzip.js';

describe('gzip bodies', () => {
  const data = new Uint8Array(1000).map((_, i) => (i * 37) & 0xff);
  const gz = gzipSync(data);
  const gzBuf = gz.buffer.slice(gz.byteOffset, gz.byteOffset + gz.byteLength);

  test('are recognised by their magic', () => {
    assert.equal(isGzip(gzBuf), true);
    assert.equal(isGzip(data.buffer), false);
  });

  test('decompress with DecompressionStream, and with fflate where it is missing', async () => {
    assert.deepEqual(new Uint8Array(await gunzipIfNeeded(gzBuf)), data);
    const saved = globalThis.DecompressionStream;
    try {
      // The fallback path of browsers without DecompressionStream.
      (globalThis as { DecompressionStream?: unknown }).DecompressionStream = undefined;
      assert.deepEqual(new Uint8Array(await gunzipIfNeeded(gzBuf)), data);
    } finally {
      globalThis.DecompressionStream = saved;
    }
    assert.deepEqual(new Uint8Array(gunzipWithoutStreams(gzBuf)), data);
    const plain = data.buffer.slice(0);
    assert.equal(await gunzipIfNeeded(plain), plain, 'a body that is not gzip is passed through');
  });
});
