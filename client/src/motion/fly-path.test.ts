// The flight path: van Wijk and Nuij's formulas, worked out here, not read back.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { interpolateZoom } from 'd3-interpolate';
import { flyPath, zoomPath } from './fly-path.js';
import { resolutionAtScale } from '../geometry/view.js';

const close = (a: number, b: number, tol: number, what = ''): void => assert.ok(Math.abs(a - b) <= tol, `${what} ${a} vs ${b}`);

describe('the flight path (van Wijk and Nuij, rho 1.42)', () => {
  const mm = 0.28, width = 640;
  const w = (scale: number): number => resolutionAtScale(scale, mm) * width;

  test('it starts and ends exactly at the two cameras', () => {
    const a = { x: 181000, y: 456900, scale: 1000 }, b = { x: 181400, y: 457200, scale: 1500 };
    const p = flyPath(a, b, width, mm);
    assert.deepEqual(p.at(0), a);
    assert.deepEqual(p.at(1), b);
    const s = p.samples(4);
    assert.equal(s.length, 5);
    assert.deepEqual(s[4], b);
  });

  test('a pan at one scale has length 2 asinh(rho^2 u / 2w) / rho, and zooms out on the way', () => {
    const rho = 1.42, u = 4000, scale = 1000;
    const a = { x: 0, y: 0, scale }, b = { x: u, y: 0, scale };
    const p = flyPath(a, b, width, mm, rho);
    const S = (2 * Math.asinh((rho * rho * u) / (2 * w(scale)))) / rho;
    close(p.durationMs(1), 1000 * S, 1e-6);
    close(p.durationMs(1.2), (1000 * S) / 1.2, 1e-6);
    const mid = p.at(0.5);
    close(mid.x, u / 2, 1e-6, 'symmetric');
    // At the middle the width is w / cosh(r0), r0 = -asinh(rho^2 u / 2w): zoomed out by cosh(...).
    close(mid.scale / scale, Math.cosh(Math.asinh((rho * rho * u) / (2 * w(scale)))), 1e-6);
  });

  test('a zoom in place has length |ln(w1 / w0)| / rho', () => {
    const p = flyPath({ x: 5, y: 5, scale: 1000 }, { x: 5, y: 5, scale: 8000 }, width, mm, 1.42);
    close(p.durationMs(1), (1000 * Math.log(8)) / 1.42, 1e-6);
    close(p.at(0.5).scale, Math.sqrt(8) * 1000, 1e-6, 'geometric in scale');
  });

  test("a pan with a zoom follows d3-interpolate's interpolateZoom, and so does a zoom in place", () => {
    // @types/d3-interpolate puts rho() on the interpolator; d3 has it on the factory.
    const d3 = (interpolateZoom as typeof interpolateZoom & { rho(r: number): typeof interpolateZoom }).rho(1.42);
    const cases: [number, number, number, number, number, number][] = [
      [181000, 456900, 230, 183500, 455000, 4100],
      [0, 0, 5000, -300, 40, 90],
      [10, 20, 300, 10, 20, 2400],
    ];
    for (const [x0, y0, w0, x1, y1, w1] of cases) {
      const ours = zoomPath(x0, y0, w0, x1, y1, w1, 1.42);
      const theirs = d3([x0, y0, w0], [x1, y1, w1]);
      close(ours.length, (theirs.duration * Math.SQRT2) / (1000 * 1.42), 1e-9, 'length');
      for (let i = 0; i <= 20; i++) {
        const [x, y, wd] = ours.at(i / 20), [ex, ey, ew] = theirs(i / 20);
        close(x, ex, 1e-6 * Math.max(1, Math.abs(ex)), `x at ${i / 20}`);
        close(y, ey, 1e-6 * Math.max(1, Math.abs(ey)), `y at ${i / 20}`);
        close(wd, ew, 1e-9 * ew, `width at ${i / 20}`);
      }
    }
  });
});
