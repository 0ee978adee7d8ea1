// Which chunks stay on the GPU, over a fake worker and a fake GPU: a view goes to the worker
// once (again when the views ahead change), chunks go up within the per-frame byte budget and
// in arrival order, a chunk the current view no longer needs is dropped, not uploaded, and the
// view is complete (loaded) and settled only for the view its answer is for.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import type { Box3 } from '../../../format/cube-index.js';
import type { ChunkPayload, ChunkStatus, NeededChunks, ViewRequest } from '../source/worker-protocol.js';
import { ChunkResidency, type ChunkRequests, type GpuChunks, type ViewQuery } from './chunk-residency.js';

const BOX: Box3 = [0, 0, 0, 10, 10, 100];

/** A chunk of `bytes` vertex bytes and no triangles. */
const chunk = (file: string, bytes = 100, bbox = BOX): ChunkPayload => ({
  kind: 'surfaces', file, bbox, buffer: new ArrayBuffer(0), vertexCount: 0, triangleCount: 0, originX: 0, originY: 0,
  vertexByteOffset: 0, vertexByteLength: bytes, indexByteOffset: 0, indexSize: 2,
  blocks: { cellBox: new Float32Array(0), cellBlocks: Uint32Array.of(0), zLow: new Float32Array(0), first: Uint32Array.of(0) }, verified: true,
});

const answer = (seq: number, visible: string[], margin: string[] = [], o: Partial<NeededChunks> = {}): NeededChunks => ({ seq, visible, margin, ahead: [], interim: [], indexComplete: true, queryMs: 1, ...o });

const query: ViewQuery = { view: { centerX: 5, centerY: 5, resolution: 1, width: 10, height: 10 }, visible: [0, 0, 10, 10], margin: [-2, -2, 12, 12], zMin: 0, zMax: 50, z: 10 };
const drawn = { ground: query.visible, zMin: 0, zMax: 50 };

function harness(budget = 250) {
  const views: ViewRequest[] = [];
  const uploadedToWorker: string[] = [];
  const evicted: string[] = [];
  const failed = new Set<string>();
  const onGpu = new Set<string>();
  const data: string[] = [];
  const source: ChunkRequests = {
    setView: (v) => views.push(v),
    uploaded: (f) => uploadedToWorker.push(f),
    evicted: (fs) => evicted.push(...fs),
    status: (f): ChunkStatus => (failed.has(f) ? 'failed' : onGpu.has(f) ? 'gpu' : 'requested'),
    handingOver: false,
  };
  const gpu: GpuChunks = { upload: (c) => onGpu.add(c.file), evict: () => [], store: { has: (f) => onGpu.has(f) } };
  const residency = new ChunkResidency(source, gpu, budget, (f) => data.push(f));
  return { residency, views, uploadedToWorker, evicted, failed, onGpu, data };
}

