// The URL hash's text in MapLibre's form, and what is not a hash.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { formatHash, parseHash } from './hash-text.js';

describe('URL hash', () => {
  test('zoom, latitude, longitude in that order, as MapLibre writes them', () => {
    // Zoom 16.123456, centre 5.81234567 E 52.06543219 N: zoom to 4 decimals, and
    // ceil((16.1235 ln 2 + ln(512 / 180)) / ln 10) = 6 decimals of a degree.
    const h = formatHash(16.123456, [5.81234567, 52.06543219]);
    assert.equal(h, '#16.1235/52.065432/5.812346');
    assert.deepEqual(parseHash(h), { zoom: 16.1235, center: [5.812346, 52.065432] });
  });

  test('fewer decimals when zoomed out', () => {
    assert.equal(formatHash(3, [5.81234567, -52.06543219]), '#3/-52.07/5.81');
  });

  test('a hash MapLibre wrote (zoom to 2 decimals) is read', () => {
    assert.deepEqual(parseHash('#16.12/52.065432/5.812346'), { zoom: 16.12, center: [5.812346, 52.065432] });
  });

  test("MapLibre's bearing and pitch are read past; anything else is not a hash", () => {
    assert.deepEqual(parseHash('#12/52.1/5.8/0/0'), { zoom: 12, center: [5.8, 52.1] });
    assert.equal(parseHash('#nonsense'), null);
    assert.equal(parseHash('#1/2'), null);
    assert.equal(parseHash('#12/95/5'), null);
    assert.equal(parseHash('#12/a/5'), null);
  });
});
