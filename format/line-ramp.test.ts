// A line's width share over z, on scales that double each step (1:1,000 at z 0): it grows over
// the first half zoom level, shrinks over the last, and does neither at the cube's floor or top.
import assert from 'node:assert/strict';
import test from 'node:test';
import { lineRamp, lineWidthShare, rampShare, ruleRamp } from './line-ramp.js';
import { scaleAtZ, type ScaleInfo } from './scale.js';

const info: ScaleInfo = { baseScale: 1000, baseFaces: 4 ** 10, zMax: 10, scaleTable: Array.from({ length: 11 }, (_, z): [number, number] => [z, 4 ** (10 - z)]) };
const near = (a: number, b: number, what: string): void => assert.ok(Math.abs(a - b) < 1e-9, `${what}: ${a} against ${b}`);

test('a line grows to full width half a zoom level after it appears and shrinks over the half before it goes', () => {
  const r = lineRamp(info, 2, 7);
  // Half a zoom level: the scale times sqrt 2, at both ends.
  near(scaleAtZ(info, r.z0Full) / scaleAtZ(info, 2), Math.SQRT2, 'in');
  near(scaleAtZ(info, 7) / scaleAtZ(info, r.z1Full), Math.SQRT2, 'out');
  assert.equal(rampShare(r, 1.99), 0);
  assert.equal(rampShare(r, 2), 0);
  near(rampShare(r, (2 + r.z0Full) / 2), 0.5, 'half-way in');
  assert.equal(rampShare(r, r.z0Full), 1);
  assert.equal(rampShare(r, 5), 1);
  near(rampShare(r, (r.z1Full + 7) / 2), 0.5, 'half-way out');
  assert.equal(rampShare(r, 7), 0, 'gone at its end');
});

test('at the floor and the top of the cube, and without a rule bound, there is no ramp', () => {
  const r = lineRamp(info, 0, 10);
  assert.deepEqual([r.z0Full, r.z1Full], [0, 10]);
  assert.equal(rampShare(r, 0), 1);
  assert.equal(rampShare(r, 9.999), 1);
  const open = ruleRamp(info, {});
  assert.equal(rampShare(open, -5), 1);
  assert.equal(rampShare(open, 50), 1);
});

test('a line shorter than a zoom level never reaches full width; its share is the smaller of its own and its rule\'s', () => {
  const r = lineRamp(info, 3, 3.5);
  assert.ok(r.z0Full <= 3.5 && r.z1Full >= 3);
  for (let z = 3; z < 3.5; z += 0.01) assert.ok(rampShare(r, z) < 1, `z ${z}`);
  // A rule ending at 1:16,000 (z 4): the line of 2..7 shrinks with the rule, and is gone from z 4.
  const rule = ruleRamp(info, { maxScale: 16000 });
  near(rule.z1, 4, 'the rule ends at z 4');
  const line = lineRamp(info, 2, 7);
  assert.equal(lineWidthShare(line, rule, 3), 1);
  near(lineWidthShare(line, rule, (rule.z1Full + 4) / 2), 0.5, 'half-way out of the rule');
  assert.equal(lineWidthShare(line, rule, 4), 0);
});
