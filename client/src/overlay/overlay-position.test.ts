// Where a marker or popup goes: MapLibre's offsets and automatic popup anchors.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { autoAnchor, offsetFor } from './overlay-position.js';

describe('overlay position', () => {
  test('a number offset is a distance away from the place, toward the side the element is on', () => {
    assert.deepEqual(offsetFor('bottom', 41), [0, -41]);
    assert.deepEqual(offsetFor('top', 10), [0, 10]);
    assert.deepEqual(offsetFor('left', 10), [10, 0]);
    assert.deepEqual(offsetFor('center', 10), [0, 0]);
    const [x, y] = offsetFor('bottom-right', 10);
    assert.ok(Math.abs(x + 10 / Math.SQRT2) < 1e-12 && Math.abs(y + 10 / Math.SQRT2) < 1e-12);
    assert.deepEqual(offsetFor('top', [3, -4]), [3, -4]);
  });

  test('a popup goes above its place, below it near the top edge, and aside near the left and right', () => {
    const map: [number, number] = [640, 480];
    const size: [number, number] = [200, 80];
    assert.equal(autoAnchor([320, 240], size, map), 'bottom');
    assert.equal(autoAnchor([320, 50], size, map), 'top');
    assert.equal(autoAnchor([50, 240], size, map), 'left');
    assert.equal(autoAnchor([600, 50], size, map), 'top-right');
    assert.equal(autoAnchor([600, 470], size, map), 'bottom-right');
  });
});
