// Fetching with retries, against a fake fetch and fake timers: passing failures (5xx, a dropped
// connection) are tried again after waits that double up to a cap, lasting ones (4xx) are not,
// it gives up after the retries allowed, an abort stops it at once, a server's Retry-After is
// followed, and gzip JSON is read.
import assert from 'node:assert/strict';
import { gzipSync } from 'node:zlib';
import { describe, test, type TestContext } from 'node:test';
import { eventually, settle, settled } from '../../../testing/event-loop.js';
import { body, installFakeFetch, networkError, status, type FakeFetch } from '../../../testing/fake-fetch.js';
import { FetchFailure, fetchBytes, fetchJson, mayPass, RETRY_AFTER_MAX_MS, type RetryOptions } from './fetch-retry.js';

const URL_A = 'https://maps.test/cube/c-a.bin';
const opts = (retries: number, over: Partial<RetryOptions> = {}): RetryOptions => ({ retries, backoffMs: 100, maxBackoffMs: 300, ...over });

/** Asserts the next attempt comes exactly `ms` of fake time after the last one failed. */
async function nextAttemptAfter(t: TestContext, f: FakeFetch, ms: number): Promise<void> {
  const before = f.requests.length;
  await settle();
  t.mock.timers.tick(ms - 1);
  await settle();
  assert.equal(f.requests.length, before, `no attempt ${ms - 1} ms after attempt ${before}`);
  t.mock.timers.tick(1);
  await eventually(() => f.requests.length === before + 1, `attempt ${before + 1} at ${ms} ms`);
}

/** The failure `p` rejects with. */
async function failureOf(p: Promise<unknown>): Promise<FetchFailure> {
  try {
    await settled(p, 'the fetch to end');
  } catch (err) {
    assert.ok(err instanceof FetchFailure, `a FetchFailure, not ${String(err)}`);
    return err;
  }
  assert.fail('it did not fail');
}

