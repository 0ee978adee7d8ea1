// The chunk scheduler over a fake server and hand-made cubes of real chunks: how many requests
// are in flight, which chunk goes first (nearest the view centre, on-screen before margin, the
// views ahead last and in their order; the margin once the view has rested), what happens to
// chunks the view no longer needs (queued ones never fetched, a request in flight aborted), and
// the status and error messages the map gets for each chunk (received, on the GPU, evicted and
// fetched again, failed).
import assert from 'node:assert/strict';
import { describe, test, type TestContext } from 'node:test';
import { parseIndex, type Box3, type ChunkLeaf } from '../../../format/cube-index.js';
import { boxMeets, queryIndex, type QueryBox } from '../../../format/index-query.js';
import { eventually, settle } from '../../../testing/event-loop.js';
import { fakeClock } from '../../../testing/fake-clock.js';
import { installFakeFetch, networkError, status, type Answer, type FakeFetch } from '../../../testing/fake-fetch.js';
import { handMadeCube, serveFiles, squareChunk, twoLevelCube, type ChunkSpec } from '../../../testing/hand-made-cube.js';
import { ChunkScheduler } from './chunk-scheduler.js';
import { firstViewFiles, INTERIM_SHARE, interimFloor, underView } from './floor-choice.js';
import { IndexTree } from './index-tree.js';
import type { AheadView, ChunkStatus, FromWorker, NeededChunks, SourceErrorInfo, SourceOptions, ViewRequest } from './worker-protocol.js';

const BASE = 'https://maps.test/cube/';

/** `n` chunks in a row along x, 10 wide each: c-0.bin over x 0..10, c-1.bin over 10..20, ... */
const row = (n: number): ChunkSpec[] => Array.from({ length: n }, (_, i) => ({ file: `c-${i}.bin`, bbox: [10 * i, 0, 0, 10 * i + 10, 10, 100] as Box3 }));

const ground = (x0: number, x1: number): [number, number, number, number] => [x0, 0, x1, 10];

/** A view over x0..x1 (y 0..10), the margin as wide unless given, base z 10 in a z range 0..100. */
function view(seq: number, x0: number, x1: number, o: { centerX: number; margin?: [number, number]; ahead?: AheadView[]; frameMs?: number }): ViewRequest {
  const v: ViewRequest = { seq, visible: ground(x0, x1), margin: ground(...(o.margin ?? [x0, x1])), zMin: 0, zMax: 100, centerX: o.centerX, centerY: 5, z: 10 };
  if (o.ahead) v.ahead = o.ahead;
  if (o.frameMs !== undefined) v.frameMs = o.frameMs;
  return v;
}

const ahead = (x0: number, x1: number): AheadView => ({ box: ground(x0, x1), zMin: 0, zMax: 100, centerX: (x0 + x1) / 2, centerY: 5, z: 10 });

interface Harness {
  scheduler: ChunkScheduler;
  fetch: FakeFetch;
  /** Chunk and sub-index files requested, in order (index.json left out). */
  fetched(): string[];
  /** How many times a file was requested. */
  times(file: string): number;
  /** The statuses posted for a chunk, in order. */
  statuses(file: string): ChunkStatus[];
  /** Chunks posted to the map, in order. */
  received(): string[];
  /** How many chunk requests had been made when `file` was posted to the map. */
  requestsWhenPosted(file: string): number | undefined;
  errors(): SourceErrorInfo[];
  needed(): NeededChunks[];
  /** Answers the oldest open request with the file it asks for. */
  answerOldest(): void;
  /** Tells the scheduler that every chunk posted so far is on the GPU, as the map does after a frame. */
  uploadAll(): void;
}

/**
 * A scheduler over a cube served from `files`. Chunk requests get `answer` (the file itself
 * when not given); index.json is always served at once. With `uploads`, every chunk posted goes
 * on the GPU at the next turn of the event loop (else only by uploadAll).
 */
async function harness(t: TestContext, files: Map<string, Uint8Array>, options: Partial<SourceOptions>, answer?: (url: string, n: number) => Answer, uploads = false): Promise<Harness> {
  const serve = serveFiles(BASE, files);
  const fetch = installFakeFetch(t, (url, n) => (url.endsWith('index.json') ? serve(url) : (answer ?? serve)(url, n)));
  const opts: SourceOptions = { concurrency: 4, retries: 0, backoffMs: 0, maxBackoffMs: 0, marginRestMs: 0, ...options };
  const tree = await IndexTree.load(`${BASE}index.json`, opts);
  const posted: FromWorker[] = [];
  const requestsAtPost = new Map<string, number>();
  const scheduler = new ChunkScheduler(tree, opts, (msg) => {
    posted.push(msg);
    if (msg.type === 'chunk') requestsAtPost.set(msg.chunk.file, fetched().length);
    if (uploads && msg.type === 'chunk') setTimeout(() => scheduler.uploaded(msg.chunk.file), 0);
  });
  const name = (url: string): string => url.slice(BASE.length);
  const fetched = (): string[] => fetch.urls().map(name).filter((f) => f !== 'index.json');
  return {
    scheduler,
    fetch,
    fetched,
    times: (file) => fetched().filter((f) => f === file).length,
    statuses: (file) => posted.flatMap((m) => (m.type === 'status' && m.file === file ? [m.status] : [])),
    received: () => posted.flatMap((m) => (m.type === 'chunk' ? [m.chunk.file] : [])),
    requestsWhenPosted: (file) => requestsAtPost.get(file),
    errors: () => posted.flatMap((m) => (m.type === 'error' ? [m.error] : [])),
    needed: () => posted.flatMap((m) => (m.type === 'needed' ? [m] : [])),
    answerOldest: () => {
      const r = fetch.open()[0];
      assert.ok(r, 'a request is open');
      const a = serve(r.url);
      assert.ok(a !== 'hold');
      r.answer(a);
    },
    uploadAll: () => {
      for (const m of posted) if (m.type === 'chunk') scheduler.uploaded(m.chunk.file);
    },
  };
}

