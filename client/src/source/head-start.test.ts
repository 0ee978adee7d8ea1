// The worker's side of the map's head start on the first view (head-start.ts, through
// fetchBytes): a body the map fetched is used without asking the network, once; one the map
// could not fetch is asked for by the worker itself, with its retries; an abort while waiting
// ends the request at once and keeps the body for the next; one the server refused (4xx) fails
// without asking again; one the server said to ask again later (Retry-After) is not asked sooner.
// The map's half: each file once, each body (a 4xx's status, a Retry-After's time, or null)
// posted, a file the worker left behind cancelled. Against a fake fetch.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { eventually, settle, settled } from '../../../testing/event-loop.js';
import { body, installFakeFetch, status } from '../../../testing/fake-fetch.js';
import { FetchFailure, fetchBytes, type RetryOptions } from './fetch-retry.js';
import { HeadStart, HeadStartFetches, type HeadStartResult } from './head-start.js';

const A = 'https://maps.test/cube/b-a.bin', B = 'https://maps.test/cube/b-b.bin', C = 'https://maps.test/cube/b-c.bin';
const bytesOf = (b: ArrayBuffer): number[] => [...new Uint8Array(b)];
/** A posted result, with a body as its bytes. */
const shown = (r: HeadStartResult): number[] | number | { retryAt: number } | null => (r instanceof ArrayBuffer ? bytesOf(r) : r);

describe('the head start on the first view', () => {
  test('a body the map fetched is taken without asking the network, and counted as loaded; a second request asks the network', async (t) => {
    const fetch = installFakeFetch(t, () => body(new Uint8Array([9, 9])));
    const headStart = new HeadStart();
    const loaded: string[] = [];
    const opts: RetryOptions = { retries: 0, backoffMs: 0, maxBackoffMs: 0, onLoaded: (u) => loaded.push(u), headStart };
    headStart.expect([A, B]);
    const p = fetchBytes(A, opts);
    await settle();
    assert.equal(fetch.requests.length, 0, 'waiting for the map, not on the network');
    headStart.arrived(A, new Uint8Array([1, 2, 3]).buffer);
    assert.deepEqual(bytesOf(await settled(p, 'the body')), [1, 2, 3]);
    assert.deepEqual(loaded, [A]);
    assert.deepEqual(bytesOf(await fetchBytes(A, opts)), [9, 9], 'taken once: asked again, from the network');
    assert.deepEqual(fetch.urls(), [A]);
    // A body that came before the worker asked for it waits for it.
    headStart.arrived(B, new Uint8Array([4]).buffer);
    assert.deepEqual(bytesOf(await fetchBytes(B, opts)), [4]);
    assert.deepEqual(fetch.urls(), [A], 'B never asked of the network');
  });

  test('one the map could not fetch the worker asks for itself, with its retries', async (t) => {
    let n = 0;
    const fetch = installFakeFetch(t, () => (++n === 1 ? status(503) : body(new Uint8Array([5]))));
    const headStart = new HeadStart();
    headStart.expect([A]);
    const p = fetchBytes(A, { retries: 1, backoffMs: 0, maxBackoffMs: 0, headStart });
    await settle();
    assert.equal(fetch.requests.length, 0);
    headStart.arrived(A, null);
    assert.deepEqual(bytesOf(await settled(p, 'the body')), [5]);
    assert.equal(fetch.requests.length, 2, 'a 503, then the body');
  });

  test('one the server refused (4xx) fails as the worker\'s own request would, without asking again', async (t) => {
    const fetch = installFakeFetch(t, () => body(new Uint8Array([5])));
    const headStart = new HeadStart();
    headStart.expect([A]);
    const p = fetchBytes(A, { retries: 3, backoffMs: 0, maxBackoffMs: 0, headStart });
    headStart.arrived(A, 404);
    await assert.rejects(settled(p, 'the failure'), (err: unknown) => err instanceof FetchFailure && err.kind === 'http' && err.status === 404 && err.message.includes(A));
    assert.equal(fetch.requests.length, 0, 'not asked of the network');
  });

  test('one the server said to ask for again later (Retry-After) the worker asks for then, not sooner', async (t) => {
    const NOW = Date.UTC(2026, 11, 5, 12, 0, 0);
    t.mock.timers.enable({ apis: ['setTimeout', 'Date'], now: NOW });
    const fetch = installFakeFetch(t, () => body(new Uint8Array([6])));
    const headStart = new HeadStart();
    headStart.expect([A]);
    const p = fetchBytes(A, { retries: 1, backoffMs: 0, maxBackoffMs: 0, headStart });
    headStart.arrived(A, { retryAt: NOW + 1500 });
    await settle();
    t.mock.timers.tick(1499);
    await settle();
    assert.equal(fetch.requests.length, 0, 'not asked 1,499 ms on');
    t.mock.timers.tick(1);
    assert.deepEqual(bytesOf(await settled(p, 'the body')), [6]);
    assert.equal(fetch.requests.length, 1);
  });

  test('aborted while the map still fetches it: an abort at once, nothing asked of the network, and the body kept for the next request', async (t) => {
    const fetch = installFakeFetch(t, () => body(new Uint8Array([1])));
    const headStart = new HeadStart();
    headStart.expect([A]);
    const controller = new AbortController();
    const opts: RetryOptions = { retries: 3, backoffMs: 0, maxBackoffMs: 0, headStart };
    const p = fetchBytes(A, opts, controller.signal);
    controller.abort();
    await assert.rejects(settled(p, 'the abort'), (err: unknown) => err instanceof FetchFailure && err.kind === 'abort');
    headStart.arrived(A, new Uint8Array([7]).buffer);
    assert.deepEqual(bytesOf(await fetchBytes(A, opts)), [7], 'the view came back: the body the map fetched');
    assert.equal(fetch.requests.length, 0);
  });

  test('a body the worker\'s view no longer needs is let go: a later request asks the network', async (t) => {
    const fetch = installFakeFetch(t, () => body(new Uint8Array([8])));
    const headStart = new HeadStart();
    headStart.expect([A, B]);
    assert.equal(headStart.holding, true);
    headStart.keepOnly((url) => url === A);
    headStart.arrived(B, new Uint8Array([1]).buffer);
    headStart.arrived(A, new Uint8Array([2]).buffer);
    const opts: RetryOptions = { retries: 0, backoffMs: 0, maxBackoffMs: 0, headStart };
    assert.deepEqual(bytesOf(await fetchBytes(A, opts)), [2]);
    assert.deepEqual(bytesOf(await fetchBytes(B, opts)), [8]);
    assert.deepEqual(fetch.urls(), [B]);
    assert.equal(headStart.holding, false, 'every body taken or let go');
  });
});

