// Steps and scales: a constant number of faces per map area, St = Sb sqrt(Nb / Nt), on a
// hand-made cube of 100 faces at 1:1000 that loses one face a step, then stops at 10.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { facesAliveAt, scaleAtZ, scaleKnots, scaleOfFaces, zAtScale, type ScaleInfo } from './scale.js';

const close = (a: number, b: number, eps = 1e-9): void => assert.ok(Math.abs(a - b) <= eps * Math.max(1, Math.abs(b)), `${a} != ${b}`);

// 100 faces, one merge a step until 10 remain at step 90; steps 90..95 change nothing.
const facesAlive = Array.from({ length: 96 }, (_, s) => Math.max(10, 100 - s));
const info: ScaleInfo = { baseScale: 1000, baseFaces: 100, scaleTable: scaleKnots(facesAlive), zMax: 95 };

describe('steps and scales', () => {
  test('the scale table keeps only the knots where the slope changes', () => {
    assert.deepEqual(info.scaleTable, [[0, 100], [90, 10], [95, 10]]);
    assert.deepEqual(scaleKnots([]), [[0, 1]]);
    assert.deepEqual(scaleKnots([7]), [[0, 7]]);
  });

  test('a quarter of the faces shows at twice the scale denominator', () => {
    assert.equal(scaleOfFaces(1000, 100, 25), 2000);
    assert.equal(scaleOfFaces(1000, 100, 100), 1000);
    // Never more than the base faces' worth of division by zero: one face is the floor.
    assert.equal(scaleOfFaces(1000, 100, 0), 10000);
  });

  test('z and scale are each other\'s inverse inside the cube, interpolated between knots', () => {
    close(facesAliveAt(info, 0), 100);
    close(facesAliveAt(info, 75), 25);
    close(facesAliveAt(info, 74.5), 25.5);
    close(scaleAtZ(info, 75), 2000);
    for (const z of [0, 1, 12.25, 50, 75, 89.9]) close(zAtScale(info, scaleAtZ(info, z)), z, 1e-9);
  });

  test('scales beyond the cube clamp to its ends', () => {
    assert.equal(zAtScale(info, 10), 0, 'more detail than the base: the floor');
    // Coarser than the cube can show: its top.
    assert.equal(zAtScale(info, 1e6), 95);
    close(scaleAtZ(info, 95), scaleOfFaces(1000, 100, 10));
  });
});
