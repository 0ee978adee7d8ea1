// Attribute pages: the properties of features first.. read back; a page that is not one is
// refused, naming the file.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { ATTRIBUTE_PAGE_SIZE, decodeAttributePage, encodeAttributePage, featureAttributes } from './attribute-page.js';

describe('attribute page', () => {
  test('holds a page of features from first, and reads back', () => {
    const attrs = Array.from({ length: ATTRIBUTE_PAGE_SIZE + 3 }, (_, i) => (i === 4097 ? null : { id: `f${i}`, height: i / 2 }));
    const second = encodeAttributePage(attrs, ATTRIBUTE_PAGE_SIZE);
    assert.equal(new TextDecoder().decode(second), JSON.stringify({ first: 4096, attributes: [{ id: 'f4096', height: 2048 }, null, { id: 'f4098', height: 2049 }] }));
    const page = decodeAttributePage(JSON.parse(new TextDecoder().decode(second)), 'a-2.json');
    assert.deepEqual(featureAttributes(page, 4098), { id: 'f4098', height: 2049 });
    assert.equal(featureAttributes(page, 4097), null);
    assert.equal(featureAttributes(page, 5000), null, 'beyond the page: nothing');
    const first = decodeAttributePage(JSON.parse(new TextDecoder().decode(encodeAttributePage(attrs, 0))), 'a-1.json');
    assert.equal(first.attributes.length, ATTRIBUTE_PAGE_SIZE);
  });

  test('a page that is not one is refused, naming the file', () => {
    assert.throws(() => decodeAttributePage({ first: -1, attributes: [] }, 'a-x.json'), /^FormatError: a-x.json: not an attribute page: first: must be >= 0/);
    assert.throws(() => decodeAttributePage({ first: 0, attributes: [1] }, 'a-x.json'), /attributes.0: must be an object or null/);
    assert.throws(() => decodeAttributePage([], 'a-x.json'), /a-x.json/);
  });
});
