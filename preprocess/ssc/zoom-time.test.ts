// Zoom time against the scale itself: u is the log of the scale denominator (up to a constant),
// so equal steps of u are equal zoom factors, and z(u) inverts u(z).
import test from 'node:test';
import assert from 'node:assert/strict';
import { scaleAtZ, type ScaleInfo } from '../../format/scale.js';
import { ZoomTime } from './zoom-time.js';

// 1000 faces at 1:1,000, one fewer per step up to step 900, then 100 faces for 50 steps (flat).
const info: ScaleInfo = { baseScale: 1000, baseFaces: 1000, scaleTable: [[0, 1000], [900, 100], [950, 100]], zMax: 950 };
const time = new ZoomTime(info);

test('u grows as the log of the scale: each x2 in scale is the same step of u', () => {
  // Scale doubles when the faces alive fall to a quarter: 1000 -> 250 at step 750.
  assert.ok(Math.abs(time.u(750) - time.u(0) - Math.log(2)) < 1e-12);
  for (const z of [10, 200, 500, 880]) {
    assert.ok(Math.abs(time.u(z) - time.u(0) - Math.log(scaleAtZ(info, z) / scaleAtZ(info, 0))) < 1e-12, `z ${z}`);
  }
});

test('z(u) inverts u(z), also where the number of faces alive stays the same', () => {
  for (const z of [-3, 0, 0.5, 123.25, 750, 899.9, 900, 920, 950, 960]) {
    assert.ok(Math.abs(time.z(time.u(z)) - z) < 1e-9, `z ${z}`);
  }
  // Strictly increasing across the flat stretch too.
  assert.ok(time.u(920) > time.u(910));
});

test('a frame of a geometric zoom spans more z at the start of a transition than at its end', () => {
  // Two equal steps of u (half a zoom level each): the first spans twice the z of the second
  // (faces fall 2x per half level, so the second half of the level has half as many to lose).
  const z0 = 0, zMid = time.z(time.u(0) + Math.log(2) / 2), z1 = time.z(time.u(0) + Math.log(2));
  assert.ok(Math.abs((zMid - z0) / (z1 - zMid) - 2) < 1e-9, `${zMid - z0} vs ${z1 - zMid}`);
});
