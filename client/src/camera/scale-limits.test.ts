// The scale limits as the API sets them, on a MapView in Node: none before the cube is known,
// its defaults after, a given limit winning over its default, null going back to it, and a
// change that would cross the two refused and undone.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { makeView, testMeta } from '../../../testing/map-view-fixture.js';
import { ScaleLimits } from './scale-limits.js';

describe('ScaleLimits', () => {
  test('given limits win over the defaults; null goes back to the default', () => {
    const { view } = makeView();
    const limits = new ScaleLimits(view, undefined, 50000);
    assert.deepEqual([view.limits.minScale, view.limits.maxScale], [1, 50000], 'before the cube: only what was given');
    view.setMeta(testMeta, () => ({ x: 0, y: 0, scale: 3000 }));
    limits.setDefaults(250, 80000);
    assert.deepEqual([view.limits.minScale, view.limits.maxScale], [250, 50000]);
    limits.set('max', null);
    assert.equal(view.limits.maxScale, 80000);
    limits.set('min', 2000);
    limits.set('min', null);
    assert.equal(view.limits.minScale, 250);
  });

  test('a default minimum above a given maximum gives way to it', () => {
    const { view } = makeView();
    const limits = new ScaleLimits(view, undefined, 100);
    limits.setDefaults(250, 80000);
    assert.deepEqual([view.limits.minScale, view.limits.maxScale], [100, 100]);
  });

  test('limits that would cross are refused, and nothing changes', () => {
    const { view } = makeView();
    assert.throws(() => new ScaleLimits(view, 5000, 1000), /maxScale \(1000\) must be at least minScale \(5000\)/);
    const limits = new ScaleLimits(view, 500, 1000);
    assert.throws(() => limits.set('min', 2000), /maxScale \(1000\) must be at least minScale \(2000\)/);
    limits.setDefaults(250, 80000);
    assert.deepEqual([view.limits.minScale, view.limits.maxScale], [500, 1000], 'the refused minimum was not kept');
  });
});
