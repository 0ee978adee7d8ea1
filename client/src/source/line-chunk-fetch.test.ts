import assert from 'node:assert/strict';
import { test } from 'node:test';
import { decodeLineChunk } from '../../../format/line-chunk.js';
import { encodeLineChunk } from '../../../format/line-chunk-encode.js';
import { linePathsAtZ, type LineRecord } from '../../../format/line-record.js';
import { glidingSegments } from '../../../format/line-glide.js';
import { lineRamp } from '../../../format/line-ramp.js';
import type { ScaleInfo } from '../../../format/scale.js';
import { lineSegmentPayload } from './line-chunk-fetch.js';

/** Scales doubling with each step, from 1:1,000 at z 0 to z 10. */
const info: ScaleInfo = { baseScale: 1000, baseFaces: 4 ** 10, zMax: 10, scaleTable: Array.from({ length: 11 }, (_, z): [number, number] => [z, 4 ** (10 - z)]) };

// Two lines near national grid coordinates: one whose middle vertices leave at z 3 and 5, one
// straight segment of another class from z 2.
const lines: LineRecord[] = [
  {
    classIndex: 4, rule: 6, feature: 17, zStart: 1, zEnd: 9,
    paths: [Float64Array.from([180000, 456000, 180010, 456004, 180020, 456000, 180030, 456006])],
    leaveZ: [Float64Array.from([9, 3, 5, 9])],
  },
  { classIndex: 7, rule: 5, feature: -1, zStart: 2, zEnd: 6, paths: [Float64Array.from([180000.5, 456050, 180040.25, 456050])], leaveZ: [Float64Array.from([6, 6])] },
];

test('the payload holds, at every z, exactly the segments of the polylines at that z, at the stored positions', async () => {
  const chunk = await decodeLineChunk(encodeLineChunk(lines).bytes);
  const p = lineSegmentPayload(chunk, info);
  assert.equal(p.kind, 'lines');
  assert.equal(p.segments.length, 14 * p.segmentCount);
  assert.deepEqual([...p.lineClass], [4, 7]);
  assert.deepEqual([...p.lineFeature], [17, -1]);
  // Each line's range with its ramps, as format/line-ramp.ts gives them for the cube's scales.
  assert.deepEqual([...p.lineRamp], [lineRamp(info, 1, 9), lineRamp(info, 2, 6)].flatMap((r) => [r.z0, r.z0Full, r.z1Full, r.z1].map(Math.fround)));
  for (const z of [0.5, 1, 2.5, 3, 4.99, 5, 5.5, 8.9, 9]) {
    const expected: string[] = [];
    lines.forEach((l, i) => {
      for (const path of linePathsAtZ(l, z)) {
        for (let k = 0; k + 3 < path.length; k += 2) expected.push(`${i} ${path[k]! - p.originX} ${path[k + 1]! - p.originY} ${path[k + 2]! - p.originX} ${path[k + 3]! - p.originY}`);
      }
    });
    const got: string[] = [];
    for (let s = 0; s < p.segmentCount; s++) {
      const [ax, ay, bx, by, z0, z1] = p.segments.subarray(14 * s, 14 * s + 6);
      if (z0! <= z && z < z1!) got.push(`${p.segmentLine[s]} ${ax} ${ay} ${bx} ${by}`);
    }
    assert.deepEqual(got.sort(), expected.sort(), `z ${z}`);
  }
  // How each end glides: format/line-glide.ts's, relative to the origin, in float32.
  const want = lines.flatMap((l) => glidingSegments(l, info)).map((g) => [g.atx - p.originX, g.aty - p.originY, g.btx - p.originX, g.bty - p.originY, g.aFrom, g.aTo, g.bFrom, g.bTo].map(Math.fround).join(' '));
  const glides = Array.from({ length: p.segmentCount }, (_, s) => [...p.segments.subarray(14 * s + 6, 14 * s + 14)].join(' '));
  assert.deepEqual(glides.sort(), want.sort());
  const f = p.segments;
  assert.ok(glides.some((_, s) => f[14 * s + 6] !== f[14 * s] || f[14 * s + 7] !== f[14 * s + 1] || f[14 * s + 8] !== f[14 * s + 2] || f[14 * s + 9] !== f[14 * s + 3]), 'some vertex glides');
  // The rule of each segment is its line's, and segments come in rule order (drawn so).
  for (let s = 0; s < p.segmentCount; s++) assert.equal(p.segmentRule[s], lines[p.segmentLine[s]!]!.rule);
  for (let s = 1; s < p.segmentCount; s++) assert.ok(p.segmentRule[s - 1]! <= p.segmentRule[s]!);
});
