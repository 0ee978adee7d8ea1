// The worker's side of the map's head start on the first view (head-start.ts, through
// fetchBytes): a body the map fetched is used without asking the network, once; one the map
// could not fetch is asked for by the worker itself, with its retries; an abort while waiting
// ends the request at once. Against a fake fetch.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { eventually, settle, settled } from '../../../testing/event-loop.js';
import { body, installFakeFetch, status } from '../../../testing/fake-fetch.js';
import { FetchFailure, fetchBytes, type RetryOptions } from './fetch-retry.js';
import { HeadStart } from './head-start.js';

const A = 'https://maps.test/cube/b-a.bin', B = 'https://maps.test/cube/b-b.bin';
const bytesOf = (b: ArrayBuffer): number[] => [...new Uint8Array(b)];

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

  test('aborted while the map still fetches it: an abort at once, and nothing asked of the network', async (t) => {
    const fetch = installFakeFetch(t, () => body(new Uint8Array([1])));
    const headStart = new HeadStart();
    headStart.expect([A]);
    const controller = new AbortController();
    const p = fetchBytes(A, { retries: 3, backoffMs: 0, maxBackoffMs: 0, headStart }, controller.signal);
    controller.abort();
    await assert.rejects(settled(p, 'the abort'), (err: unknown) => err instanceof FetchFailure && err.kind === 'abort');
    headStart.arrived(A, new Uint8Array([1]).buffer); // late: no one waits
    await eventually(() => true, 'a turn');
    assert.equal(fetch.requests.length, 0);
  });
});
