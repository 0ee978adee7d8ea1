// The view limits, against hand-worked views: 0.25 mm pixels, so at 1:4000 a CSS pixel is 1 m
// of ground and a 400 x 200 px view is 400 x 200 m.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { checkViewLimits, constrainCamera, limitScale, type ViewLimits } from './view-limits.js';

const PX_MM = 0.25;
const SIZE: [number, number] = [400, 200];
const free: ViewLimits = { minScale: 500, maxScale: 64000, maxBounds: null };
/** 1000 x 1000 m: it fills the 400 px width at 2.5 m a pixel, 1:10000. */
const boxed: ViewLimits = { ...free, maxBounds: [0, 0, 1000, 1000] };

describe('view limits', () => {
  test('the scale stays between minScale and maxScale', () => {
    assert.equal(limitScale(100, free, SIZE, PX_MM), 500);
    assert.equal(limitScale(1e6, free, SIZE, PX_MM), 64000);
    assert.equal(limitScale(3000, free, SIZE, PX_MM), 3000);
  });

  test('with maxBounds the view cannot zoom out past the scale at which the box fills it', () => {
    assert.equal(limitScale(1e6, boxed, SIZE, PX_MM), 10000);
    const c = constrainCamera({ x: 500, y: 500, scale: 50000 }, boxed, SIZE, PX_MM);
    assert.deepEqual(c, { x: 500, y: 500, scale: 10000 });
  });

  test('the visible area is moved back inside maxBounds', () => {
    // 1:4000: the view is 400 x 200 m, so its centre stays within [200, 800] x [100, 900].
    assert.deepEqual(constrainCamera({ x: -50, y: 2000, scale: 4000 }, boxed, SIZE, PX_MM), { x: 200, y: 900, scale: 4000 });
    assert.deepEqual(constrainCamera({ x: 999, y: 0, scale: 4000 }, boxed, SIZE, PX_MM), { x: 800, y: 100, scale: 4000 });
    assert.deepEqual(constrainCamera({ x: 300, y: 600, scale: 4000 }, boxed, SIZE, PX_MM), { x: 300, y: 600, scale: 4000 }, 'inside: unchanged');
  });

  test('a box smaller than the view at minScale centres the view on it', () => {
    // At 1:500 the view is 50 x 25 m; the box is 10 x 10 m.
    const tiny: ViewLimits = { ...free, maxBounds: [100, 100, 110, 110] };
    assert.deepEqual(constrainCamera({ x: 0, y: 0, scale: 3000 }, tiny, SIZE, PX_MM), { x: 105, y: 105, scale: 500 });
  });

  test('bad limits are refused, naming what is wrong', () => {
    assert.throws(() => checkViewLimits({ ...free, minScale: 0 }), /minScale must be a finite number > 0, not 0/);
    assert.throws(() => checkViewLimits({ ...free, maxScale: 100 }), /maxScale \(100\) must be at least minScale \(500\)/);
    assert.throws(() => checkViewLimits({ ...free, maxBounds: [0, 0, Number.NaN, 1] }), /maxBounds must be \[x0, y0, x1, y1\] of finite numbers/);
    assert.throws(() => checkViewLimits({ ...free, maxBounds: [5, 0, 1, 1] }), /maxBounds must have x0 < x1 and y0 < y1, not \[5,0,1,1\]/);
    assert.doesNotThrow(() => checkViewLimits({ ...boxed, maxScale: Infinity }));
  });
});
