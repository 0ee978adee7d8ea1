// Zooming about a point and interpolating cameras.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { cameraAround, groundAt, lerpCamera, zoomAboutPath } from './camera.js';
import { resolutionAtScale } from './view.js';

const close = (a: number, b: number, tol: number, what = ''): void => assert.ok(Math.abs(a - b) <= tol, `${what} ${a} vs ${b}`);

describe('camera: zoom about a point', () => {
  test('the ground point under an offset stays under it at every step', () => {
    const a = { x: 181282.7, y: 457031.1, scale: 3000 };
    const offset: [number, number] = [-150, 90];
    const g = groundAt(a, offset, 0.28);
    const path = zoomAboutPath(a, 750, offset, 0.28);
    for (const t of [0, 0.3, 0.7, 1]) {
      const c = path(t);
      const h = groundAt(c, offset, 0.28);
      close(Math.hypot(h[0] - g[0], h[1] - g[1]) / resolutionAtScale(c.scale, 0.28), 0, 1e-6);
    }
    close(path(1).scale, 750, 1e-9);
    assert.deepEqual(cameraAround(g, offset, 3000, 0.28).scale, 3000);
  });

  test('lerp is geometric in scale', () => {
    close(lerpCamera({ x: 0, y: 0, scale: 1000 }, { x: 10, y: 0, scale: 4000 }, 0.5).scale, 2000, 1e-9);
  });
});
