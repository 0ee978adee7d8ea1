// Conditional requests (RFC 9110 §13): when a 304 is the answer, and when a Range still
// applies to the copy the client holds.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { isNotModified, rangeApplies, type Validators } from './preconditions.js';

const v: Validators = { etag: '"abc"', lastModifiedMs: Date.parse('Thu, 02 Jan 2020 03:04:05 GMT') };

test('If-None-Match: a 304 for this tag in the list, compared weakly, or for *', () => {
  assert.equal(isNotModified('"abc"', undefined, v), true);
  assert.equal(isNotModified('"x", "abc"', undefined, v), true);
  assert.equal(isNotModified('W/"abc"', undefined, v), true);
  assert.equal(isNotModified(' * ', undefined, v), true);
  assert.equal(isNotModified('"abcd"', undefined, v), false);
  assert.equal(isNotModified('abc', undefined, v), false); // not a tag at all
  assert.equal(isNotModified('', undefined, v), false);
});

test('If-Modified-Since: a 304 when not modified since, and only without If-None-Match', () => {
  assert.equal(isNotModified(undefined, 'Thu, 02 Jan 2020 03:04:05 GMT', v), true);
  assert.equal(isNotModified(undefined, 'Fri, 03 Jan 2020 00:00:00 GMT', v), true);
  assert.equal(isNotModified(undefined, 'Wed, 01 Jan 2020 00:00:00 GMT', v), false);
  assert.equal(isNotModified(undefined, 'yesterday', v), false);
  assert.equal(isNotModified('"other"', 'Fri, 03 Jan 2020 00:00:00 GMT', v), false, 'the tag decides');
  assert.equal(isNotModified(undefined, undefined, v), false);
});

test('If-Range: the range applies to exactly this version, compared strongly', () => {
  assert.equal(rangeApplies(undefined, v), true);
  assert.equal(rangeApplies('"abc"', v), true);
  assert.equal(rangeApplies(' "abc" ', v), true);
  assert.equal(rangeApplies('W/"abc"', v), false); // a weak tag never matches
  assert.equal(rangeApplies('"other"', v), false);
  assert.equal(rangeApplies('Thu, 02 Jan 2020 03:04:05 GMT', v), true);
  assert.equal(rangeApplies('Fri, 03 Jan 2020 00:00:00 GMT', v), false); // a date must be exact
  assert.equal(rangeApplies('soon', v), false);
});
