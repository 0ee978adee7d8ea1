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
    assert.deepEqual(new Uint8Array(await gunzipWithoutStreams(gzBuf)), data);
    const plain = data.buffer.slice(0);
    assert.equal(await gunzipIfNeeded(plain), plain, 'a body that is not gzip is passed through');
  });

  test('without DecompressionStream, a damaged body is refused as the platform refuses it', async () => {
    const damaged = (edit: (b: Uint8Array, dv: DataView) => void): ArrayBuffer => {
      const b = new Uint8Array(gz);
      edit(b, new DataView(b.buffer));
      return b.buffer;
    };
    const n = gz.byteLength;
    const cases: [string, ArrayBuffer, RegExp][] = [
      ['a CRC-32 one bit off', damaged((_, dv) => dv.setUint32(n - 8, dv.getUint32(n - 8, true) ^ 1, true)), /CRC-32 does not match/],
      // fflate sizes its output by the stored length: one byte short, the CRC tells.
      ['a stored length one short', damaged((_, dv) => dv.setUint32(n - 4, 999, true)), /CRC-32 does not match/],
      ['a stored length one long', damaged((_, dv) => dv.setUint32(n - 4, 1001, true)), /gave 1000 bytes, its trailer says 1001/],
      ['a stored length deflate cannot reach', damaged((_, dv) => dv.setUint32(n - 4, 0xfffffff0, true)), /says it holds 4294967280, more than deflate can give/],
      // The last 8 bytes are then compressed data, read as a length beyond reach.
      ['the trailer cut short', gzBuf.slice(0, n - 3), /more than deflate can give/],
      ['a few bytes', gzBuf.slice(0, 12), /too short to be whole/],
    ];
    for (const [what, body, why] of cases) {
      await assert.rejects(gunzipWithoutStreams(body), why, what);
      await assert.rejects(gunzipIfNeeded(body), Error, `${what}: DecompressionStream refuses it too`);
    }
  });
});
