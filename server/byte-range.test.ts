// parseRange: one byte range of a file of known size (RFC 9110 §14.1.2), a suffix, an open end;
// what cannot be satisfied; and every header it does not understand, or several ranges,
// ignored so that the whole file is sent.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { parseRange, type RangeRequest } from './byte-range.js';

const WHOLE: RangeRequest = { kind: 'whole' };
const UNSATISFIABLE: RangeRequest = { kind: 'unsatisfiable' };
const range = (start: number, end: number): RangeRequest => ({ kind: 'range', start, end });

test('a single range, with the end clamped to the file', () => {
  const cases: [string, RangeRequest][] = [
    ['bytes=0-99', range(0, 99)],
    ['bytes=0-0', range(0, 0)],
    ['bytes=999-999', range(999, 999)],
    ['bytes=990-', range(990, 999)],
    ['bytes=995-5000', range(995, 999)],
    ['bytes=0-', range(0, 999)],
    ['bytes=-100', range(900, 999)], // the last 100 bytes
    ['bytes=-5000', range(0, 999)], // a suffix longer than the file is all of it
    ['BYTES = 10-19', range(10, 19)], // the unit is case-insensitive, spaces around = allowed
    ['bytes= 10-19 ,', range(10, 19)], // an empty list element is no range
  ];
  for (const [header, expected] of cases) assert.deepEqual(parseRange(header, 1000), expected, header);
});

test('what selects no byte of the file is unsatisfiable', () => {
  const cases: [string, number][] = [
    ['bytes=1000-', 1000],
    ['bytes=1000-2000', 1000],
    ['bytes=-0', 1000], // an empty suffix
    ['bytes=0-', 0], // nothing of an empty file
    ['bytes=-5', 0],
    ['bytes=0-0', 0],
  ];
  for (const [header, size] of cases) assert.deepEqual(parseRange(header, size), UNSATISFIABLE, `${header} of ${size} bytes`);
});

test('no header, a header we do not understand, or several ranges: the whole file', () => {
  const headers = [undefined, 'bytes=5-2', 'items=0-5', 'bytes=abc', 'bytes=', 'bytes=1-2-3', 'bytes 0-5', 'bytes=0-1,5-6', 'bytes=-1,-2', 'bytes=0x10-20'];
  for (const header of headers) assert.deepEqual(parseRange(header, 1000), WHOLE, String(header));
});
