// Web map zoom levels as scale denominators.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { scaleAtZoom, zoomAtScale } from './zoom-levels.js';

const close = (a: number, b: number, tol: number, what = ''): void => assert.ok(Math.abs(a - b) <= tol, `${what} ${a} vs ${b}`);

describe('zoom levels', () => {
  test('zoom levels are the web map scale set', () => {
    close(scaleAtZoom(0), 559082264.0287178, 1e-6);
    close(zoomAtScale(scaleAtZoom(17.5)), 17.5, 1e-12);
  });
});
