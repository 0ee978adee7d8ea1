// Unit tests of the client's pure modules (client/src/shared), in Node.
import assert from 'node:assert/strict';
import { gzipSync } from 'node:zlib';
import { describe, test } from 'node:test';
import { gunzipIfNeeded, gunzipWithPako, isGzip } from '../src/shared/gunzip.js';
import { relativeZ, surfaceParams } from '../src/shared/surface-params.js';
import { surfaceZ, type SurfaceSpec } from '../../format/slicing-surface.js';
import { keepUpwardTriangles } from '../src/shared/upward-triangles.js';
import { fitBbox, groundToPixel, pixelToGround, viewBbox } from '../src/shared/view.js';

describe('surfaces around the view centre (the GPU formulas)', () => {
  // A view centre on the Dutch national grid, where float32 alone would lose centimetres.
  const cx = 181282.695, cy = 457031.109;
  const specs: SurfaceSpec[] = [
    { kind: 'flat' },
    { kind: 'tilted', cx: 181300.5, cy: 457000.25, dzdx: 0.9, dzdy: -0.4 },
    { kind: 'sine', amplitude: 150, wavelength: 130, angle: 30 },
    { kind: 'lens', cx: 181250, cy: 457100, radius: 140, depth: 370 },
    { kind: 'idw', power: 2, points: [{ x: 181143.2, y: 456911.36, z: 10 }, { x: 181392.7, y: 456951.1, z: 300 }, { x: 181282.7, y: 457181.1, z: 150 }] },
  ];
  for (const spec of specs) {
    test(`${spec.kind}: the same z as surfaces.ts`, () => {
      const s = { base: 220, spec };
      const p = surfaceParams(s, cx, cy);
      let worst = 0;
      for (let k = 0; k < 500; k++) {
        const dx = ((k * 7919) % 401) - 200.3, dy = ((k * 104729) % 397) - 198.7;
        const want = surfaceZ(s, cx + dx, cy + dy, 1e9);
        // surfaceZ clamps to [0, zMax] (the shader too, after relativeZ).
        worst = Math.max(worst, Math.abs(Math.max(0, relativeZ(p, dx, dy)) - want));
      }
      // idw points travel as float32 offsets from the centre: a few micrometres.
      assert.ok(worst < 1e-4, `largest difference ${worst}`);
    });
  }
});

describe('gzip bodies', () => {
  const data = new Uint8Array(1000).map((_, i) => (i * 37) & 0xff);
  const gz = gzipSync(data);
  const gzBuf = gz.buffer.slice(gz.byteOffset, gz.byteOffset + gz.byteLength);

  test('are recognised by their magic', () => {
    assert.equal(isGzip(gzBuf), true);
    assert.equal(isGzip(data.buffer), false);
  });

  test('decompress with DecompressionStream, and with pako where it is missing', async () => {
    assert.deepEqual(new Uint8Array(await gunzipIfNeeded(gzBuf)), data);
    const saved = globalThis.DecompressionStream;
    try {
      // The fallback path of browsers without DecompressionStream.
      (globalThis as { DecompressionStream?: unknown }).DecompressionStream = undefined;
      assert.deepEqual(new Uint8Array(await gunzipIfNeeded(gzBuf)), data);
    } finally {
      globalThis.DecompressionStream = saved;
    }
    assert.deepEqual(new Uint8Array(await gunzipWithPako(gzBuf)), data);
    const plain = data.buffer.slice(0);
    assert.equal(await gunzipIfNeeded(plain), plain, 'a body that is not gzip is passed through');
  });
});

describe('the inside-facing triangles', () => {
  test('are the counterclockwise ones; clockwise and degenerate ones are dropped', () => {
    const pos = Float32Array.from([0, 0, 0, 1, 0, 0, 0, 1, 0, 2, 2, 0]);
    const idx = Uint16Array.from([0, 1, 2, 0, 2, 1, 1, 2, 3, 0, 3, 0, 1, 3, 2]);
    const n = keepUpwardTriangles(pos, idx);
    assert.equal(n, 2);
    assert.deepEqual([...idx.subarray(0, 6)], [0, 1, 2, 1, 3, 2]);
  });
});

describe('view geometry', () => {
  test('fits a box with square pixels and maps pixel centres both ways', () => {
    const v = fitBbox([181000, 456800, 181400, 457200], 640, 480);
    assert.equal(v.resolution, 400 / 480);
    const b = viewBbox(v);
    assert.ok(Math.abs(b[1] - 456800) < 1e-9 && Math.abs(b[3] - 457200) < 1e-9);
    assert.ok(Math.abs(b[2] - b[0] - 640 * v.resolution) < 1e-9);
    const [x, y] = pixelToGround(v, 0.5, 0.5);
    assert.ok(Math.abs(x - (b[0] + 0.5 * v.resolution)) < 1e-9 && Math.abs(y - (b[3] - 0.5 * v.resolution)) < 1e-9);
    const [px, py] = groundToPixel(v, x, y);
    assert.ok(Math.abs(px - 0.5) < 1e-9 && Math.abs(py - 0.5) < 1e-9);
  });
});
