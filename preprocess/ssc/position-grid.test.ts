import assert from 'node:assert/strict';
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { describe, test } from 'node:test';
import { chooseGrid, coarsestGrid, cubeGridExponent, defaultPrecision, pointGrid } from './position-grid.js';
import { generalizeFile } from '../pipeline.js';

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
  test('points on a coarser grid of their own keep it, up to an 8th of a base pixel and 1 unit', () => {
    const ring = (...xy: number[]): Float64Array => Float64Array.from(xy);
    // 1:50,000: a pixel is 14 m, an 8th 1.75 m, so whole metres (a raster's corners) keep 1 m.
    const metres = [ring(304205, 4154086, 304237, 4154055), ring(-304300, 4154086)];
    assert.equal(pointGrid(50000, 0.28, metres), 1);
    // Half metres somewhere, negative too: 0.5. A coordinate off every grid down to the default
    // precision (0.25 m), or not finite: none.
    assert.equal(pointGrid(50000, 0.28, [...metres, ring(-304205.5, 4154055)]), 0.5);
    assert.equal(pointGrid(50000, 0.28, [...metres, ring(304205.25, 4154055)]), null);
    assert.equal(pointGrid(50000, 0.28, [...metres, ring(304205.1, 4154055)]), null);
    assert.equal(pointGrid(50000, 0.28, [...metres, ring(NaN, 4154055)]), null);
    assert.equal(pointGrid(50000, 0.28, [...metres, ring(Infinity, 4154055)]), null);
    // 1:1,000: an 8th of a pixel is 3.5 cm, so whole metres give 2^-5 m; millimetres none.
    assert.equal(pointGrid(1000, 0.28, metres), 2 ** -5);
    assert.equal(pointGrid(1000, 0.28, [ring(181082.695, 456831.109)]), null);
    // 1:150,000: the default precision is 1 unit already, and no grid is coarser than that.
    assert.equal(pointGrid(150000, 0.28, [ring(2609050, 1243550)]), null);
  });
  test('whole metres at 1:50,000 are snapped at the default precision and keep 1 m for the points the build makes', async (t) => {
    const dir = mkdtempSync(path.join(tmpdir(), 'ssc-grid-'));
    t.after(() => rmSync(dir, { recursive: true, force: true }));
    // Three squares of 60 m side by side; the middle one has corners 1 m apart on its top, and
    // a strip 1 m wide (3 x 60 m) lies along the bottom of all three. With the precision, the
    // topology's merge distance, at 1 m those corners were one point and the strip a part too
    // narrow to keep.
    const sq = (x0: number, top: number[][] = []): number[][] => [[x0, 1], [x0 + 60, 1], [x0 + 60, 61], ...top, [x0, 61], [x0, 1]];
    const feature = (ring: number[][], cls: string): unknown => ({ type: 'Feature', properties: { cls }, geometry: { type: 'Polygon', coordinates: [ring] } });
    const input = path.join(dir, 'metres.geojson');
    writeFileSync(input, JSON.stringify({
      type: 'FeatureCollection',
      features: [
        feature(sq(0), 'a'), feature(sq(60, [[90, 61], [89, 61]]), 'b'), feature(sq(120), 'a'),
        feature([[0, 0], [180, 0], [180, 1], [120, 1], [60, 1], [0, 1], [0, 0]], 'c'),
      ],
    }));
    const { tgap, report } = await generalizeFile(input, { classProperty: 'cls', baseScale: 50000, crs: 'EPSG:28992' });
    assert.equal(tgap.meta.options.precision, 0.25, 'snapped at a 32nd of a pixel, as before');
    assert.equal(tgap.meta.options.grid, 1, 'every point on whole metres');
    assert.equal(report.topology.repairs.mergedPoints, 0);
    assert.equal(report.topology.repairs.slivers, 0);
    assert.equal(tgap.meta.baseFaces, 4, 'the strip kept');
    // The top of the middle square keeps both corners 1 m apart.
    const xs = new Set<number>();
    tgap.ys.forEach((y, v) => {
      if (y === 61) xs.add(tgap.xs[v]!);
    });
    assert.ok(xs.has(89) && xs.has(90), `corners at x 89 and 90 on the top (${[...xs].sort((a, b) => a - b).join(', ')})`);
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
