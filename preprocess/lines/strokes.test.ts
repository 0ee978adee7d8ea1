// Strokes on a hand-drawn network:
//
//              s3 (group 1, up from (200,0))
//               |
//   m1 ------- m2 ------- m3        a main road (group 0) cut at (100,0) and (200,0),
//   (0,0)   (100,0)  (200,0)  (300,0)   bending 20 degrees at (200,0)
//               |
//              s1 (group 1, down from (100,0))      s2 (group 1): turns 90 degrees off s1's end
//
// The main road's three pieces are one stroke; s1 and s3 cross the road at different points and
// stay apart; s2 turns too sharply to continue s1; a street (group 1) running on straight from
// the road's end is not part of the road's stroke.
import assert from 'node:assert/strict';
import test from 'node:test';
import { strokes, type StrokeLine } from './strokes.js';

function line(...pts: number[]): StrokeLine {
  let length = 0;
  for (let k = 2; k < pts.length; k += 2) length += Math.hypot(pts[k]! - pts[k - 2]!, pts[k + 1]! - pts[k - 1]!);
  return { paths: [Float64Array.from(pts)], length };
}

const bend = (deg: number, len: number, from: [number, number]): [number, number] => [from[0] + len * Math.cos((deg * Math.PI) / 180), from[1] + len * Math.sin((deg * Math.PI) / 180)];

test('pieces of a road that continue one another are one stroke; turns, crossings and other groups are not', () => {
  const m3end = bend(20, 100, [200, 0]);
  const lines = [
    line(0, 0, 50, 0, 100, 0), // m1, with a vertex in between
    line(100, 0, 200, 0), // m2
    line(200, 0, ...m3end), // m3: a 20 degree bend at (200, 0)
    line(100, 0, 100, -80), // s1: meets the road where m1 and m2 end
    line(100, -80, 180, -80), // s2: 90 degrees off s1
    line(200, 0, 200, 60), // s3: meets the road where m2 and m3 end
    line(...m3end, ...bend(20, 150, m3end)), // straight on from m3, but a street
  ];
  const group = [0, 0, 0, 1, 1, 1, 1];
  const { stroke, strokeLength } = strokes(lines, group);
  assert.deepEqual([...stroke], [0, 0, 0, 3, 4, 5, 6]);
  for (const i of [0, 1, 2]) assert.ok(Math.abs(strokeLength[i]! - 300) < 1e-9, `the road is 300 m: ${strokeLength[i]}`);
  assert.deepEqual([...strokeLength.slice(3)].map((x) => Math.round(x)), [80, 80, 60, 150]);
  // With turns of up to 91 degrees allowed, s2 continues s1; s1 and s3 still meet the road at a T, not an end of theirs continued.
  assert.deepEqual([...strokes(lines, group, 91).stroke], [0, 0, 0, 3, 3, 5, 6]);
});

test('where three pieces of a road end at one point, the two most nearly straight pair up', () => {
  // Ends at (0,0): one from the west, one going east 10 degrees up, one going east 30 degrees down.
  const lines = [line(-100, 0, 0, 0), line(0, 0, ...bend(10, 100, [0, 0])), line(0, 0, ...bend(-30, 100, [0, 0]))];
  const { stroke } = strokes(lines, [0, 0, 0]);
  assert.deepEqual([...stroke], [0, 0, 2]);
});

test('a line\'s direction at an end is read some way along it, past a kink at the junction', () => {
  // The second piece starts with a 1 m jog at 60 degrees, then runs straight on east for 100 m.
  const lines = [line(-100, 0, 0, 0), line(0, 0, 0.5, 0.87, 100.5, 0.87)];
  assert.deepEqual([...strokes(lines, [0, 0]).stroke], [0, 0]);
});
