// The CORS settings: `--cors` text to origins, origins normalised or refused at start, and
// which request origins are granted.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { CorsConfigError, CorsPolicy, parseCorsOrigins } from './cors.js';

test('--cors is * or a comma-separated list, blanks dropped', () => {
  assert.equal(parseCorsOrigins(' * '), '*');
  assert.deepEqual(parseCorsOrigins('https://a.example, http://localhost:5173,,'), ['https://a.example', 'http://localhost:5173']);
  assert.deepEqual(parseCorsOrigins(','), []);
});

test('no origins, or an empty list, is no CORS', () => {
  for (const policy of [new CorsPolicy(undefined), new CorsPolicy([])]) {
    assert.equal(policy.enabled, false);
    assert.equal(policy.allowOrigin('https://a.example'), undefined);
  }
});

test('* grants every origin, and the answer does not depend on it', () => {
  const policy = new CorsPolicy('*');
  assert.ok(policy.enabled && !policy.variesByOrigin);
  assert.equal(policy.allowOrigin('https://a.example'), '*');
  assert.equal(policy.allowOrigin(undefined), '*');
});

test('a list grants its origins whatever their case, echoing the one asked, and nothing else', () => {
  const policy = new CorsPolicy(['https://Map.Example.org/', 'http://localhost:5173']);
  assert.ok(policy.enabled && policy.variesByOrigin);
  assert.equal(policy.allowOrigin('https://map.example.org'), 'https://map.example.org');
  assert.equal(policy.allowOrigin('HTTPS://MAP.EXAMPLE.ORG'), 'HTTPS://MAP.EXAMPLE.ORG');
  assert.equal(policy.allowOrigin('http://localhost:5173'), 'http://localhost:5173');
  for (const other of ['http://localhost:5174', 'https://map.example.org.evil.example', 'null', undefined]) {
    assert.equal(policy.allowOrigin(other), undefined, String(other));
  }
});

test('what cannot be an origin is refused at start', () => {
  for (const bad of ['https://a.example/app', 'https://a.example?x=1', 'https://a.example#x', 'a.example', 'null', 'https://user@a.example', 'https://u:p@a.example']) {
    assert.throws(() => new CorsPolicy([bad]), (err: unknown) => err instanceof CorsConfigError && /not an origin/.test(err.message), bad);
  }
});
