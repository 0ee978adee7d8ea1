// The view geometry the map and the tests share: fitting a box, pixels to ground and back.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { fitBbox, groundToPixel, pixelToGround, viewBbox } from './view.js';

describe('view geometry', () => {
  test('fits a box with square pixels and maps pixel centres both ways', () => {
    const v = fitBbox([181000, 456800, 181400, 457200], 640, 480);
    assert.equal(v.resolution, 400 / 480);
    const b = viewBbox(v);
    assert.ok(Math.abs(b[1] - 456800) < 1e-9 && Math.abs(b[3] - 457200) < 1e-9);
    assert.ok(Math.abs(b[2] - b[0] - 640 * v.resolution) < 1e-9);
    const [x, y] = pixelToGround(v, 0.5, 0.5);
    assert.ok(Math.abs(x - (b[0] + 0.5 * v.resolution)) < 1e-9 && Math.abs(y - (b[3] - 0.5 * v.resolution)) < 1e-9);
    const [px, py] = groundToPixel(v, x, y);
    assert.ok(Math.abs(px - 0.5) < 1e-9 && Math.abs(py - 0.5) < 1e-9);
  });
});