describe('chunk residency', () => {
  test('a view is sent once, and again when the views ahead change', () => {
    const h = harness();
    const aheadQuery = (): ViewQuery => ({ ...query, margin: [20, 20, 30, 30], z: 12 });
    h.residency.request(1, query, aheadQuery);
    h.residency.request(1, query, aheadQuery);
    assert.equal(h.views.length, 1);
    assert.deepEqual(h.views[0]?.ahead, []);
    h.residency.prefetch([{ x: 25, y: 25, scale: 1000 }]);
    h.residency.request(1, query, aheadQuery);
    assert.equal(h.views.length, 2);
    assert.deepEqual(h.views[1]?.ahead, [{ box: [20, 20, 30, 30], zMin: 0, zMax: 50, centerX: 25, centerY: 25, z: 12 }]);
    h.residency.request(2, query, aheadQuery);
    assert.equal(h.views.length, 3);
  });

  test('uploads in arrival order within the byte budget, the rest a frame later', () => {
    const h = harness(250);
    h.residency.answer(answer(1, ['a', 'b', 'c']));
    for (const f of ['a', 'b', 'c']) h.residency.arrived(chunk(f));
    assert.equal(h.residency.upload(1, 1, drawn), true, 'a chunk on screen changes the picture');
    assert.deepEqual(h.data, ['a', 'b', 'c'], 'each upload is reported');
    assert.deepEqual([...h.onGpu], ['a', 'b', 'c'], '100 + 100 < 250: the third goes up too, then the budget is spent');
    const h2 = harness(150);
    h2.residency.answer(answer(1, ['a', 'b', 'c']));
    for (const f of ['a', 'b', 'c']) h2.residency.arrived(chunk(f));
    h2.residency.upload(1, 1, drawn);
    assert.deepEqual([...h2.onGpu], ['a', 'b']);
    assert.ok(h2.residency.hasPending);
    assert.equal(h2.residency.loaded(1), false, 'not loaded while chunks wait');
    h2.residency.upload(2, 1, drawn);
    assert.deepEqual([...h2.onGpu], ['a', 'b', 'c']);
    assert.deepEqual(h2.uploadedToWorker, ['a', 'b', 'c']);
    assert.equal(h2.residency.loaded(1), true);
  });

  test('a chunk the current view no longer needs is dropped; one off screen leaves the picture as it is', () => {
    const h = harness();
    h.residency.answer(answer(1, ['a'], ['m']));
    h.residency.arrived(chunk('gone'));
    h.residency.arrived(chunk('m', 100, [50, 50, 0, 60, 60, 100]));
    assert.equal(h.residency.upload(1, 1, drawn), false, 'the margin chunk is off screen');
    assert.deepEqual([...h.onGpu], ['m']);
    assert.deepEqual(h.evicted, ['gone']);
  });

  test('an interim floor chunk is kept and changes the picture though it lies below the view\'s z range; it is not part of what the view shows', () => {
    const h = harness();
    h.residency.answer(answer(1, ['a'], [], { interim: ['floor'] }));
    h.residency.arrived(chunk('floor', 100, [0, 0, 0, 10, 10, 0.05]));
    assert.equal(h.residency.upload(1, 1, { ground: query.visible, zMin: 20, zMax: 30 }), true, 'the floor goes under the picture');
    assert.deepEqual([...h.onGpu], ['floor'], 'kept, not dropped');
    assert.deepEqual([...h.residency.interimChunks(1)], ['floor']);
    assert.deepEqual([...h.residency.interimChunks(2)], ['floor'], 'the last answer\'s, for a view not answered yet');
    assert.deepEqual([...h.residency.interimChunks(0)], [], 'not for an older view');
    assert.equal(h.residency.loaded(1), false, 'the view\'s own chunk is still to come');
    h.residency.arrived(chunk('a'));
    h.residency.upload(2, 1, drawn);
    assert.deepEqual([...(h.residency.shownChunks(1) ?? [])], ['a'], 'complete without the floor');
  });

  test('loaded and settled are for the view the answer is for', () => {
    const h = harness();
    h.residency.answer(answer(1, ['a', 'b']));
    h.residency.arrived(chunk('a'));
    h.residency.upload(1, 1, drawn);
    assert.equal(h.residency.loaded(1), false);
    assert.equal(h.residency.settled(1), false, 'b is still to come');
    h.failed.add('b');
    assert.equal(h.residency.settled(1), true, 'b failed: nothing more will come');
    assert.equal(h.residency.settled(2), false, 'no answer for view 2 yet');
    h.residency.answer(answer(0, ['x']));
    assert.deepEqual(h.residency.neededChunks().visible, ['a', 'b'], 'an older answer is ignored');
    h.residency.answer(answer(2, ['a'], [], { indexComplete: false }));
    assert.equal(h.residency.loaded(2), false, 'sub-index files still loading');
    h.residency.answer(answer(2, ['a']));
    assert.equal(h.residency.loaded(2), true);
    assert.equal(h.residency.loaded(1), false, 'the answer is for view 2');
  });

  test('shows: the image drawn from these chunks shows the view only when it holds every visible chunk of that view', () => {
    const h = harness();
    const drawnFrom = new Set(['a', 'b']);
    assert.equal(h.residency.shows(1, drawnFrom), false, 'no answer yet');
    h.residency.answer(answer(1, ['a', 'b'], ['m']));
    assert.equal(h.residency.shows(1, drawnFrom), true, 'margin chunks are not on screen');
    assert.equal(h.residency.shows(2, drawnFrom), false, 'the answer is for view 1');
    assert.equal(h.residency.shows(1, new Set(['a'])), false, 'b is not in the image');
    h.residency.answer(answer(2, ['a'], [], { indexComplete: false }));
    assert.equal(h.residency.shows(2, drawnFrom), false, 'sub-index files still loading');
  });

  test('the chunks a view shows, once all are on the GPU: the floor chunks alone, not the cube\'s margin beside them', () => {
    const h = harness(1000);
    h.residency.answer(answer(1, ['floor-a', 'floor-b'], ['cube-a']));
    h.residency.arrived(chunk('floor-a'));
    h.residency.upload(1, 1, drawn);
    assert.equal(h.residency.shownChunks(1), null, 'floor-b is still to come');
    h.residency.arrived(chunk('floor-b'));
    h.residency.arrived(chunk('cube-a'));
    h.residency.upload(2, 1, drawn);
    assert.deepEqual([...h.residency.shownChunks(1)!].sort(), ['floor-a', 'floor-b']);
    assert.equal(h.residency.shownChunks(2), null, 'not for a view the worker has not answered');
  });
});
