// The comparison mode's scales: from the base scale by a factor, and the nearest in log.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { discreteLevels, levelFor } from './discrete-scales.js';

describe('comparison mode scales', () => {
  test('discrete scales double from the base scale past the largest, and a scale snaps to the nearest in log', () => {
    const l = discreteLevels(1000, 20000);
    assert.deepEqual(l, [1000, 2000, 4000, 8000, 16000, 32000]);
    assert.equal(levelFor(l, 1400), 1000);
    assert.equal(levelFor(l, 1500), 2000);
    assert.equal(levelFor(l, 500), 1000);
    assert.equal(levelFor(l, 1e6), 32000);
  });
});
