// The scale bar's round lengths and the scale's text.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { formatScale, scaleBarLength, spokenScale } from './scale-bar-length.js';

describe('scale bar', () => {
  test('the scale bar takes a round length that fits', () => {
    assert.deepEqual(scaleBarLength(1.4, 100), { length: 100, px: 100 / 1.4 });
    assert.equal(scaleBarLength(3, 100).length, 200);
    assert.equal(scaleBarLength(0.6, 100).length, 50);
    assert.equal(formatScale(25000), '1:25\u202f000');
    assert.equal(formatScale(1234567), '1:1\u202f230\u202f000');
    assert.equal(spokenScale(1234567), 'Scale 1:1,230,000');
    assert.equal(spokenScale(512.3), 'Scale 1:512');
  });
});
