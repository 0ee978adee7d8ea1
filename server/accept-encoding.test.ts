// The order of codings to try for an Accept-Encoding header (RFC 9110 §12.5.3): the client's
// q-values first, brotli before gzip on a tie, identity always last in reserve; and the
// siblings worth looking for, whose remembered answers stay right however many headers come.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { codingsToTry, siblingCodings, type Coding } from './accept-encoding.js';

const ORDERS: [string | undefined, Coding[]][] = [
  [undefined, ['identity']], // says nothing: could decode nothing else
  ['', ['identity']],
  ['gzip, deflate, br, zstd', ['br', 'gzip', 'identity']], // a browser's
  ['gzip;q=1, br;q=0.5', ['gzip', 'br', 'identity']],
  ['br;q=0.2, gzip;q=0.8', ['gzip', 'br', 'identity']],
  ['gzip;q=0.5, br;q=0.5', ['br', 'gzip', 'identity']], // a tie: the smaller first
  ['*', ['br', 'gzip', 'identity']],
  ['*;q=0.5, gzip', ['gzip', 'br', 'identity']],
  ['br;q=0, *', ['gzip', 'identity']],
  ['*;q=0', ['identity']], // nothing is acceptable: identity is sent anyway
  ['identity;q=0', ['identity']],
  ['gzip;q=0.1, identity', ['identity', 'gzip']],
  ['gzip;q=0', ['identity']],
  ['br;q=0.000', ['identity']],
  ['br;q=1.5', ['identity']], // an impossible weight: that entry is ignored
  ['br;q=abc, gzip', ['gzip', 'identity']],
  ['x-gzip', ['gzip', 'identity']],
  ['  BR  ', ['br', 'identity']],
  ['deflate', ['identity']],
];

test('codings come in the order the client weighs them, identity last in reserve', () => {
  for (const [header, order] of ORDERS) assert.deepEqual(codingsToTry(header), order, JSON.stringify(header));
});

function assertSiblings(): void {
  for (const [header, order] of ORDERS) {
    assert.deepEqual(siblingCodings(header), order.slice(0, order.indexOf('identity')), JSON.stringify(header));
  }
}

test('siblings are looked for only for codings preferred to identity', assertSiblings);

test('remembered answers stay right past the number of headers remembered', () => {
  // Each header's answer is remembered; a flood of distinct values must not change any answer.
  for (let i = 0; i < 500; i++) assert.deepEqual(siblingCodings(`gzip;q=0.${(i % 9) + 1}, br;q=0.5, x-${i}`), i % 9 >= 5 ? ['gzip', 'br'] : ['br', 'gzip']);
  assertSiblings();
});