const sorted = (xs: string[]): string[] => [...xs].sort();

describe('the chunk scheduler', () => {
  test('ten chunks, four at a time, nearest the centre first; when the view moves, chunks it left are never fetched and the one in flight is aborted', async (t) => {
    const h = await harness(t, handMadeCube(row(10)).files, { concurrency: 4 }, () => 'hold');
    // Centre x = 44: c-4 under it, then c-3 (4 away), c-5 (6), c-2 (14), c-6 (16), c-1, c-7, c-0, c-8, c-9.
    const first = view(1, 0, 100, { centerX: 44 });
    h.scheduler.setView(first);
    h.scheduler.setView(first); // asked again: no chunk is requested twice
    await eventually(() => h.fetched().length === 4, 'four requests');
    await settle();
    assert.deepEqual(h.fetched(), ['c-4.bin', 'c-3.bin', 'c-5.bin', 'c-2.bin']);
    assert.deepEqual(h.statuses('c-6.bin'), [], 'queued: nothing posted yet');

    // The view moves right: c-0, c-1 and c-9 (queued) and c-2 (in flight) leave it.
    const c2 = h.fetch.requests.find((r) => r.url === `${BASE}c-2.bin`);
    h.scheduler.setView(view(2, 30.5, 89.5, { centerX: 60 }));
    assert.equal(c2?.signal?.aborted, true, 'the request for c-2 is aborted');
    assert.deepEqual(h.statuses('c-2.bin'), ['requested', 'not-requested']);
    assert.deepEqual(sorted(h.needed().at(-1)!.visible), ['c-3.bin', 'c-4.bin', 'c-5.bin', 'c-6.bin', 'c-7.bin', 'c-8.bin']);

    while (h.received().length < 6) {
      await eventually(() => h.fetch.open().length > 0, 'a request to answer');
      h.answerOldest();
      await eventually(() => h.fetch.open().length > 0 || h.received().length === 6, 'the chunk handled');
    }
    await settle();
    // The aborted slot went to c-6, under the new centre, then c-7 and c-8.
    assert.deepEqual(h.fetched(), ['c-4.bin', 'c-3.bin', 'c-5.bin', 'c-2.bin', 'c-6.bin', 'c-7.bin', 'c-8.bin']);
    assert.deepEqual(sorted(h.received()), ['c-3.bin', 'c-4.bin', 'c-5.bin', 'c-6.bin', 'c-7.bin', 'c-8.bin']);
    for (const gone of ['c-0.bin', 'c-1.bin', 'c-9.bin']) assert.deepEqual(h.statuses(gone), [], `${gone} never requested`);
    assert.equal(h.fetch.maxOpen, 4);
    assert.deepEqual(h.errors(), []);
  });

  test('a request frees its place once its body has come: the next one goes out while the chunk is still being checked and decoded', async (t) => {
    const h = await harness(t, handMadeCube(row(3)).files, { concurrency: 1 }, () => 'hold');
    h.scheduler.setView(view(1, 0, 30, { centerX: 5 }));
    await eventually(() => h.fetched().length === 1, 'one request');
    h.answerOldest();
    await eventually(() => h.received().length === 1, 'c-0 on its way to the map');
    // The decoding of c-0 took no place in the queue: c-1 was asked for before c-0 was posted.
    assert.equal(h.requestsWhenPosted('c-0.bin'), 2);
    assert.deepEqual(h.fetched(), ['c-0.bin', 'c-1.bin']);
    assert.equal(h.fetch.open().length, 1);
    h.answerOldest();
    await eventually(() => h.received().length === 2, 'c-1 on its way');
    h.answerOldest();
    await eventually(() => h.received().length === 3, 'c-2 on its way');
    assert.equal(h.fetch.maxOpen, 1, 'never more than one request on the network');
    assert.deepEqual(h.errors(), []);
  });

  test('what is on screen comes first, even when farther; the views ahead come in their order', async (t) => {
    const chunks: ChunkSpec[] = [
      { file: 'c-margin.bin', bbox: [10.5, 0, 0, 20, 10, 100] }, // just off screen, at the view's z
      { file: 'c-high.bin', bbox: [0, 0, 60, 10, 10, 100] }, // on screen, 50 steps above the view's z
      { file: 'c-low.bin', bbox: [0, 0, 0, 10, 10, 60] }, // on screen, at the view's z
      { file: 'c-ahead-near.bin', bbox: [30, 0, 0, 40, 10, 100] },
      { file: 'c-ahead-far.bin', bbox: [100, 0, 0, 110, 10, 100] },
    ];
    const h = await harness(t, handMadeCube(chunks).files, { concurrency: 1 }, undefined, true);
    // A flight to x 100..110 and then back to 0..40 (which also covers the view's own chunks).
    h.scheduler.setView(view(1, 0, 10, { centerX: 9.9, margin: [-10, 20], ahead: [ahead(100, 110), ahead(0, 40)] }));
    await eventually(() => h.received().length === 5, 'all five chunks');
    // The margin waits until what is on screen is on the GPU (a turn of the event loop here), so
    // the views ahead may go before it.
    const order = h.fetched();
    assert.deepEqual(order.slice(0, 2), ['c-low.bin', 'c-high.bin']);
    assert.deepEqual(order.filter((f) => f.startsWith('c-ahead')), ['c-ahead-far.bin', 'c-ahead-near.bin']);
    const n = h.needed()[0]!;
    assert.deepEqual(sorted(n.visible), ['c-high.bin', 'c-low.bin']);
    assert.deepEqual(n.margin, ['c-margin.bin']);
    assert.deepEqual(n.ahead, ['c-ahead-far.bin', 'c-ahead-near.bin']);
    assert.equal(n.indexComplete, true);
  });

  test('the margin waits until the view has rested: a new view before then starts the wait again', async (t) => {
    const rest = 800;
    const h = await harness(t, handMadeCube(row(4)).files, { concurrency: 4, marginRestMs: rest });
    const clock = fakeClock(t);
    // On screen: c-0 (x 0..9.5); the margin (to x 29) holds c-1, c-2.
    h.scheduler.setView(view(1, 0, 9.5, { centerX: 5, margin: [0, 29] }));
    await eventually(() => h.received().length === 1, 'the chunk on screen');
    h.uploadAll();
    clock.advance(rest / 2);
    await settle();
    assert.deepEqual(h.fetched(), ['c-0.bin'], 'the view has not rested yet');
    // The view moves a little (a new view, the same chunks): the rest starts again.
    h.scheduler.setView(view(2, 0.5, 9.5, { centerX: 5.5, margin: [0, 29] }));
    clock.advance(rest - 1);
    await settle();
    assert.deepEqual(h.fetched(), ['c-0.bin'], 'rested since the first view, not since the second');
    clock.advance(1);
    await eventually(() => h.fetched().length === 3, 'the margin requested once the second view has rested');
    assert.deepEqual(h.fetched().slice(1), ['c-1.bin', 'c-2.bin']);
  });

  test('where the map\'s frames take longer than the rest (a slow device), the margin waits one and a half frames; a rest of 0 waits for nothing', async (t) => {
    const rest = 300;
    const frameMs = 700;
    const h = await harness(t, handMadeCube(row(4)).files, { concurrency: 4, marginRestMs: rest });
    const clock = fakeClock(t);
    // On screen: c-0 (x 0..9.5); the margin (to x 29) holds c-1, c-2.
    h.scheduler.setView(view(1, 0, 9.5, { centerX: 5, margin: [0, 29], frameMs }));
    await eventually(() => h.received().length === 1, 'the chunk on screen');
    h.uploadAll();
    clock.advance(1.5 * frameMs - 1);
    await settle();
    assert.deepEqual(h.fetched(), ['c-0.bin'], 'rested more than marginRestMs, less than one and a half frames');
    clock.advance(1);
    await eventually(() => h.fetched().length === 3, 'the margin requested after one and a half frames');
    assert.deepEqual(h.fetched().slice(1), ['c-1.bin', 'c-2.bin']);

    const none = await harness(t, handMadeCube(row(4)).files, { concurrency: 4, marginRestMs: 0 });
    none.scheduler.setView(view(1, 0, 9.5, { centerX: 5, margin: [0, 29], frameMs }));
    await eventually(() => none.received().length === 1, 'the chunk on screen');
    none.uploadAll();
    await eventually(() => none.fetched().length === 3, 'the margin requested without the clock moving');
  });

  test('the margin waits until every chunk on screen is on the GPU, even with requests to spare; a flight\'s path does not wait', async (t) => {
    const h = await harness(t, handMadeCube(row(7)).files, { concurrency: 4 }, () => 'hold');
    // On screen: c-0 and c-1 (x 0..19.5); the margin (to x 50) holds c-2, c-3, c-4; a view ahead c-6.
    h.scheduler.setView(view(1, 0, 19.5, { centerX: 9, margin: [0, 50], ahead: [ahead(60.5, 69.5)] }));
    await eventually(() => h.fetched().length === 3, 'three requests');
    await settle();
    assert.deepEqual(h.fetched(), ['c-0.bin', 'c-1.bin', 'c-6.bin'], 'what is on screen and the path ahead, though one more could go');
    h.answerOldest();
    await eventually(() => h.received().length === 1, 'the first chunk');
    await settle();
    assert.equal(h.fetched().length, 3, 'one on-screen chunk still coming: the margin still waits');
    h.answerOldest();
    await eventually(() => h.received().length === 2, 'the second chunk');
    await settle();
    assert.equal(h.fetched().length, 3, 'both on-screen chunks have come, not yet on the GPU: the margin still waits');
    h.uploadAll();
    await eventually(() => h.fetched().length === 6, 'the margin requested');
    assert.deepEqual(h.fetched().slice(3), ['c-2.bin', 'c-3.bin', 'c-4.bin']);
    assert.equal(h.fetch.maxOpen, 4);
  });

  test('the margin starts when the last chunk on screen fails its check, with nothing else to wait for', async (t) => {
    const { files } = handMadeCube(row(3));
    files.set('c-0.bin', squareChunk(7)); // a chunk, but not the one the index names
    const h = await harness(t, files, { concurrency: 1 }, undefined, true);
    // On screen c-0 only (no floor in this cube); c-1 and c-2 are the margin.
    h.scheduler.setView(view(1, 0, 9.5, { centerX: 5, margin: [0, 30] }));
    await eventually(() => h.errors().length === 1, 'c-0 refused');
    assert.equal(h.errors()[0]!.kind, 'corrupt');
    await eventually(() => h.received().length === 2, 'the margin fetched');
    assert.deepEqual(h.fetched(), ['c-0.bin', 'c-1.bin', 'c-2.bin']);
  });

  test('a chunk goes requested, received, on the GPU; evicted while in view it is fetched again, evicted out of view it waits until the view comes back', async (t) => {
    const h = await harness(t, handMadeCube(row(2)).files, { concurrency: 2 });
    const both = view(1, 0, 20, { centerX: 5 });
    h.scheduler.setView(both);
    await eventually(() => h.received().length === 2, 'both chunks');
    assert.deepEqual(h.statuses('c-0.bin'), ['requested', 'received']);
    h.scheduler.uploaded('c-0.bin');
    h.scheduler.uploaded('c-1.bin');
    assert.deepEqual(h.statuses('c-0.bin'), ['requested', 'received', 'gpu']);

    h.scheduler.evicted(['c-0.bin']);
    await eventually(() => h.received().length === 3, 'c-0 again');
    assert.deepEqual(h.statuses('c-0.bin'), ['requested', 'received', 'gpu', 'evicted', 'requested', 'received']);
    assert.equal(h.times('c-0.bin'), 2);

    h.scheduler.setView(view(2, 0, 9, { centerX: 5 }));
    h.scheduler.evicted(['c-1.bin']);
    await settle();
    assert.deepEqual(h.statuses('c-1.bin'), ['requested', 'received', 'gpu', 'evicted']);
    assert.equal(h.times('c-1.bin'), 1, 'not needed: not fetched again');
    h.scheduler.setView(view(3, 0, 20, { centerX: 5 }));
    await eventually(() => h.received().length === 4, 'c-1 again');
    assert.equal(h.times('c-1.bin'), 2);
    // The first two were fetched together and may come in either order (each is hashed by crypto.subtle, off the thread).
    assert.deepEqual(sorted(h.received().slice(0, 2)), ['c-0.bin', 'c-1.bin']);
    assert.deepEqual(h.received().slice(2), ['c-0.bin', 'c-1.bin']);
  });

  test('failures: a 404 and a corrupt chunk fail at once, a 503 after its retries; each is reported, and tried again only when the view comes back', async (t) => {
    const { files } = handMadeCube(row(3));
    files.set('c-1.bin', squareChunk(7)); // a chunk, but not the one the index names
    const serve = serveFiles(BASE, files);
    const h = await harness(t, files, { concurrency: 3, retries: 2 }, (url, n) => {
      if (url.endsWith('c-0.bin') && n === 1) return status(404);
      if (url.endsWith('c-2.bin')) return status(503);
      return serve(url);
    });
    const all = view(1, 0, 30, { centerX: 15 });
    h.scheduler.setView(all);
    await eventually(() => h.errors().length === 3, 'three errors');
    const byFile = new Map(h.errors().map((e) => [e.file, e]));
    assert.deepEqual(byFile.get('c-0.bin'), { kind: 'http', status: 404, file: 'c-0.bin', url: `${BASE}c-0.bin`, message: `HTTP 404 for ${BASE}c-0.bin (after 1 attempt)` });
    assert.equal(byFile.get('c-1.bin')?.kind, 'corrupt');
    assert.match(byFile.get('c-1.bin')?.message ?? '', /^c-1\.bin: SHA-256 .* does not match the index/);
    assert.equal(byFile.get('c-2.bin')?.status, 503);
    assert.match(byFile.get('c-2.bin')?.message ?? '', /\(after 3 attempts\)$/);
    for (const f of ['c-0.bin', 'c-1.bin', 'c-2.bin']) assert.deepEqual(h.statuses(f), ['requested', 'failed'], f);
    assert.deepEqual([h.times('c-0.bin'), h.times('c-1.bin'), h.times('c-2.bin')], [1, 1, 3]);

    h.scheduler.setView({ ...all, seq: 2 });
    await settle();
    assert.equal(h.fetched().length, 5, 'the same view again: nothing is tried again');

    h.scheduler.setView(view(3, 100, 110, { centerX: 105 }));
    h.scheduler.setView({ ...all, seq: 4 });
    await eventually(() => h.received().length === 1, 'c-0 on its second try');
    await eventually(() => h.errors().length === 5, 'c-1 and c-2 failing again');
    assert.deepEqual(h.received(), ['c-0.bin']);
    assert.deepEqual(h.statuses('c-0.bin'), ['requested', 'failed', 'not-requested', 'requested', 'received']);
  });

  test('the network back (retryFailed): chunks that failed for want of it (a network failure, a 503 after its retries) are asked for again in the same view and come; a 404 and a corrupt chunk are not', async (t) => {
    const { files } = handMadeCube(row(4));
    files.set('c-1.bin', squareChunk(7)); // a chunk, but not the one the index names
    const serve = serveFiles(BASE, files);
    let down = true;
    const h = await harness(t, files, { concurrency: 4, retries: 1 }, (url) => {
      if (url.endsWith('c-0.bin')) return status(404);
      if (down && url.endsWith('c-2.bin')) return networkError();
      if (down && url.endsWith('c-3.bin')) return status(503);
      return serve(url);
    });
    const all = view(1, 0, 40, { centerX: 20 });
    h.scheduler.setView(all);
    await eventually(() => h.errors().length === 4, 'four errors');
    assert.deepEqual([h.times('c-0.bin'), h.times('c-1.bin'), h.times('c-2.bin'), h.times('c-3.bin')], [1, 1, 2, 2]);

    down = false;
    const views = h.needed().length;
    h.scheduler.retryFailed();
    assert.equal(h.needed().length, views + 1, 'the view asked again');
    await eventually(() => h.received().length === 2, 'c-2 and c-3 on their next try');
    await settle();
    assert.deepEqual(sorted(h.received()), ['c-2.bin', 'c-3.bin']);
    for (const f of ['c-2.bin', 'c-3.bin']) assert.deepEqual(h.statuses(f), ['requested', 'failed', 'not-requested', 'requested', 'received'], f);
    assert.deepEqual([h.times('c-0.bin'), h.times('c-1.bin')], [1, 1], 'a 404 and a corrupt chunk are not asked for again');
    assert.deepEqual(h.statuses('c-0.bin'), ['requested', 'failed']);
    assert.equal(h.errors().length, 4, 'no new error');
    assert.equal(h.needed().at(-1)!.seq, 1, 'the same view, unmoved');

    h.scheduler.retryFailed();
    await settle();
    assert.equal(h.fetched().length, 8, 'once they came, nothing is asked for again');
  });

  test('a fetch begun while the network was down and failing after it came back (retryFailed) is asked again at once, without an error', async (t) => {
    const h = await harness(t, handMadeCube(row(1)).files, { concurrency: 1 }, () => 'hold');
    h.scheduler.setView(view(1, 0, 10, { centerX: 5 }));
    await eventually(() => h.fetch.open().length === 1, 'c-0 asked for');
    h.scheduler.retryFailed();
    h.fetch.open()[0]!.answer(networkError());
    await eventually(() => h.times('c-0.bin') === 2, 'c-0 asked for again');
    h.answerOldest();
    await eventually(() => h.received().length === 1, 'c-0');
    assert.deepEqual(h.statuses('c-0.bin'), ['requested', 'not-requested', 'requested', 'received']);
    assert.deepEqual(h.errors(), []);
  });

  test('a chunk left and taken back before its aborted request ends is fetched anew and arrives once', async (t) => {
    const h = await harness(t, handMadeCube(row(2)).files, { concurrency: 3 }, () => 'hold');
    const left = view(1, 0, 9, { centerX: 5 });
    h.scheduler.setView(left);
    await eventually(() => h.fetched().length === 1, 'c-0 requested');
    h.scheduler.setView(view(2, 11, 20, { centerX: 15 }));
    h.scheduler.setView({ ...left, seq: 3 });
    await eventually(() => h.times('c-0.bin') === 2, 'c-0 requested again');
    await settle();
    assert.deepEqual(h.fetch.open().map((r) => r.url), [`${BASE}c-0.bin`], 'the first request for c-0 and the one for c-1 were aborted');
    h.answerOldest();
    await eventually(() => h.received().length === 1, 'c-0 arrives');
    await settle();
    assert.deepEqual(h.received(), ['c-0.bin']);
    assert.deepEqual(h.statuses('c-0.bin'), ['requested', 'not-requested', 'requested', 'received']);
    assert.equal(h.times('c-0.bin'), 2);
  });

  test('chunks under a sub-index not loaded yet are fetched once it arrives', async (t) => {
    const { files } = twoLevelCube();
    const serve = serveFiles(BASE, files);
    const h = await harness(t, files, {}, (url) => (url.endsWith('i-b.json') ? 'hold' : serve(url)));
    h.scheduler.setView(view(1, 0, 20, { centerX: 10 }));
    await eventually(() => h.received().length === 1, 'c-a');
    assert.deepEqual(h.needed().map((n) => [n.seq, n.indexComplete, n.visible]), [[1, false, ['c-a.bin']]]);
    h.answerOldest(); // i-b.json
    await eventually(() => h.received().length === 2, 'c-b');
    assert.deepEqual(h.needed().map((n) => [n.seq, n.indexComplete, sorted(n.visible)]), [[1, false, ['c-a.bin']], [1, true, ['c-a.bin', 'c-b.bin']]]);
    assert.deepEqual(sorted(h.fetched()), ['c-a.bin', 'c-b.bin', 'i-b.json'], 'each once');
  });
});