describe('fetch with retries', () => {
  test('503 twice then 200: the body after three attempts, waiting 100 then 200 ms', async (t) => {
    t.mock.timers.enable({ apis: ['setTimeout'] });
    const f = installFakeFetch(t, (_url, n) => (n <= 2 ? status(503) : body(new Uint8Array([1, 2, 3]))));
    const loaded: string[] = [];
    const p = fetchBytes(URL_A, opts(3, { onLoaded: (u) => loaded.push(u) }));
    await nextAttemptAfter(t, f, 100);
    await nextAttemptAfter(t, f, 200);
    assert.deepEqual([...new Uint8Array(await settled(p, 'the body'))], [1, 2, 3]);
    assert.deepEqual(loaded, [URL_A], 'told once, of the body received whole');
  });

  test('the wait doubles up to the cap: 100, 200, 400, 800, 1000, 1000 ms', async (t) => {
    t.mock.timers.enable({ apis: ['setTimeout'] });
    const f = installFakeFetch(t, (_url, n) => (n <= 6 ? status(500) : body('ok')));
    const p = fetchBytes(URL_A, opts(6, { maxBackoffMs: 1000 }));
    for (const ms of [100, 200, 400, 800, 1000, 1000]) await nextAttemptAfter(t, f, ms);
    assert.equal(new TextDecoder().decode(await settled(p, 'the body')), 'ok');
  });

  test('a dropped connection is retried like a server error', async (t) => {
    t.mock.timers.enable({ apis: ['setTimeout'] });
    const f = installFakeFetch(t, (_url, n) => (n === 1 ? networkError() : body('ok')));
    const p = fetchBytes(URL_A, opts(2));
    await nextAttemptAfter(t, f, 100);
    assert.equal(new TextDecoder().decode(await settled(p, 'the body')), 'ok');
  });

  for (const code of [408, 429]) {
    test(`${code} passes (a timeout, a CDN's answer to a burst): retried like a server error`, async (t) => {
      t.mock.timers.enable({ apis: ['setTimeout'] });
      const f = installFakeFetch(t, (_url, n) => (n === 1 ? status(code) : body('ok')));
      const p = fetchBytes(URL_A, opts(3));
      await nextAttemptAfter(t, f, 100);
      assert.equal(new TextDecoder().decode(await settled(p, 'the body')), 'ok');
    });
  }

  // A fixed clock, a whole second, so that an HTTP date names an exact wait.
  const NOW = Date.UTC(2026, 11, 5, 12, 0, 0);
  const retryAfterCases: [string, number, string][] = [
    ['seconds', 429, '2'],
    ['an HTTP date', 503, new Date(NOW + 3000).toUTCString()],
  ];
  for (const [kind, code, value] of retryAfterCases) {
    test(`a ${code} with Retry-After in ${kind} is asked again when the server said, not after the backoff`, async (t) => {
      t.mock.timers.enable({ apis: ['setTimeout', 'Date'], now: NOW });
      const f = installFakeFetch(t, (_url, n) => (n === 1 ? status(code, { 'Retry-After': value }) : body('ok')));
      const p = fetchBytes(URL_A, opts(3));
      await nextAttemptAfter(t, f, kind === 'seconds' ? 2000 : 3000);
      assert.equal(new TextDecoder().decode(await settled(p, 'the body')), 'ok');
    });
  }

  test('Retry-After never shortens the backoff, one that does not read or is past is ignored, and a very long one is cut to RETRY_AFTER_MAX_MS', async (t) => {
    t.mock.timers.enable({ apis: ['setTimeout', 'Date'], now: NOW });
    // Date.parse would read "soon 2030" as a day in 2030.
    const after = ['0', 'soon 2030', '-5', '1.5', new Date(NOW - 60_000).toUTCString(), '3600'];
    const f = installFakeFetch(t, (_url, n) => (n <= after.length ? status(429, { 'Retry-After': after[n - 1]! }) : body('ok')));
    const p = fetchBytes(URL_A, opts(6, { maxBackoffMs: 1000 }));
    for (const ms of [100, 200, 400, 800, 1000, RETRY_AFTER_MAX_MS]) await nextAttemptAfter(t, f, ms);
    assert.equal(new TextDecoder().decode(await settled(p, 'the body')), 'ok');
  });

  for (const code of [400, 403, 404, 410]) {
    test(`${code} is not retried: it fails at once and never asks again`, async (t) => {
      t.mock.timers.enable({ apis: ['setTimeout'] });
      const loaded: string[] = [];
      const f = installFakeFetch(t, (_url, n) => (n === 1 ? status(code) : body('too late')));
      const err = await failureOf(fetchBytes(URL_A, opts(5, { onLoaded: (u) => loaded.push(u) })));
      assert.equal(err.kind, 'http');
      assert.equal(err.status, code);
      assert.equal(err.attempts, 1);
      assert.ok(err.message.includes(`HTTP ${code}`) && err.message.includes(URL_A), err.message);
      t.mock.timers.tick(60_000);
      await settle();
      assert.equal(f.requests.length, 1);
      assert.deepEqual(loaded, []);
    });
  }

  test('gives up after the retries allowed, with the last failure and the attempts made', async (t) => {
    t.mock.timers.enable({ apis: ['setTimeout'] });
    const f = installFakeFetch(t, () => status(503));
    const p = failureOf(fetchBytes(URL_A, opts(2)));
    await nextAttemptAfter(t, f, 100);
    await nextAttemptAfter(t, f, 200);
    const err = await p;
    assert.equal(err.kind, 'http');
    assert.equal(err.status, 503);
    assert.equal(err.attempts, 3);
    t.mock.timers.tick(60_000);
    await settle();
    assert.equal(f.requests.length, 3, 'one attempt and two retries, no more');
  });

  test('the failures the network\'s return may mend (mayPass): a network failure, and 5xx, 408 and 429 after the retries; not another 4xx, a body that is not JSON, or an abort', async (t) => {
    const answers = new Map<string, () => Response | Error>([
      ['network', networkError],
      ['503', () => status(503)],
      ['500', () => status(500)],
      ['408', () => status(408)],
      ['429', () => status(429)],
      ['404', () => status(404)],
      ['403', () => status(403)],
      ['not json', () => body('<html>')],
    ]);
    installFakeFetch(t, (url) => answers.get(decodeURIComponent(url.slice(URL_A.length + 1)))!());
    const passing: string[] = [];
    for (const name of answers.keys()) {
      const err = await fetchJson(`${URL_A}?${encodeURIComponent(name)}`, opts(0)).then(() => assert.fail(`${name} did not fail`), (e: unknown) => e);
      if (mayPass(err)) passing.push(name);
    }
    assert.deepEqual(passing, ['network', '503', '500', '408', '429']);
    const ac = new AbortController();
    ac.abort();
    assert.equal(mayPass(await fetchBytes(`${URL_A}?network`, opts(0), ac.signal).catch((e: unknown) => e)), false, 'an abort');
  });

  test('a network failure it gives up on says so', async (t) => {
    installFakeFetch(t, () => networkError());
    const err = await failureOf(fetchBytes(URL_A, opts(0)));
    assert.equal(err.kind, 'network');
    assert.equal(err.status, undefined);
    assert.ok(err.message.includes('fetch failed'), err.message);
  });

  test('an abort while the request is open stops it at once, without a retry', async (t) => {
    t.mock.timers.enable({ apis: ['setTimeout'] });
    const f = installFakeFetch(t, () => 'hold');
    const ac = new AbortController();
    const p = failureOf(fetchBytes(URL_A, opts(3), ac.signal));
    await eventually(() => f.requests.length === 1, 'the request');
    ac.abort();
    assert.equal((await p).kind, 'abort');
    t.mock.timers.tick(60_000);
    await settle();
    assert.equal(f.requests.length, 1);
  });

  test('an abort during the wait before a retry stops it: no further attempt', async (t) => {
    t.mock.timers.enable({ apis: ['setTimeout'] });
    const f = installFakeFetch(t, () => status(503));
    const ac = new AbortController();
    const p = failureOf(fetchBytes(URL_A, opts(3), ac.signal));
    await eventually(() => f.requests.length === 1, 'the first attempt');
    await settle();
    t.mock.timers.tick(50);
    ac.abort();
    const err = await p;
    assert.equal(err.kind, 'abort');
    assert.equal(err.url, URL_A);
    t.mock.timers.tick(60_000);
    await settle();
    assert.equal(f.requests.length, 1);
  });

  test('JSON is read whether or not the host left it gzip-compressed', async (t) => {
    const doc = { format: 'ssc-index', n: [1, 2, 3], name: 'Zion – NLCD' };
    const text = JSON.stringify(doc);
    installFakeFetch(t, (url) => body(url.endsWith('.gz') ? new Uint8Array(gzipSync(text)) : text));
    assert.deepEqual(await fetchJson('https://maps.test/index.json', opts(0)), doc);
    assert.deepEqual(await fetchJson('https://maps.test/index.json.gz', opts(0)), doc);
  });

  test('a body that is not JSON is an error, not retried', async (t) => {
    const f = installFakeFetch(t, () => body('<html>not found</html>'));
    await assert.rejects(fetchJson('https://maps.test/index.json', opts(3)), SyntaxError);
    assert.equal(f.requests.length, 1);
  });
});
