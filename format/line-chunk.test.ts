// The line chunk file: the encoder writes the layout of docs/FORMAT.md (checked at offsets
// worked out by hand), lines come back as they went in (to float32), the polyline at a z drops
// the vertices gone by then, and a damaged file is refused with a message saying what is wrong.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { decodeLineChunk, encodeLineChunk, lineAliveAt, lineOfChunk, linePathsAtZ, lineSegments, type LineRecord } from './line-chunk.js';
import { FormatError } from './format-error.js';

/** A road of two polylines (a T: 3 + 2 points) and a brook of one (3 points). */
function lines(): LineRecord[] {
  return [
    {
      classIndex: 4, rule: 9, feature: 17, zStart: 10.5, zEnd: 40.25,
      paths: [Float64Array.of(181000.5, 457000.25, 181010.5, 457000.25, 181020.5, 457000.25), Float64Array.of(181010.5, 457000.25, 181010.5, 457030.75)],
      leaveZ: [Float64Array.of(40.25, 20.125, 40.25), Float64Array.of(40.25, 40.25)],
    },
    {
      classIndex: 7, rule: 300, feature: -1, zStart: 3, zEnd: 12,
      paths: [Float64Array.of(181005, 456990, 181006, 456995, 181030, 457001)],
      leaveZ: [Float64Array.of(12, 5, 12)],
    },
  ];
}

