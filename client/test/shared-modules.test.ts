// Unit tests of the client's pure modules (client/src/shared), in Node.
import assert from 'node:assert/strict';
import { gzipSync } from 'node:zlib';
import { describe, test } from 'node:test';
import type { InnerNode } from '../../format/cube-index.js';
import { decodeFacePage, faceRecord, FacePageError } from '../../format/face-page.js';
import { gunzipIfNeeded, gunzipWithPako, isGzip } from '../src/shared/gunzip.js';
import { chunkPriority, queryIndex } from '../../format/index-query.js';
import { relativeZ, surfaceParams } from '../src/shared/surface-params.js';
import { formatSurface } from '../../format/slicing-surface.js';
import { parseSurface, surfaceZ, type SurfaceSpec } from '../../format/slicing-surface.js';
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

  test('a surface written as text reads back the same', () => {
    for (const spec of specs.slice(1)) assert.deepEqual(parseSurface(formatSurface(spec)), spec);
  });
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

describe('face table pages', () => {
  /** A page written by hand after docs/FORMAT.md. */
  function page(first: number, rows: [number, number, number, number, number][]): ArrayBuffer {
    const n = rows.length;
    const classBytes = (2 * n + 3) & ~3;
    const buf = new ArrayBuffer(16 + classBytes + 16 * n);
    const dv = new DataView(buf);
    dv.setUint32(0, 0x46435353, true);
    dv.setUint32(4, 1, true);
    dv.setUint32(8, first, true);
    dv.setUint32(12, n, true);
    rows.forEach(([cls, feat, lo, hi, into], i) => {
      dv.setUint16(16 + 2 * i, cls, true);
      dv.setInt32(16 + classBytes + 4 * i, feat, true);
      dv.setUint32(16 + classBytes + 4 * n + 4 * i, lo, true);
      dv.setUint32(16 + classBytes + 8 * n + 4 * i, hi, true);
      dv.setInt32(16 + classBytes + 12 * n + 4 * i, into, true);
    });
    return buf;
  }

  test('give each face its class, feature and steps', () => {
    const p = decodeFacePage(page(100, [[3, 7, 0, 12, 101], [1, -1, 12, 475, -1], [65535, 9, 5, 6, 100]]));
    assert.deepEqual(faceRecord(p, 101), { face: 101, classIndex: 1, feature: -1, stepLow: 12, stepHigh: 475, mergedInto: -1 });
    assert.deepEqual(faceRecord(p, 102), { face: 102, classIndex: 65535, feature: 9, stepLow: 5, stepHigh: 6, mergedInto: 100 });
    assert.equal(faceRecord(p, 99), undefined);
    assert.equal(faceRecord(p, 103), undefined);
  });

  test('refuse a bad magic or length', () => {
    const good = page(0, [[1, 2, 3, 4, 5]]);
    const bad = good.slice(0);
    new DataView(bad).setUint32(0, 0x12345678, true);
    assert.throws(() => decodeFacePage(bad), FacePageError);
    assert.throws(() => decodeFacePage(good.slice(0, good.byteLength - 4)), FacePageError);
  });
});

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
