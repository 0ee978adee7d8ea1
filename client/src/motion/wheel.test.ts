// Wheel classification (mouse wheel or trackpad, told apart as MapLibre does) and wheel zoom.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { MAC_WHEEL_DELTA, WheelClassifier, wheelDeltaPx, wheelZoomLevels } from './wheel.js';

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