describe('floor chunks (docs/FORMAT.md, "Floor chunks")', () => {
  // The cube's three chunks along x (0..30, z 0..100), and one floor chunk over all of them, below
  // z 0.5; with `subIndex`, the cube's chunks listed in that sub-index file (as the build writes it).
  const cube = (subIndex?: string): Map<string, Uint8Array> => handMadeCube(row(3), { top: 0.5, chunks: [{ file: 'c-floor.bin', bbox: [0, 0, 0, 30, 10, 0.5] }] }, subIndex).files;
  const at = (seq: number, zMax: number): ViewRequest => ({ ...view(seq, 0, 30, { centerX: 15 }), zMin: 0, zMax });
  // Beyond twice the base scale (z 83 in the hand-made cube's scale table): no interim floor.
  const high = (seq: number): ViewRequest => ({ ...view(seq, 0, 30, { centerX: 15 }), zMin: 90, zMax: 90, z: 90 });
  const CUBE = ['c-0.bin', 'c-1.bin', 'c-2.bin'];
  /** Three floor chunks along x below z 0.5 (b-0 .. b-2); with `subIndex`, listed in a sub-index file of that name. */
  const floorRow = (subIndex?: string): { top: number; chunks: ChunkSpec[]; subIndex?: string } => ({
    top: 0.5,
    chunks: [0, 1, 2].map((i): ChunkSpec => ({ file: `b-${i}.bin`, bbox: [10 * i, 0, 0, 10 * i + 10, 10, 0.5] })),
    ...(subIndex ? { subIndex } : {}),
  });

  test('a view below the floor top shows the floor chunk, fetched first, with the cube\'s chunks as its margin; a view reaching the top, the cube\'s', async (t) => {
    const h = await harness(t, cube(), { concurrency: 1 }, undefined, true);
    h.scheduler.setView(at(1, 0.49));
    await eventually(() => h.received().length === 4, 'the floor chunk, then the margin');
    await settle();
    assert.deepEqual(h.fetched()[0], 'c-floor.bin');
    assert.deepEqual(sorted(h.fetched().slice(1)), CUBE);
    const n = h.needed().at(-1)!;
    assert.deepEqual([n.visible, sorted(n.margin)], [['c-floor.bin'], CUBE]);
    h.scheduler.setView(at(2, 0.5));
    await settle();
    assert.deepEqual([h.needed().at(-1)!.visible.sort(), h.needed().at(-1)!.margin], [CUBE, []]);
    assert.equal(h.fetched().length, 4, 'nothing fetched twice');
  });

  test('the map\'s head start on a first view names the floor chunks the scheduler shows, in its order; above the floor, the sub-index file', async (t) => {
    // Three floor chunks along x; the view over x 12..30, its centre at 25: b-2 under it, then b-1.
    const floor = floorRow();
    const { files } = handMadeCube(row(3), floor, 'i-cube.json');
    const index = parseIndex(JSON.parse(new TextDecoder().decode(files.get('index.json'))));
    const first: ViewRequest = { ...view(1, 12, 30, { centerX: 25 }), zMin: 0, zMax: 0.49 };
    const h = await harness(t, files, { concurrency: 1 }, undefined, true);
    h.scheduler.setView(first);
    await eventually(() => h.received().length === 2, 'the floor chunks on screen');
    assert.deepEqual(firstViewFiles(index, first), ['b-2.bin', 'b-1.bin']);
    assert.deepEqual(h.fetched().slice(0, 2), ['b-2.bin', 'b-1.bin'], 'the scheduler\'s first requests');
    assert.deepEqual(sorted(h.needed()[0]!.visible), ['b-1.bin', 'b-2.bin']);
    // The cube's chunks under the view come after them, as the margin: let them end here.
    await eventually(() => h.received().length === 4, 'the margin');
    await settle();
    assert.deepEqual(firstViewFiles(index, { ...first, zMax: 0.5 }), ['b-2.bin', 'b-1.bin', 'i-cube.json'], 'a view reaching the floor\'s top: its floor on screen (the interim floor), then the sub-index file that lists the cube\'s chunks');
    assert.deepEqual(firstViewFiles(index, { ...first, zMin: 90, zMax: 90, z: 90 }), ['i-cube.json'], 'a view beyond twice the base scale: the sub-index file alone');
    const noFloor = parseIndex(JSON.parse(new TextDecoder().decode(handMadeCube(row(3)).files.get('index.json'))));
    assert.deepEqual(firstViewFiles(noFloor, first), ['c-2.bin', 'c-1.bin'], 'a cube without floor chunks: its chunks on screen, nearest first');
  });

  test('a floor too large for index.json: the head start names the floor\'s sub-index file, which the scheduler asks for first too', async (t) => {
    const floor = floorRow('i-floor.json');
    const { files } = handMadeCube(row(3), floor, 'i-cube.json');
    const index = parseIndex(JSON.parse(new TextDecoder().decode(files.get('index.json'))));
    const first: ViewRequest = { ...view(1, 12, 30, { centerX: 25 }), zMin: 0, zMax: 0.49 };
    assert.deepEqual(firstViewFiles(index, first), ['i-floor.json'], 'at the floor: its sub-index file, which lists the floor chunks');
    assert.deepEqual(firstViewFiles(index, { ...first, zMax: 0.5 }), ['i-floor.json', 'i-cube.json'], 'just above it: the interim floor\'s sub-index file and the cube\'s');
    assert.deepEqual(firstViewFiles(index, { ...first, zMin: 90, zMax: 90, z: 90 }), ['i-cube.json'], 'beyond twice the base scale: no floor');
    const h = await harness(t, files, { concurrency: 1 }, undefined, true);
    h.scheduler.setView(first);
    await eventually(() => h.received().length === 2, 'the floor chunks on screen');
    assert.deepEqual(h.fetched().slice(0, 3), ['i-floor.json', 'b-2.bin', 'b-1.bin'], 'the scheduler\'s first requests: the floor\'s sub-index file, then the floor chunks it lists, nearest first; the cube\'s sub-index file waits for them');
    // The cube's sub-index file and chunks come after them, as the margin: let them end here.
    await eventually(() => h.received().length === 4, 'the margin');
    await settle();
    assert.deepEqual(h.fetched().slice(3, 4), ['i-cube.json']);
  });

  test('a floor sub-index file that fails: the view draws from the cube\'s chunks, which hold the floor too, and is not asked for again', async (t) => {
    const floor = floorRow('i-floor.json');
    const { files } = handMadeCube(row(3), floor, 'i-cube.json');
    const serve = serveFiles(BASE, files);
    const h = await harness(t, files, { concurrency: 1 }, (url) => (url.endsWith('i-floor.json') ? status(404) : serve(url)), true);
    const first = { ...view(1, 12, 30, { centerX: 25 }), zMin: 0, zMax: 0.49 };
    h.scheduler.setView(first);
    await eventually(() => h.received().length === 2, 'the cube\'s chunks under the view');
    assert.equal(h.errors()[0]?.status, 404);
    assert.deepEqual(h.fetched().slice(0, 2), ['i-floor.json', 'i-cube.json']);
    const last = h.needed().at(-1)!;
    assert.deepEqual([sorted(last.visible), last.indexComplete], [['c-1.bin', 'c-2.bin'], true], 'the cube\'s chunks on screen, the list whole');
    h.scheduler.setView({ ...first, seq: 2 });
    await settle();
    assert.equal(h.times('i-floor.json'), 1, 'not asked for again');
  });

  test('a floor sub-index file that failed for want of a network is taken again once it is back (retryFailed): the view goes back to the floor; one refused with a 404 is not', async (t) => {
    for (const [answer, again] of [[networkError, true], [() => status(404), false]] as const) {
      await t.test(again ? 'a network failure' : 'a 404', async (tt) => {
        const floor = floorRow('i-floor.json');
        const { files } = handMadeCube(row(3), floor);
        const serve = serveFiles(BASE, files);
        let down = true;
        const h = await harness(tt, files, { concurrency: 1 }, (url) => (down && url.endsWith('i-floor.json') ? answer() : serve(url)), true);
        const first = { ...view(1, 12, 30, { centerX: 25 }), zMin: 0, zMax: 0.49 };
        h.scheduler.setView(first);
        await eventually(() => h.received().length === 2, 'the cube\'s chunks under the view');
        assert.deepEqual(sorted(h.needed().at(-1)!.visible), ['c-1.bin', 'c-2.bin']);

        down = false;
        h.scheduler.evicted(['c-1.bin', 'c-2.bin']); // gone from the GPU: the floor costs less again
        h.scheduler.retryFailed();
        await settle();
        await eventually(() => h.fetch.open().length === 0, 'nothing in flight');
        await settle();
        assert.equal(h.times('i-floor.json'), again ? 2 : 1);
        assert.deepEqual(sorted(h.needed().at(-1)!.visible), again ? ['b-1.bin', 'b-2.bin'] : ['c-1.bin', 'c-2.bin'], 'on screen');
      });
    }
  });

  test('a floor chunk that failed for want of a network is chosen again once it is back (retryFailed); one refused with a 404 is not', async (t) => {
    for (const [answer, again] of [[networkError, true], [() => status(404), false]] as const) {
      await t.test(again ? 'a network failure' : 'a 404', async (tt) => {
        const serve = serveFiles(BASE, cube());
        let down = true;
        const h = await harness(tt, cube(), {}, (url) => (down && url.endsWith('c-floor.bin') ? answer() : serve(url)), true);
        h.scheduler.setView(at(1, 0));
        await eventually(() => h.received().length === 3, 'the cube\'s chunks');
        down = false;
        h.scheduler.evicted(CUBE);
        h.scheduler.retryFailed();
        await settle();
        await eventually(() => h.fetch.open().length === 0, 'nothing in flight');
        await settle();
        assert.deepEqual(sorted(h.needed().at(-1)!.visible), again ? ['c-floor.bin'] : CUBE);
        assert.equal(h.times('c-floor.bin'), again ? 2 : 1);
      });
    }
  });

  test('a floor sub-index file that fails, with the cube\'s tree in index.json: the view is asked again at once, and draws from the cube\'s chunks', async (t) => {
    const floor = floorRow('i-floor.json');
    const { files } = handMadeCube(row(3), floor);
    const serve = serveFiles(BASE, files);
    const h = await harness(t, files, { concurrency: 1 }, (url) => (url.endsWith('i-floor.json') ? status(404) : serve(url)), true);
    h.scheduler.setView({ ...view(1, 12, 30, { centerX: 25 }), zMin: 0, zMax: 0.49 });
    await eventually(() => h.received().length === 2, 'the cube\'s chunks under the view');
    const last = h.needed().at(-1)!;
    assert.deepEqual([sorted(last.visible), last.indexComplete], [['c-1.bin', 'c-2.bin'], true]);
    assert.equal(h.times('i-floor.json'), 1);
  });

  test('a margin of the cube\'s chunks waits for the floor chunk on screen', async (t) => {
    const h = await harness(t, cube(), { concurrency: 4 }, () => 'hold');
    h.scheduler.setView(at(1, 0));
    await eventually(() => h.fetched().length === 1, 'the floor chunk requested');
    await settle();
    assert.deepEqual(h.fetched(), ['c-floor.bin'], 'the cube\'s chunks wait');
  });

  test('the cube\'s sub-index file waits for the floor chunk on screen; then it and the cube\'s chunks come as the margin', async (t) => {
    const files = cube('i-cube.json');
    const h = await harness(t, files, { concurrency: 4 }, () => 'hold');
    h.scheduler.setView(at(1, 0));
    await eventually(() => h.fetched().length === 1, 'the floor chunk requested');
    await settle();
    assert.deepEqual(h.fetched(), ['c-floor.bin'], 'nothing else while it comes');
    assert.deepEqual(h.needed().at(-1)!.visible, ['c-floor.bin']);
    h.answerOldest();
    await eventually(() => h.received().length === 1, 'the floor chunk');
    await settle();
    assert.equal(h.fetched().length, 1, 'the sub-index file waits for the floor chunk to be on the GPU');
    h.uploadAll();
    await eventually(() => h.fetched().length === 2, 'the sub-index file');
    assert.equal(h.fetched()[1], 'i-cube.json');
    h.answerOldest();
    await eventually(() => h.fetched().length === 5, 'the cube\'s chunks');
    assert.deepEqual(sorted(h.fetched().slice(2)), CUBE);
    assert.deepEqual(sorted(h.needed().at(-1)!.margin), CUBE);
  });

  test('with the floor chunk on screen failing, the cube\'s sub-index file is asked for at once, and its chunks drawn instead', async (t) => {
    const files = cube('i-cube.json');
    const serve = serveFiles(BASE, files);
    const h = await harness(t, files, {}, (url) => (url.endsWith('c-floor.bin') ? status(404) : serve(url)), true);
    h.scheduler.setView(at(1, 0));
    await eventually(() => h.received().length === 3, 'the cube\'s chunks');
    assert.deepEqual(h.fetched().slice(0, 2), ['c-floor.bin', 'i-cube.json']);
    assert.deepEqual(sorted(h.needed().at(-1)!.visible), CUBE);
  });

  test('a view above the floor asks for the cube\'s sub-index file at once', async (t) => {
    const files = cube('i-cube.json');
    const h = await harness(t, files, { concurrency: 4 }, () => 'hold');
    h.scheduler.setView(high(1));
    await eventually(() => h.fetched().length === 1, 'a request');
    assert.deepEqual(h.fetched(), ['i-cube.json']);
  });

  test('back at the floor with the cube\'s chunks here, the view takes them and fetches nothing', async (t) => {
    const h = await harness(t, cube(), {}, undefined, true);
    h.scheduler.setView(high(1));
    await eventually(() => h.received().length === 3, 'the cube\'s chunks');
    await settle();
    h.scheduler.setView(at(2, 0));
    await settle();
    assert.deepEqual(sorted(h.needed().at(-1)!.visible), CUBE);
    assert.deepEqual(sorted(h.fetched()), CUBE, 'the floor chunk is never fetched');
  });

  test('a floor chunk that fails gives way to the cube\'s chunks at once, and is not chosen again', async (t) => {
    const serve = serveFiles(BASE, cube());
    const h = await harness(t, cube(), {}, (url) => (url.endsWith('c-floor.bin') ? status(404) : serve(url)), true);
    h.scheduler.setView(at(1, 0));
    await eventually(() => h.received().length === 3, 'the cube\'s chunks, with no new view');
    await settle();
    assert.deepEqual(h.errors().map((e) => e.file), ['c-floor.bin']);
    assert.deepEqual([sorted(h.needed().at(-1)!.visible), h.needed().at(-1)!.seq], [CUBE, 1]);
    // The cube's chunks leave, then the view comes back: still the cube's.
    h.scheduler.evicted(CUBE);
    h.scheduler.setView(at(2, 0));
    await eventually(() => h.received().length === 6, 'the cube\'s chunks again');
    assert.equal(h.times('c-floor.bin'), 1);
  });

  test('a first view just above the floor\'s top fetches its floor on screen first, as its interim floor, then its own chunks; once those have been on the GPU, no view has one', async (t) => {
    const h = await harness(t, cube('i-cube.json'), { concurrency: 1 }, undefined, true);
    h.scheduler.setView(at(1, 1));
    await eventually(() => h.received().length === 4, 'the floor chunk and the cube\'s');
    await settle();
    assert.deepEqual(sorted(h.fetched().slice(0, 2)), ['c-floor.bin', 'i-cube.json'], 'the floor chunk before any of the cube\'s, beside the sub-index file that lists them');
    assert.deepEqual(sorted(h.fetched().slice(2)), CUBE);
    const n = h.needed().at(-1)!;
    assert.deepEqual([n.interim, sorted(n.visible)], [['c-floor.bin'], CUBE], 'the floor is the interim, the cube\'s chunks on screen');
    await eventually(() => CUBE.every((f) => h.statuses(f).includes('gpu')), 'the cube\'s chunks on the GPU');
    h.scheduler.setView(at(2, 2));
    await settle();
    assert.deepEqual(h.needed().at(-1)!.interim, [], 'the view\'s own chunks have been on the GPU');
    assert.equal(h.fetched().length, 5, 'nothing fetched twice: four chunks and the sub-index file');
  });

  test('the interim floor stays while the view\'s sub-index file is still coming, though the floor is on the GPU', async (t) => {
    const files = cube('i-cube.json');
    const serve = serveFiles(BASE, files);
    const h = await harness(t, files, { concurrency: 4 }, (url) => (url.endsWith('i-cube.json') ? 'hold' : serve(url)), true);
    h.scheduler.setView(at(1, 1));
    await eventually(() => h.statuses('c-floor.bin').includes('gpu'), 'the floor on the GPU');
    h.answerOldest();
    await eventually(() => h.needed().at(-1)!.visible.length === 3, 'the view asked again with the cube\'s chunks');
    assert.deepEqual(h.needed().at(-1)!.interim, ['c-floor.bin'], 'none of the view\'s own chunks had been on screen');
  });

  test('no interim floor for a view beyond twice the base scale, or when its floor is more than half the cube\'s bytes on screen still to fetch', async (t) => {
    const h = await harness(t, cube(), { concurrency: 1 }, () => 'hold');
    h.scheduler.setView(high(1));
    assert.deepEqual(h.needed().at(-1)!.interim, []);
    // A flat slice just above the floor's top, the cube's three chunks on screen and the floor's
    // one: with two of the cube's here, the floor is more than half of what is left to fetch.
    const index = parseIndex(JSON.parse(new TextDecoder().decode(cube().get('index.json'))));
    const v: ViewRequest = { ...at(1, 1), zMin: 1, zMax: 1, z: 1 };
    const under = queryIndex(index.floor!.root, underView(v.visible), () => undefined);
    const cubeQuery = queryIndex(index.root, { ground: v.margin, zMin: v.zMin, zMax: v.zMax }, () => undefined);
    const bytes = (leaves: readonly ChunkLeaf[], box: QueryBox): number => leaves.reduce((s, l) => s + (boxMeets(l.bbox, box) ? l.bytes : 0), 0);
    const floorBytes = bytes(under.leaves, underView(v.visible)), cubeBytes = bytes(cubeQuery.leaves, { ground: v.visible, zMin: 1, zMax: 1 });
    assert.ok(floorBytes > 0 && floorBytes <= INTERIM_SHARE * cubeBytes, `the floor (${floorBytes} bytes) is at most half the cube's (${cubeBytes})`);
    assert.deepEqual(interimFloor(index, v, under, cubeQuery, bytes).map((l) => l.file), ['c-floor.bin']);
    const lastOnly = (leaves: readonly ChunkLeaf[], box: QueryBox): number => bytes(leaves.filter((l) => l.file !== 'c-0.bin' && l.file !== 'c-1.bin'), box);
    assert.ok(floorBytes > INTERIM_SHARE * lastOnly(cubeQuery.leaves, { ground: v.visible, zMin: 1, zMax: 1 }));
    assert.deepEqual(interimFloor(index, v, under, cubeQuery, lastOnly), [], 'two of the cube\'s three chunks here');
  });
});
