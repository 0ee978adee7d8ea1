// The line chunk file, version 4: the encoder writes the layout of docs/FORMAT.md (header and
// records checked at offsets worked out by hand, the streams decoded with meshoptimizer's own
// decoder), lines come back on the position grid (within half a step; z exact in float32), the
// same lines give the same bytes, and a damaged, truncated or old file is refused with a message
// saying what is wrong.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { MeshoptDecoder } from 'meshoptimizer/decoder';
import { MeshoptEncoder } from 'meshoptimizer/encoder';
import { roadAndBrook } from '../testing/road-and-brook.js';
import { FormatError } from './format-error.js';
import { decodeLineChunk, lineOfChunk } from './line-chunk.js';
import { encodeLineChunk } from './line-chunk-encode.js';
import type { LineRecord } from './line-record.js';

await MeshoptDecoder.ready;
await MeshoptEncoder.ready;

/** Record sizes of docs/FORMAT.md: line, polyline, vertex. */
const STRIDES = [20, 4, 12] as const;
const pad4 = (n: number): number => Math.ceil(n / 4) * 4;

/** The three streams of a file, decoded to records by the header's lengths, read as the doc says. */
function records(bytes: Uint8Array): DataView[] {
  const dv = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const counts = [dv.getUint32(8, true), dv.getUint32(12, true), dv.getUint32(16, true)];
  let at = 76;
  return STRIDES.map((stride, s) => {
    const length = dv.getUint32(64 + 4 * s, true);
    const out = new Uint8Array(counts[s]! * stride);
    MeshoptDecoder.decodeVertexBuffer(out, counts[s]!, stride, bytes.subarray(at, at + length));
    at = pad4(at + length);
    return new DataView(out.buffer);
  });
}

/** A file with the header of `bytes` and its records edited: streams re-encoded, lengths rewritten. */
function edited(bytes: Uint8Array, edit: (lines: DataView, paths: DataView, vertices: DataView) => void): Uint8Array {
  const r = records(bytes);
  edit(r[0]!, r[1]!, r[2]!);
  const streams = r.map((v, s) => MeshoptEncoder.encodeVertexBufferLevel(new Uint8Array(v.buffer), v.byteLength / STRIDES[s]!, STRIDES[s]!, 2, 1));
  const out = new Uint8Array(streams.reduce((n, s) => pad4(n + s.length), 76));
  out.set(bytes.subarray(0, 64));
  let at = 76;
  streams.forEach((s, i) => {
    new DataView(out.buffer).setUint32(64 + 4 * i, s.length, true);
    out.set(s, at);
    at = pad4(at + s.length);
  });
  return out;
}

