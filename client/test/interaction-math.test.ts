// Unit tests of the interaction's pure math, in Node: wheel classification and wheel zoom,
// pan inertia, the flight path, zoom about a point, the easing that continues a zoom, the
// comparison mode's scales, the scale bar and the URL hash. Expectations are worked out here
// from the definitions (MapLibre's numbers, van Wijk and Nuij's formulas), not read back.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { cameraAround, groundAt, lerpCamera, zoomAboutPath } from '../src/shared/camera.js';
import { discreteLevels, levelFor } from '../src/shared/discrete-scales.js';
import { continuingEasing, easeInOut, easingSpeed, inertiaEasing } from '../src/shared/easing.js';
import { flyPath } from '../src/shared/fly-path.js';
import { formatHash, parseHash } from '../src/shared/hash-text.js';
import { InertiaBuffer, panInertia, PAN_INERTIA } from '../src/shared/inertia.js';
import { formatScale, scaleBarLength } from '../src/shared/scale-bar-length.js';
import { resolutionAtScale } from '../src/shared/view.js';
import { MAC_WHEEL_DELTA, WheelClassifier, wheelDeltaPx, wheelZoomLevels } from '../src/shared/wheel.js';
import { scaleAtZoom, zoomAtScale } from '../src/shared/zoom-levels.js';

const close = (a: number, b: number, tol: number, what = ''): void => assert.ok(Math.abs(a - b) <= tol, `${what} ${a} vs ${b}`);

describe('wheel: mouse wheel or trackpad', () => {
  test('a delta under 4 is a trackpad, a multiple of 4.000244140625 a mouse wheel', () => {
    const c = new WheelClassifier();
    assert.deepEqual(c.push(2.5, 1000), { kind: 'trackpad', delta: 2.5 });
    const d = new WheelClassifier();
    assert.deepEqual(d.push(MAC_WHEEL_DELTA * 3, 1000), { kind: 'wheel', delta: MAC_WHEEL_DELTA * 3 });
  });

  test('a lone first event waits; with no second one it is a wheel click', () => {
    const c = new WheelClassifier();
    assert.equal(c.push(100, 1000), null);
    assert.deepEqual(c.flush(), { kind: 'wheel', delta: 100 });
    assert.equal(c.flush(), null, 'flushed once');
  });

  test('a quick stream of moderate deltas is a trackpad, and the waiting delta is not lost', () => {
    const c = new WheelClassifier();
    assert.equal(c.push(10, 1000), null);
    // 16 ms later: |16 * 10| < 200.
    assert.deepEqual(c.push(10, 1016), { kind: 'trackpad', delta: 20 });
    assert.deepEqual(c.push(12, 1032), { kind: 'trackpad', delta: 12 });
  });

  test('big deltas soon after each other are a wheel spun quickly', () => {
    const c = new WheelClassifier();
    assert.equal(c.push(100, 1000), null);
    assert.deepEqual(c.push(100, 1030), { kind: 'wheel', delta: 200 });
    // After a pause a new gesture is judged afresh.
    assert.equal(c.push(3.5, 2000)?.kind, 'trackpad');
  });

  test('a wheel notch is one zoom step of the step factor; a trackpad zooms 2x per 100 px', () => {
    assert.equal(wheelZoomLevels({ kind: 'wheel', delta: 100 }, 2), 1);
    assert.equal(wheelZoomLevels({ kind: 'wheel', delta: -100 }, 2), -1);
    close(wheelZoomLevels({ kind: 'wheel', delta: 100 }, 1.5), Math.log2(1.5), 1e-12);
    assert.equal(wheelZoomLevels({ kind: 'wheel', delta: -MAC_WHEEL_DELTA * 5 }, 2), -1, 'a macOS notch whatever its size');
    close(wheelZoomLevels({ kind: 'trackpad', delta: 50 }, 2), 0.5, 1e-12);
    assert.equal(wheelDeltaPx(3, 1), 100, 'three lines (Firefox) are one notch');
    assert.equal(wheelDeltaPx(1, 2), 100);
  });
});

