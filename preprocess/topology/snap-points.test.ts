// Snapping to the precision grid, and one id per distinct point.
import test from 'node:test';
import assert from 'node:assert/strict';
import { gridSnapper, snapPoints } from './snap-points.js';

test('a grid of a power of ten rounds through the decimal text, so values on the grid stay bit-identical', () => {
  const snap = gridSnapper(0.001);
  assert.equal(snap(181477.123), 181477.123);
  assert.equal(snap(1.23456), 1.235);
  assert.equal(snap(-0.0004), -0);
  assert.equal(gridSnapper(0.5)(1.3), 1.5);
  assert.equal(gridSnapper(0)(1.23456789), 1.23456789, 'precision 0: no grid');
});

test('points shared by neighbours get one id; repeated and closing points are dropped and counted', () => {
  const repairs = { closedRings: 0, duplicatePoints: 0, reorientedRings: 0, tJunctions: 0, snappedPoints: 0, mergedPoints: 0, spikes: 0, slivers: 0 };
  const feature = (index: number, ring: number[]): { ref: { index: number; id: null }; properties: Record<string, unknown>; polygons: Float64Array[][] } =>
    ({ ref: { index, id: null }, properties: {}, polygons: [[Float64Array.from(ring)]] });
  const { rings, xs, ys } = snapPoints([
    // Closed (the first point again), and (1,0) twice.
    feature(0, [0, 0, 1, 0, 1, 0, 1, 1, 0, 1, 0, 0]),
    // Shares (1,0) and (1,1); (2,0.0001) snaps to (2,0).
    feature(1, [1, 0, 2, 0.0001, 2, 1, 1, 1]),
  ], 0.001, repairs);
  assert.deepEqual(rings.map((r) => [r.face, r.outer, [...r.ids]]), [[1, true, [0, 1, 2, 3]], [2, true, [1, 4, 5, 2]]]);
  assert.deepEqual([...xs], [0, 1, 1, 0, 2, 2]);
  assert.deepEqual([...ys], [0, 0, 1, 1, 0, 1]);
  assert.equal(repairs.duplicatePoints, 2);
  assert.equal(repairs.snappedPoints, 1);
});