describe('line chunk file', () => {
  test('the encoder writes the documented layout', () => {
    const { bytes, bbox } = encodeLineChunk(roadAndBrook());
    const dv = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
    assert.equal(dv.getUint32(0, true), 0x4c435353);
    assert.equal(dv.getUint32(4, true), 4);
    assert.deepEqual([dv.getUint32(8, true), dv.getUint32(12, true), dv.getUint32(16, true)], [2, 3, 8], '2 lines, 3 polylines, 8 vertices');
    // The box relative to the origin reaches y 40.75: below 2^6, so the step is 2^(6 - 24).
    assert.equal(dv.getInt32(20, true), -18, 'position step exponent');
    assert.equal(dv.getFloat64(24, true), 181000, 'origin x: whole metres below the smallest x');
    assert.equal(dv.getFloat64(32, true), 456990);
    assert.deepEqual([0, 1, 2, 3, 4, 5].map((i) => dv.getFloat32(40 + 4 * i, true)), [0.5, 0, 3, 30, 40.75, 40.25], 'box');
    const [ll, lp, lv] = [64, 68, 72].map((o) => dv.getUint32(o, true)) as [number, number, number];
    assert.equal(bytes.byteLength, pad4(pad4(pad4(76 + ll) + lp) + lv), 'header, then the three streams, each padded to 4 bytes');
    const [lines, paths, vertices] = records(bytes) as [DataView, DataView, DataView];
    // Line 1 (the brook) from byte 20 of the line records.
    assert.deepEqual(
      [lines.getUint16(20, true), lines.getUint16(22, true), lines.getInt32(24, true), lines.getFloat32(28, true), lines.getFloat32(32, true), lines.getUint32(36, true)],
      [7, 300, -1, 3, 12, 1], 'class, rule, feature, zStart, zEnd, polylines of line 1',
    );
    assert.equal(lines.getUint32(16, true), 2, 'the road has two polylines');
    assert.deepEqual([0, 4, 8].map((o) => paths.getUint32(o, true)), [3, 2, 3], 'vertices of each polyline');
    // Vertex 4: the T's end (181010.5, 457030.75), 10.5 and 40.75 m from the origin, in steps of 2^-18.
    assert.deepEqual([vertices.getInt32(48, true), vertices.getInt32(52, true), vertices.getFloat32(56, true)], [10.5 * 2 ** 18, 40.75 * 2 ** 18, 40.25]);
    assert.equal(vertices.getFloat32(6 * 12 + 8, true), 5, 'leave z of vertex 6');
    assert.deepEqual(bbox, [181000.5, 456990, 3, 181030, 457030.75, 40.25]);
  });

  test('lines come back with their class, rule, feature, z range and coordinates', async () => {
    const c = await decodeLineChunk(encodeLineChunk(roadAndBrook()).bytes);
    assert.deepEqual([c.lineCount, c.pathCount, c.vertexCount], [2, 3, 8]);
    assert.deepEqual([...c.linePaths], [0, 2, 3]);
    assert.deepEqual([...c.pathVertices], [0, 3, 5, 8]);
    assert.deepEqual([0, 1].map((i) => lineOfChunk(c, i)), roadAndBrook(), 'these coordinates are on the grid and these z exact in float32');
  });

  test('coordinates off the grid come back on it, within half a step; z to float32', async () => {
    // 1,765 m wide from the origin 181234: below 2^11, a step of 2^(11 - 24) = 1/8192 m.
    const x = [181234.123456, 182999.001, 181500.3, 182000.77777], y = [457890.987654, 459000.002, 458000.1, 457891.5];
    const l: LineRecord = { classIndex: 0, rule: 0, feature: 0, zStart: 0.1, zEnd: 1.3, paths: [Float64Array.from(x.flatMap((v, i) => [v, y[i]!]))], leaveZ: [Float64Array.of(1.3, 0.7, 0.9, 1.3)] };
    const c = await decodeLineChunk(encodeLineChunk([l]).bytes);
    assert.deepEqual([c.originX, c.originY], [181234, 457890]);
    const step = 2 ** -13;
    const back = lineOfChunk(c, 0);
    for (let i = 0; i < 8; i++) {
      const want = l.paths[0]![i]!, got = back.paths[0]![i]!, origin = i % 2 === 0 ? 181234 : 457890;
      assert.equal(got - origin, Math.round((want - origin) / step) * step, `coordinate ${i}: the nearest grid value`);
      assert.ok(Math.abs(got - want) <= step / 2, `coordinate ${i}: ${got} for ${want}`);
    }
    assert.deepEqual([...back.leaveZ[0]!], [1.3, 0.7, 0.9, 1.3].map(Math.fround));
    assert.deepEqual([back.zStart, back.zEnd], [Math.fround(0.1), Math.fround(1.3)]);
  });

  test('on the cube\'s grid: positions are whole steps of it, within half a step; version 3 is still read', async () => {
    const lines = roadAndBrook();
    const { bytes } = encodeLineChunk(lines, -7);
    assert.equal(new DataView(bytes.buffer).getInt32(20, true), -7, 'the header holds the cube\'s grid');
    const c = await decodeLineChunk(bytes);
    let k = 0;
    for (const l of lines) for (const p of l.paths) for (let j = 0; j < p.length; j++, k++) {
      const got = c.positions[k]! + (j % 2 === 0 ? c.originX : c.originY);
      assert.equal(got, Math.round(p[j]! * 128) / 128, `coordinate ${k}: the nearest 1/128`);
    }
    const v3 = encodeLineChunk(lines).bytes.slice();
    new DataView(v3.buffer).setUint32(4, 3, true);
    assert.equal((await decodeLineChunk(v3)).vertexCount, c.vertexCount);
  });

  test('the same lines give the same bytes, and decoded lines encode to them again', async () => {
    const a = encodeLineChunk(roadAndBrook()).bytes;
    assert.deepEqual(encodeLineChunk(roadAndBrook()).bytes, a);
    const c = await decodeLineChunk(a);
    assert.deepEqual(encodeLineChunk([0, 1].map((i) => lineOfChunk(c, i))).bytes, a);
  });

  test('damaged, truncated and old files are refused, saying what is wrong', async () => {
    const good = encodeLineChunk(roadAndBrook()).bytes;
    const header = (edit: (dv: DataView) => void): Uint8Array => {
      const b = good.slice();
      edit(new DataView(b.buffer));
      return b;
    };
    const refuses = async (bytes: Uint8Array, message: RegExp): Promise<void> => {
      await assert.rejects(decodeLineChunk(bytes, 'l-test.bin'), (err: Error) => {
        assert.ok(err instanceof FormatError && err.message.startsWith('l-test.bin: '), err.message);
        assert.match(err.message, message);
        return true;
      });
    };
    await refuses(good.subarray(0, 40), /truncated \(40 bytes, the header alone is 76\)/);
    await refuses(good.subarray(0, good.length - 4), /bytes, its header \(.*\) needs \d+/);
    await refuses(header((dv) => dv.setUint32(0, 0x43435353, true)), /bad magic/);
    await refuses(header((dv) => dv.setUint32(4, 2, true)), /line chunk version 2, this reader knows only versions 3 and 4 \(rebuild the cube with ssc build\)/);
    await refuses(header((dv) => dv.setUint32(16, 0xffffffff, true)), /4294967295 vertices cannot fit a stream of \d+ bytes/);
    await refuses(header((dv) => dv.setUint32(12, 1, true)), /counts out of bounds \(2 lines, 1 polylines/);
    await refuses(header((dv) => dv.setInt32(20, -19, true)), /position step 2\^-19 does not fit its box \(2\^-18 to 2\^64\)/);
    // Version 3 knew only the box's own grid.
    await refuses(header((dv) => { dv.setUint32(4, 3, true); dv.setInt32(20, -17, true); }), /position step 2\^-17 does not fit its box \(2\^-18\)/);
    await refuses(header((dv) => dv.setUint8(76, 0)), /compressed lines, polylines or vertices do not decode/);
    await refuses(edited(good, (_, paths) => paths.setUint32(0, 1, true)), /polyline 0 has 1 vertices \(at least 2\)/);
    await refuses(edited(good, (_, paths) => paths.setUint32(8, 4, true)), /polyline 2 ends at vertex 9, beyond the header's 8/);
    await refuses(edited(good, (lines) => lines.setUint32(16, 0, true)), /line 0 has no polyline/);
    await refuses(edited(good, (lines) => lines.setUint32(36, 2, true)), /line 1 ends at polyline 4, beyond the header's 3/);
    await refuses(edited(good, (lines) => lines.setFloat32(12, 10.5, true)), /line 0 has an empty z range \[10.5, 10.5\)/);
    await refuses(edited(good, (_, __, vertices) => vertices.setFloat32(6 * 12 + 8, NaN, true)), /vertex 6 has a non-finite leave z/);
    await refuses(edited(good, (_, __, vertices) => vertices.setInt32(0, 2 ** 24 + 1, true)), /vertex 0 lies outside the grid of its box/);
    // The edits alone, without damage, give a file the reader takes.
    assert.equal((await decodeLineChunk(edited(good, () => {}))).vertexCount, 8);
  });

  test('the encoder refuses a polyline of one point and a rule beyond u16', () => {
    const l: LineRecord = { classIndex: 2, rule: 0, feature: 9, zStart: 0, zEnd: 1, paths: [Float64Array.of(1, 2)], leaveZ: [Float64Array.of(1)] };
    assert.throws(() => encodeLineChunk([l]), /class 2, feature #9: polyline 0 needs two points/);
    const ok = { ...l, paths: [Float64Array.of(1, 2, 3, 4)], leaveZ: [Float64Array.of(1, 1)] };
    assert.throws(() => encodeLineChunk([{ ...ok, rule: 65536 }]), /class 2, feature #9: line rule 65536 is not a u16/);
  });
});
