// MapLibre's zoom levels as scale denominators.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { scaleAtZoom, zoomAtScale } from './zoom-levels.js';

const close = (a: number, b: number, tol: number, what = ''): void => assert.ok(Math.abs(a - b) <= tol, `${what} ${a} vs ${b}`);

describe('zoom levels', () => {
  test('zoom 0 at the equator is one 512-px tile around the earth', () => {
    // 40075016.686 m over 512 px is 78271.517 m a pixel; with 0.28 mm pixels 1:279541132.
    close(scaleAtZoom(0, 0, 0.28), 40075016.686 / 512 / 0.00028, 1e-3);
  });

  test('at 60 degrees a pixel covers half the ground it covers at the equator, one zoom level', () => {
    close(scaleAtZoom(15, 60, 0.28), scaleAtZoom(15, 0, 0.28) / 2, 1e-6);
    close(zoomAtScale(scaleAtZoom(15, 0, 0.28), 60, 0.28), 14, 1e-12);
  });

  test('zoom and scale are inverse at any latitude and pixel size', () => {
    for (const lat of [-70, 0, 52.1, 80]) for (const mm of [0.25, 0.28]) close(zoomAtScale(scaleAtZoom(17.5, lat, mm), lat, mm), 17.5, 1e-12, `${lat} ${mm}`);
  });
});