describe('the map\'s fetches for the worker', () => {
  test('each file once, without retries; each body posted as it comes, a lasting 4xx\'s status, null for another failure (a 429); done once all are', async (t) => {
    const fetch = installFakeFetch(t, (url) => (url === B ? status(429) : url === C ? status(404) : 'hold'));
    const posted: [string, ReturnType<typeof shown>][] = [];
    let done = 0;
    const fetches = new HeadStartFetches([A, B, C], { retries: 5, backoffMs: 0, maxBackoffMs: 0 }, (url, r) => posted.push([url, shown(r)]), () => done++);
    await eventually(() => posted.length === 2, 'B and C posted');
    assert.deepEqual(new Map(posted), new Map([[B, null], [C, 404]]), 'B failed, not retried: the worker fetches it itself; C was refused');
    assert.equal(fetches.pending, true);
    assert.equal(done, 0);
    fetch.open()[0]!.answer(body(new Uint8Array([3])));
    await eventually(() => done === 1, 'done');
    assert.deepEqual(posted[2], [A, [3]]);
    assert.equal(fetches.pending, false);
    assert.deepEqual(fetch.urls(), [A, B, C]);
  });

  test('a 429 or 503 with Retry-After posts when to ask again, in ms since the epoch', async (t) => {
    const NOW = Date.UTC(2026, 11, 5, 12, 0, 0);
    t.mock.timers.enable({ apis: ['Date'], now: NOW });
    installFakeFetch(t, (url) => (url === A ? status(429, { 'Retry-After': '3' }) : status(503, { 'Retry-After': new Date(NOW + 5000).toUTCString() })));
    const posted: [string, ReturnType<typeof shown>][] = [];
    new HeadStartFetches([A, B], { retries: 5, backoffMs: 0, maxBackoffMs: 0 }, (url, r) => posted.push([url, shown(r)]), () => undefined);
    await eventually(() => posted.length === 2, 'both posted');
    assert.deepEqual(new Map(posted), new Map([[A, { retryAt: NOW + 3000 }], [B, { retryAt: NOW + 5000 }]]));
  });

  test('a file the worker left behind is cancelled: its request aborted, null posted', async (t) => {
    const fetch = installFakeFetch(t, () => 'hold');
    const posted: [string, HeadStartResult][] = [];
    let done = 0;
    const fetches = new HeadStartFetches([A, B], { retries: 0, backoffMs: 0, maxBackoffMs: 0 }, (url, r) => posted.push([url, r]), () => done++);
    await eventually(() => fetch.open().length === 2, 'both asked for');
    fetches.cancel(A);
    assert.equal(fetch.requests[0]!.signal?.aborted, true);
    await eventually(() => posted.length === 1, 'A posted');
    assert.deepEqual(posted, [[A, null]]);
    fetches.cancelAll();
    await eventually(() => done === 1, 'done');
    assert.deepEqual(posted, [[A, null], [B, null]]);
  });
});