describe('line chunk file', () => {
  test('the encoder writes the documented layout', () => {
    const { bytes, bbox } = encodeLineChunk(lines());
    const dv = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
    // 2 lines, 3 polylines, 8 vertices: header 64, classes 4, rules 4, feature/zStart/zEnd 3 x 8,
    // line polylines 3 x 4, polyline vertices 4 x 4, positions 8 x 8, leave z 8 x 4.
    assert.equal(bytes.byteLength, 64 + 4 + 4 + 24 + 12 + 16 + 64 + 32);
    assert.equal(dv.getUint32(0, true), 0x4c435353);
    assert.equal(dv.getUint32(4, true), 2);
    assert.deepEqual([dv.getUint32(8, true), dv.getUint32(12, true), dv.getUint32(16, true)], [2, 3, 8]);
    assert.equal(dv.getFloat64(24, true), 181000, 'origin x: whole metres below the smallest x');
    assert.equal(dv.getFloat64(32, true), 456990);
    assert.equal(dv.getFloat32(40 + 4 * 5, true), 40.25, 'box z1');
    assert.equal(dv.getUint16(64 + 2, true), 7, 'class of line 1');
    assert.deepEqual([68, 70].map((o) => dv.getUint16(o, true)), [9, 300], 'line rule of each line');
    assert.equal(dv.getInt32(72 + 4, true), -1, 'feature of line 1');
    assert.equal(dv.getFloat32(80, true), 10.5, 'zStart of line 0');
    assert.equal(dv.getFloat32(88 + 4, true), 12, 'zEnd of line 1');
    assert.deepEqual([96, 100, 104].map((o) => dv.getUint32(o, true)), [0, 2, 3], 'first polyline of each line, then the count');
    assert.deepEqual([108, 112, 116, 120].map((o) => dv.getUint32(o, true)), [0, 3, 5, 8], 'first vertex of each polyline, then the count');
    assert.equal(dv.getFloat32(124 + 8 * 4 + 4, true), 40.75, 'y of vertex 4, relative to origin y 456990');
    assert.equal(dv.getFloat32(188 + 4 * 6, true), 5, 'leave z of vertex 6');
    assert.deepEqual(bbox, [181000.5, 456990, 3, 181030, 457030.75, 40.25]);
  });

  test('lines come back with their class, rule, feature, z range and coordinates', () => {
    const c = decodeLineChunk(encodeLineChunk(lines()).bytes);
    assert.equal(c.lineCount, 2);
    assert.deepEqual([0, 1].map((i) => lineOfChunk(c, i)), lines(), 'these coordinates and z are exact in float32 relative to the origin');
  });

  test('coordinates far from whole metres keep millimetres', () => {
    const l: LineRecord = { classIndex: 0, rule: 0, feature: 0, zStart: 0, zEnd: 1, paths: [Float64Array.of(181234.123456, 457890.987654, 182999.001, 459000.002)], leaveZ: [Float64Array.of(1, 1)] };
    const back = lineOfChunk(decodeLineChunk(encodeLineChunk([l]).bytes), 0).paths[0]!;
    for (let i = 0; i < 4; i++) assert.ok(Math.abs(back[i]! - l.paths[0]![i]!) < 0.001, `coordinate ${i}: ${back[i]} for ${l.paths[0]![i]}`);
  });

  test('a line is there for zStart <= z < zEnd, and loses each vertex at its leave z', () => {
    const [road, brook] = lines() as [LineRecord, LineRecord];
    assert.deepEqual([10, 10.5, 40, 40.25].map((z) => lineAliveAt(road, z)), [false, true, true, false]);
    assert.deepEqual(linePathsAtZ(road, 20).map((p) => [...p]), [[181000.5, 457000.25, 181010.5, 457000.25, 181020.5, 457000.25], [181010.5, 457000.25, 181010.5, 457030.75]]);
    assert.deepEqual(linePathsAtZ(road, 20.125)[0], Float64Array.of(181000.5, 457000.25, 181020.5, 457000.25), 'the middle vertex has gone');
    assert.deepEqual(linePathsAtZ(brook, 12), [], 'pruned');
  });

  test('segments with their z ranges: at every z, the segments of the polylines at that z', () => {
    const [road, brook] = lines() as [LineRecord, LineRecord];
    const seg = (ax: number, ay: number, bx: number, by: number, z0: number, z1: number, path: number, a: number, b: number): object => ({ ax, ay, bx, by, z0, z1, path, a, b });
    assert.deepEqual(lineSegments(road), [
      seg(181000.5, 457000.25, 181010.5, 457000.25, 10.5, 20.125, 0, 0, 1),
      seg(181000.5, 457000.25, 181020.5, 457000.25, 20.125, 40.25, 0, 0, 2),
      seg(181010.5, 457000.25, 181020.5, 457000.25, 10.5, 20.125, 0, 1, 2),
      seg(181010.5, 457000.25, 181010.5, 457030.75, 10.5, 40.25, 1, 0, 1),
    ]);
    // A line whose vertices leave one after another, checked at many z against linePathsAtZ.
    const zig: LineRecord = {
      classIndex: 0, rule: 0, feature: 0, zStart: 1, zEnd: 9,
      paths: [Float64Array.from({ length: 14 }, (_, i) => (i % 2 === 0 ? i : (i % 4) * 3))],
      leaveZ: [Float64Array.of(9, 4, 2, 6, 3, 5, 9)],
    };
    for (const l of [road, brook, zig]) {
      for (let z = 0; z < 42; z += 0.25) {
        const want = linePathsAtZ(l, z).flatMap((p) => Array.from({ length: p.length / 2 - 1 }, (_, i) => [...p.subarray(2 * i, 2 * i + 4)].join(' ')));
        const got = lineSegments(l).filter((s) => s.z0 <= z && z < s.z1).map((s) => [s.ax, s.ay, s.bx, s.by].join(' '));
        assert.deepEqual(got.sort(), want.sort(), `segments at z ${z}`);
      }
    }
  });

  test('damaged files are refused, saying what is wrong', () => {
    const good = encodeLineChunk(lines()).bytes;
    const damaged = (edit: (dv: DataView) => void): Uint8Array => {
      const b = good.slice();
      edit(new DataView(b.buffer));
      return b;
    };
    const refuses = (bytes: Uint8Array, message: RegExp): void => {
      assert.throws(() => decodeLineChunk(bytes, 'l-test.bin'), (err: Error) => err instanceof FormatError && message.test(err.message) && err.message.startsWith('l-test.bin'));
    };
    refuses(good.subarray(0, 40), /truncated/);
    refuses(good.subarray(0, good.length - 4), /bytes, 2 lines, 3 polylines and 8 vertices need/);
    refuses(damaged((dv) => dv.setUint32(0, 0x43435353, true)), /bad magic/);
    refuses(damaged((dv) => dv.setUint32(4, 1, true)), /version 1, this reader knows 2/);
    refuses(damaged((dv) => dv.setUint32(112, 1, true)), /polyline 0 has 1 vertices \(at least 2\)/);
    refuses(damaged((dv) => dv.setUint32(104, 2, true)), /line offsets do not run from 0 to 3/);
    refuses(damaged((dv) => dv.setFloat32(88, 10.5, true)), /line 0 has an empty z range/);
    refuses(damaged((dv) => dv.setFloat32(124, NaN, true)), /vertex 0 has a non-finite coordinate/);
  });

  test('the encoder refuses a polyline of one point and a rule beyond u16', () => {
    const l: LineRecord = { classIndex: 2, rule: 0, feature: 9, zStart: 0, zEnd: 1, paths: [Float64Array.of(1, 2)], leaveZ: [Float64Array.of(1)] };
    assert.throws(() => encodeLineChunk([l]), /class 2, feature #9: polyline 0 needs two points/);
    const ok = { ...l, paths: [Float64Array.of(1, 2, 3, 4)], leaveZ: [Float64Array.of(1, 1)] };
    assert.throws(() => encodeLineChunk([{ ...ok, rule: 65536 }]), /class 2, feature #9: line rule 65536 is not a u16/);
  });
});
