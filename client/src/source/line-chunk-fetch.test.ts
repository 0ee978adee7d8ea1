import assert from 'node:assert/strict';
import { test } from 'node:test';
import { decodeLineChunk, encodeLineChunk, linePathsAtZ, type LineRecord } from '../../../format/line-chunk.js';
import { lineSegmentPayload } from './line-chunk-fetch.js';

// Two lines near national grid coordinates: one whose middle vertices leave at z 3 and 5, one
// straight segment of another class from z 2.
const lines: LineRecord[] = [
  {
    classIndex: 4, feature: 17, zStart: 1, zEnd: 9,
    paths: [Float64Array.from([180000, 456000, 180010, 456004, 180020, 456000, 180030, 456006])],
    leaveZ: [Float64Array.from([9, 3, 5, 9])],
  },
  { classIndex: 7, feature: -1, zStart: 2, zEnd: 6, paths: [Float64Array.from([180000.5, 456050, 180040.25, 456050])], leaveZ: [Float64Array.from([6, 6])] },
];

test('the payload holds, at every z, exactly the segments of the polylines at that z, at the stored positions', () => {
  const chunk = decodeLineChunk(encodeLineChunk(lines).bytes);
  const p = lineSegmentPayload(chunk);
  assert.equal(p.kind, 'lines');
  assert.equal(p.segments.length, 6 * p.segmentCount);
  assert.deepEqual([...p.lineClass], [4, 7]);
  assert.deepEqual([...p.lineFeature], [17, -1]);
  assert.deepEqual([...p.lineZ], [1, 9, 2, 6]);
  for (const z of [0.5, 1, 2.5, 3, 4.99, 5, 5.5, 8.9, 9]) {
    const expected: string[] = [];
    lines.forEach((l, i) => {
      for (const path of linePathsAtZ(l, z)) {
        for (let k = 0; k + 3 < path.length; k += 2) expected.push(`${i} ${path[k]! - p.originX} ${path[k + 1]! - p.originY} ${path[k + 2]! - p.originX} ${path[k + 3]! - p.originY}`);
      }
    });
    const got: string[] = [];
    for (let s = 0; s < p.segmentCount; s++) {
      const [ax, ay, bx, by, z0, z1] = p.segments.subarray(6 * s, 6 * s + 6);
      if (z0! <= z && z < z1!) got.push(`${p.segmentLine[s]} ${ax} ${ay} ${bx} ${by}`);
    }
    assert.deepEqual(got.sort(), expected.sort(), `z ${z}`);
  }
  // The rule of each segment is its line's class (until the style gives line rules).
  for (let s = 0; s < p.segmentCount; s++) assert.equal(p.segmentRule[s], lines[p.segmentLine[s]!]!.classIndex);
});
