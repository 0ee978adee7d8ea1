// The map's one view owner, in Node: the first view fitted to the cube (what the options gave
// winning), the slice's z following the scale, snapped to the comparison scales or pinned, the
// listener told at once (with whether the slice moved), the movement events a gesture and a
// jump yield, the scale limits, and fitting a box to device pixels as `ssc slice --bbox` does.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { scaleAtZ, zAtScale } from '../../../format/scale.js';
import { makeView, testMeta as meta } from '../../../testing/map-view-fixture.js';
import { fitBbox } from '../geometry/view.js';

describe('MapView', () => {
  test('the first view fits the cube, keeping the centre or the scale the options gave', () => {
    const fitted = { x: 500, y: 250, scale: 4000 };
    const a = makeView();
    a.view.setMeta(meta, () => fitted);
    assert.deepEqual(a.view.camera, fitted);
    const b = makeView();
    b.view.place({ x: 10, y: 20 });
    b.view.setMeta(meta, () => fitted);
    assert.deepEqual(b.view.camera, { x: 10, y: 20, scale: 4000 });
    const c = makeView();
    c.view.place({ scale: 2500 });
    c.view.setMeta(meta, () => fitted);
    assert.deepEqual(c.view.camera, { x: 500, y: 250, scale: 2500 });
    assert.equal(c.view.pixelSizeMm, 0.25, "the cube's pixel size");
  });

  test('the slice follows the scale, snaps to the comparison scales, or stays pinned', () => {
    const { view, changes } = makeView();
    view.setMeta(meta, () => ({ x: 0, y: 0, scale: 3000 }));
    assert.equal(view.z(), zAtScale(meta, 3000));
    changes.length = 0;
    view.setLevels([1000, 4000]);
    assert.equal(view.z(), zAtScale(meta, 4000), '3000 is nearer 4000 than 1000 in log scale');
    assert.deepEqual(changes, [true], 'the slice moved');
    view.pinZ(7);
    assert.equal(view.z(), 7);
    assert.equal(view.zAt(123456), 7, 'pinned at every scale');
    assert.equal(view.surface().base, 7);
    view.pinZ(null);
    view.setLevels(null);
    assert.ok(Math.abs(scaleAtZ(meta, view.z()) - 3000) < 1e-6, 'following the scale again');
  });

  test('a gesture yields movestart, move and zoom, and end() closes it once; a jump is all of it', () => {
    const { view, events, changes } = makeView();
    view.setMeta(meta, () => ({ x: 0, y: 0, scale: 2000 }));
    changes.length = 0;
    view.set({ x: 5, y: 0, scale: 2000 });
    view.set({ x: 5, y: 0, scale: 3000 });
    assert.deepEqual(events, ['movestart', 'move', 'zoomstart', 'move', 'zoom']);
    assert.deepEqual(changes, [false, true], 'a pan leaves the slice where it is; a zoom moves it');
    assert.ok(view.isMoving);
    view.end();
    view.end();
    assert.deepEqual(events.slice(5), ['zoomend', 'moveend']);
    assert.ok(!view.isMoving);
    events.length = 0;
    view.jump({ x: 0, y: 0, scale: 2000 });
    assert.deepEqual(events, ['movestart', 'zoomstart', 'move', 'zoom', 'zoomend', 'moveend']);
  });

  test('the scale stays within the limits', async () => {
    const { view } = makeView();
    view.setMeta(meta, () => ({ x: 0, y: 0, scale: 2000 }));
    view.setLimits({ minScale: 500, maxScale: 8000 });
    view.jump({ x: 0, y: 0, scale: 100 });
    assert.equal(view.camera.scale, 500);
    // Reduced motion: an animation jumps to its end at once.
    assert.equal(await view.zoomAbout(1e6, [0, 0], { durationMs: 300 }), true);
    assert.equal(view.camera.scale, 8000);
  });

  test('a new minimum scale brings the view within it at once, with movement events', () => {
    const { view, events } = makeView();
    view.setMeta(meta, () => ({ x: 0, y: 0, scale: 2000 }));
    view.setLimits({ minScale: 3000 });
    assert.equal(view.camera.scale, 3000);
    assert.deepEqual(events, ['movestart', 'zoomstart', 'move', 'zoom', 'zoomend', 'moveend']);
    events.length = 0;
    view.setLimits({ maxScale: 5000 });
    assert.deepEqual(events, [], 'the view was within: nothing moves');
    assert.throws(() => view.setLimits({ maxScale: 1000 }), /maxScale \(1000\) must be at least minScale \(3000\)/);
    assert.equal(view.limits.maxScale, 5000, 'a refused change leaves the limits as they were');
  });

  test('with maxBounds no movement leaves the box: pans, zooms and animations alike', async () => {
    const { view } = makeView();
    view.setMeta(meta, () => ({ x: 500, y: 250, scale: 4000 }));
    view.setLimits({ maxBounds: [0, 0, 1000, 500] });
    // The box fills the 400 x 200 px view at 2.5 units a px: 1:10000.
    view.jump({ x: 500, y: 250, scale: 1e6 });
    assert.deepEqual(view.camera, { x: 500, y: 250, scale: 10000 });
    view.set({ x: -1e6, y: 1e6, scale: 4000 });
    view.end();
    assert.deepEqual(view.camera, { x: 200, y: 400, scale: 4000 }, 'the corner of the box at the corner of the view');
    assert.equal(await view.zoomAbout(1e9, [150, 50], { durationMs: 300 }), true);
    assert.deepEqual(view.camera, { x: 500, y: 250, scale: 10000 });
    assert.equal(view.clamp(1e6), 10000, 'zoom steps aim at the largest scale the box allows');
    view.setLimits({ maxBounds: null });
    assert.equal(view.clamp(1e6), 1e6);
  });

  test('fitting a box to device pixels is the view `ssc slice --bbox` shows', () => {
    const { view } = makeView();
    view.setMeta(meta, () => ({ x: 0, y: 0, scale: 2000 }));
    const bbox: [number, number, number, number] = [100, 50, 900, 450];
    for (const ratio of [1, 2]) {
      const c = view.fitCamera(bbox, 640 * ratio, 480 * ratio, ratio);
      const g = view.geometry(640 * ratio, 480 * ratio, ratio, c);
      const want = fitBbox(bbox, 640 * ratio, 480 * ratio);
      assert.ok(Math.abs(g.resolution - want.resolution) < 1e-12 && g.centerX === want.centerX && g.centerY === want.centerY, `ratio ${ratio}`);
    }
    // Padding (device px) leaves that much room on the tighter side.
    const padded = view.geometry(640, 480, 1, view.fitCamera(bbox, 640, 480, 1, 20));
    assert.ok(Math.abs(padded.resolution - 800 / 600) < 1e-12);
  });
});
