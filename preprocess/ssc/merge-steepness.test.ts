// The steepness variation of tilted surfaces on hand-made triangles with slopes worked out by
// hand, and on the three rectangles' smooth merges (linear ramps: one slope each).
import test from 'node:test';
import assert from 'node:assert/strict';
import { fixtureTgap, rect } from '../../testing/planar-fixtures.js';
import { mergeTriangles } from './merge-surface.js';
import { slopeVariation, triangleSlope } from './merge-steepness.js';
import { buildSurfaces, Surfaces } from './surfaces.js';

// Unit squares [0,1] x [0,1] (vertices 0..3) and [1,2] x [0,1] (vertices 1, 4, 5, 2).
const xs = Float64Array.of(0, 1, 1, 0, 2, 2);
const ys = Float64Array.of(0, 0, 1, 1, 0, 1);

test('triangleSlope: |grad z| and area of a plane through three corners', () => {
  const s = new Surfaces();
  // z = 3x + 4y: |grad z| = 5.
  s.addTilted(0, 1, 2, 0, 3, 7, 2, 1, 'p');
  assert.deepEqual(triangleSlope(s, 0, xs, ys), { slope: 5, area: 0.5 });
  s.add(0, 1, 2, 4, 2, 1);
  assert.deepEqual(triangleSlope(s, 1, xs, ys), { slope: 0, area: 0.5 });
});

test('slopeVariation: one slope is 0; slopes 1 and 3 on equal areas 0.5; area weighs', () => {
  const s = new Surfaces();
  // Square 1 at z = x (slope 1), square 2 at z = 1 + 3 (x - 1) (slope 3).
  s.addTilted(0, 1, 2, 0, 1, 1, 2, 1, 'p');
  s.addTilted(0, 2, 3, 0, 1, 0, 2, 1, 'p');
  s.addTilted(1, 4, 5, 1, 4, 4, 2, 1, 'p');
  s.addTilted(1, 5, 2, 1, 4, 1, 2, 1, 'p');
  assert.equal(slopeVariation(s, [0, 1], xs, ys), 0);
  // Mean 2, standard deviation 1.
  assert.ok(Math.abs(slopeVariation(s, [0, 1, 2, 3], xs, ys) - 0.5) < 1e-12);
  // Three triangles of slope 1 or 3 by area 1/2 each: slopes 1, 1, 3 -> mean 5/3, sd sqrt(8)/3.
  assert.ok(Math.abs(slopeVariation(s, [0, 1, 2], xs, ys) - Math.sqrt(8) / 5) < 1e-12);
  // A flat triangle in the set counts as slope 0: 1 and 0 -> mean 1/2, sd 1/2.
  s.add(0, 2, 3, 0.5, 2, 1);
  assert.ok(Math.abs(slopeVariation(s, [0, 4], xs, ys) - 1) < 1e-12);
  assert.ok(Number.isNaN(slopeVariation(s, [4], xs, ys)), 'no slope at all');
});

test('the smooth merges of three rectangles are linear ramps: variation 0', () => {
  const t = fixtureTgap([{ cls: 'a', rings: [rect(0, 0, 4, 4)] }, { cls: 'a', rings: [rect(4, 0, 6, 4)] }, { cls: 'a', rings: [rect(6, 0, 10, 4)] }], ['a']);
  const { surfaces: s, transitions } = buildSurfaces(t, { smooth: true });
  const cvs = mergeTriangles(s, transitions, t).map((tris) => slopeVariation(s, tris, s.xs, s.ys));
  assert.equal(cvs.length, 2);
  for (const cv of cvs) assert.ok(Math.abs(cv) < 1e-9, `variation ${cv}`);
});