describe('pan inertia (MapLibre: 160 ms, linearity 0.3, 2500 px/s^2, 1400 px/s)', () => {
  test('100 px in the last 100 ms glides on 60 px over 400 ms', () => {
    // speed = 100 px / 0.1 s * 0.3 = 300 px/s; t = 300 / (2500 * 0.3) = 0.4 s; d = 300 * 0.4 / 2 = 60 px.
    const g = panInertia([{ time: 0, x: 0, y: 0 }, { time: 50, x: 30, y: 40 }, { time: 100, x: 60, y: 80 }], 110)!;
    close(g.durationMs, 400, 1e-9);
    close(Math.hypot(g.dx, g.dy), 60, 1e-9);
    close(g.dx / g.dy, 0.75, 1e-12, 'in the direction of the drag');
  });

  test('speed is capped at 1400 px/s', () => {
    const g = panInertia([{ time: 0, x: 0, y: 0 }, { time: 10, x: 1000, y: 0 }], 10)!;
    // t = 1400 / 750 s, d = 1400 * t / 2.
    close(g.durationMs, (1400 / 750) * 1000, 1e-9);
    close(g.dx, (1400 * (1400 / 750)) / 2, 1e-9);
  });

  test('only the last 160 ms count, measured from where the pointer was then', () => {
    const samples = [{ time: 0, x: 0, y: 0 }, { time: 500, x: 1000, y: 0 }, { time: 600, x: 1010, y: 0 }, { time: 700, x: 1020, y: 0 }];
    const g = panInertia(samples, 700)!;
    // From the sample at or before 700 - 160 = 540 (t 500) to the last: 20 px in 200 ms.
    close(g.durationMs, ((20 / 0.2) * 0.3 * 1000) / 750, 1e-9);
  });

  test('a pointer that rested before the release does not throw the map', () => {
    assert.equal(panInertia([{ time: 0, x: 0, y: 0 }, { time: 50, x: 100, y: 0 }], 50 + PAN_INERTIA.cutoffMs + 1), null);
    assert.equal(panInertia([{ time: 0, x: 0, y: 0 }], 0), null);
    assert.equal(panInertia([{ time: 0, x: 5, y: 5 }, { time: 50, x: 5, y: 5 }], 50), null);
  });

  test('the buffer keeps what the window needs and forgets on release', () => {
    const b = new InertiaBuffer();
    for (let t = 0; t <= 1000; t += 20) b.push({ time: t, x: t, y: 0 });
    const g = b.release(1000)!;
    // 1000 px/s * 0.3 = 300 px/s.
    close(g.durationMs, 400, 1e-9);
    assert.equal(b.release(1000), null);
  });

  test('the glide eases out along bezier(0, 0, 0.3, 1): fast first, slow at the end', () => {
    assert.equal(inertiaEasing(0), 0);
    assert.equal(inertiaEasing(1), 1);
    assert.ok(easingSpeed(inertiaEasing, 0) > 2 && easingSpeed(inertiaEasing, 0.99) < 0.1);
  });
});

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
});

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

describe('easing', () => {
  test('ease-in-out starts and ends at rest', () => {
    assert.equal(easeInOut(0), 0);
    assert.equal(easeInOut(1), 1);
    assert.ok(easingSpeed(easeInOut, 0) < 0.1 && easingSpeed(easeInOut, 0.99) < 0.1 && easingSpeed(easeInOut, 0.5) > 1.4);
  });

  test('a continuing zoom starts at the pace it is given', () => {
    for (const speed of [0.5, 1, 2]) close(easingSpeed(continuingEasing(speed), 0), speed, 0.15 * speed, `slope ${speed}`);
    assert.equal(continuingEasing(0), easeInOut, 'from rest: ease in and out');
  });
});

describe('comparison mode, scale bar, hash, zoom levels', () => {
  test('discrete scales double from the base scale past the largest, and a scale snaps to the nearest in log', () => {
    const l = discreteLevels(1000, 20000);
    assert.deepEqual(l, [1000, 2000, 4000, 8000, 16000, 32000]);
    assert.equal(levelFor(l, 1400), 1000);
    assert.equal(levelFor(l, 1500), 2000);
    assert.equal(levelFor(l, 500), 1000);
    assert.equal(levelFor(l, 1e6), 32000);
  });

  test('the scale bar takes a round length that fits', () => {
    assert.deepEqual(scaleBarLength(1.4, 100), { length: 100, px: 100 / 1.4 });
    assert.equal(scaleBarLength(3, 100).length, 200);
    assert.equal(scaleBarLength(0.6, 100).length, 50);
    assert.equal(formatScale(25000), '1:25\u202f000');
    assert.equal(formatScale(1234567), '1:1\u202f230\u202f000');
  });

  test('the hash round-trips centre and scale to about a pixel', () => {
    const h = formatHash([181282.695, 457031.109], 1000, 0.28);
    assert.equal(h, '#181282.7/457031.1/1000');
    assert.deepEqual(parseHash(h), { center: [181282.7, 457031.1], scaleDenominator: 1000 });
    assert.equal(parseHash('#nonsense'), null);
    assert.equal(parseHash('#1/2/0'), null);
  });

  test('zoom levels are the web map scale set', () => {
    close(scaleAtZoom(0), 559082264.0287178, 1e-6);
    close(zoomAtScale(scaleAtZoom(17.5)), 17.5, 1e-12);
  });
});
