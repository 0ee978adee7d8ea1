import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { chooseGrid, coarsestGrid, cubeGridExponent, defaultPrecision, inputPrecision } from './position-grid.js';

describe('cubeGridExponent', () => {
  test('a 256th of a base pixel, rounded down to a power of two', () => {
    // 1:1,000 at 0.28 mm: pixels of 0.28 m, a 256th is 1.09 mm; 2^-10 m = 0.98 mm, 2^-9 = 1.95 mm.
    assert.equal(cubeGridExponent(1000, 0.28), -10);
    // 1:50,000: 14 m pixels, 54.7 mm; 2^-5 m = 31 mm, 2^-4 = 62 mm.
    assert.equal(cubeGridExponent(50000, 0.28), -5);
  });
  test('exactly a power of two is that power', () => {
    // 256 * 2^-8 m = 1 m pixels: 1:1,000 at 1 mm.
    assert.equal(cubeGridExponent(1000, 1), -8);
    assert.equal(cubeGridExponent(1000, 2 - 1e-9), -8);
  });
  test('never coarser than one unit, so that whole-unit origins lie on it', () => {
    assert.equal(cubeGridExponent(10_000_000, 0.28), 0);
  });
  test('nonsense in, an error out', () => {
    assert.throws(() => cubeGridExponent(0, 0.28), /no position grid for base scale 0/);
    assert.throws(() => cubeGridExponent(1000, Number.NaN), /pixel size NaN mm/);
  });
  test('chooseGrid keeps the grid, or a finer one of the three below it, that encodes smallest; the coarser on a tie', () => {
    const sizes: Record<number, number> = { [-5]: 185, [-6]: 170, [-7]: 166, [-8]: 158, [-9]: 100 };
    const tried: number[] = [];
    assert.equal(chooseGrid(-5, (e) => (tried.push(e), sizes[e]!)), -8);
    assert.deepEqual(tried, [-5, -6, -7, -8], 'never finer than three below');
    assert.equal(chooseGrid(-5, (e) => (e === -5 || e === -7 ? 10 : 20)), -5);
    assert.equal(chooseGrid(-10, (e) => 50 + e), -13);
  });
});

describe('defaultPrecision and coarsestGrid', () => {
  test('the default snapping grid is a 32nd of a base pixel, rounded down to a power of two, at most 1 unit', () => {
    // 1:1,000: 0.28 m / 32 = 8.75 mm; 2^-7 m = 7.8 mm. 1:50,000: 14 m / 32 = 0.44 m; 2^-2 m.
    assert.equal(defaultPrecision(1000, 0.28), 2 ** -7);
    assert.equal(defaultPrecision(50000, 0.28), 0.25);
    assert.equal(defaultPrecision(150000, 0.28), 1);
    assert.throws(() => defaultPrecision(0, 0.28), /no position grid for base scale 0/);
  });
  test('an input on a coarser grid of its own keeps it, up to an 8th of a base pixel and 1 unit', () => {
    const ring = (...xy: number[]): Float64Array => Float64Array.from(xy);
    // 1:50,000: a pixel is 14 m, an 8th 1.75 m, so whole metres (a raster's corners) stay 1 m.
    const metres = [ring(304205, 4154086, 304237, 4154055), ring(304300, 4154086)];
    assert.equal(inputPrecision(50000, 0.28, metres), 1);
    // Half metres somewhere: 0.5; a coordinate off every power-of-two grid: the default.
    assert.equal(inputPrecision(50000, 0.28, [...metres, ring(304205.5, 4154055)]), 0.5);
    assert.equal(inputPrecision(50000, 0.28, [...metres, ring(304205.1, 4154055)]), defaultPrecision(50000, 0.28));
    // 1:1,000: an 8th of a pixel is 3.5 cm, so whole metres give 2^-5 m; millimetres the default 2^-7.
    assert.equal(inputPrecision(1000, 0.28, metres), 2 ** -5);
    assert.equal(inputPrecision(1000, 0.28, [ring(181082.695, 456831.109)]), 2 ** -7);
    // 1:150,000: the default is 1 unit already, and no grid is coarser than that.
    assert.equal(inputPrecision(150000, 0.28, [ring(2609050, 1243550)]), 1);
    // No coordinates: nothing to keep off the coarsest grid allowed.
    assert.equal(inputPrecision(50000, 0.28, []), 1);
  });
  test('the chunks may be as coarse as a power-of-two precision, never coarser than 1 unit', () => {
    assert.equal(coarsestGrid(1000, 0.28, 2 ** -7), -7);
    assert.equal(coarsestGrid(1000, 0.28, 4), 0);
  });
  test('a decimal precision, one finer than the cube grid, or none keeps the cube grid', () => {
    assert.equal(coarsestGrid(1000, 0.28, 0.001), -10);
    assert.equal(coarsestGrid(1000, 0.28, 2 ** -12), -10);
    assert.equal(coarsestGrid(1000, 0.28, 0), -10);
  });
});
