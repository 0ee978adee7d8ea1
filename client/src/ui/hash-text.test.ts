// The URL hash's text: centre and scale, and what is not a hash.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { formatHash, parseHash } from './hash-text.js';

describe('URL hash', () => {
  test('the hash round-trips centre and scale to about a pixel', () => {
    const h = formatHash([181282.695, 457031.109], 1000, 0.28);
    assert.equal(h, '#181282.7/457031.1/1000');
    assert.deepEqual(parseHash(h), { center: [181282.7, 457031.1], scaleDenominator: 1000 });
    assert.equal(parseHash('#nonsense'), null);
    assert.equal(parseHash('#1/2/0'), null);
  });
});
