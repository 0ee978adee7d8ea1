// A line over z: it is there for zStart <= z < zEnd, its polyline at a z drops the vertices gone
// by then, and its segments with their z ranges are, at every z, those of the polylines.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { roadAndBrook } from '../testing/road-and-brook.js';
import { lineAliveAt, linePathsAtZ, lineSegments, type LineRecord } from './line-record.js';

test('a line is there for zStart <= z < zEnd, and loses each vertex at its leave z', () => {
  const [road, brook] = roadAndBrook() as [LineRecord, LineRecord];
  assert.deepEqual([10, 10.5, 40, 40.25].map((z) => lineAliveAt(road, z)), [false, true, true, false]);
  assert.deepEqual(linePathsAtZ(road, 20).map((p) => [...p]), [[181000.5, 457000.25, 181010.5, 457000.25, 181020.5, 457000.25], [181010.5, 457000.25, 181010.5, 457030.75]]);
  assert.deepEqual(linePathsAtZ(road, 20.125)[0], Float64Array.of(181000.5, 457000.25, 181020.5, 457000.25), 'the middle vertex has gone');
  assert.deepEqual(linePathsAtZ(brook, 12), [], 'pruned');
});

test('segments with their z ranges: at every z, the segments of the polylines at that z', () => {
  const [road, brook] = roadAndBrook() as [LineRecord, LineRecord];
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
