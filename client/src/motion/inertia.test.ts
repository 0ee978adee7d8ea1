// Pan inertia with MapLibre's numbers, worked out here from the definitions, not read back.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { easingSpeed, inertiaEasing } from './easing.js';
import { InertiaBuffer, panInertia, PAN_INERTIA } from './inertia.js';

const close = (a: number, b: number, tol: number, what = ''): void => assert.ok(Math.abs(a - b) <= tol, `${what} ${a} vs ${b}`);

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
