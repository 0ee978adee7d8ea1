// The frame loop with a real view and residency and a renderer that records what it is asked to
// draw: the interim floor is drawn under a view whose z range it does not meet until the view's
// own chunks are all on the GPU, and a hold keeps the map from going idle until it is let go.
import assert from 'node:assert/strict';
import { afterEach, beforeEach, describe, test } from 'node:test';
import type { Box3 } from '../../../format/cube-index.js';
import type { MapView } from '../camera/map-view.js';
import { DEFAULT_STATE_PAINTS } from '../render/colour-options.js';
import type { GpuChunk } from '../render/gpu-chunk.js';
import type { Renderer } from '../render/renderer.js';
import type { ChunkPayload, ChunkStatus, NeededChunks } from '../source/worker-protocol.js';
import { makeView, testMeta } from '../../../testing/map-view-fixture.js';
import { eventually, settle } from '../../../testing/event-loop.js';
import { ChunkResidency, type ChunkRequests, type GpuChunks } from './chunk-residency.js';
import { FrameLoop, type RenderSettings } from './frame-loop.js';
import type { MapCanvas } from './map-canvas.js';

const SETTINGS: RenderSettings = {
  blending: { mode: 'never', distance: 0.5 },
  boundaries: { enabled: false, width: 1, color: '#000000', opacity: 0.35 },
  paints: DEFAULT_STATE_PAINTS,
  supersampling: 1,
  lines: false,
  prefetchMargin: 0.25,
};

/** A chunk over the whole cube at z 0..top (the floor's box) or 0..100 (the cube's). */
const payload = (file: string, bbox: Box3): ChunkPayload => ({
  kind: 'surfaces', file, bbox, buffer: new ArrayBuffer(0), vertexCount: 0, triangleCount: 0, originX: 0, originY: 0,
  vertexByteOffset: 0, vertexByteLength: 0, indexByteOffset: 0, indexSize: 2,
  blocks: { cellBox: new Float32Array(0), cellBlocks: Uint32Array.of(0), zLow: new Float32Array(0), first: Uint32Array.of(0) }, verified: true,
});
const FLOOR: Box3 = [0, 0, 0, 1000, 500, 0.05];
const CUBE: Box3 = [0, 0, 0, 1000, 500, 100];

function harness() {
  const { view } = makeView();
  view.setMeta(testMeta, () => ({ x: 500, y: 250, scale: 4000 }));
  // A flat slice well above the floor's top.
  view.pinZ(20);
  const onGpu = new Map<string, GpuChunk>();
  const drawn: string[][] = [];
  const sent: number[] = [];
  const source: ChunkRequests = {
    setView: (v) => sent.push(v.seq),
    uploaded: () => undefined,
    evicted: () => undefined,
    status: (f): ChunkStatus => (onGpu.has(f) ? 'gpu' : 'requested'),
    handingOver: false,
  };
  const store = { has: (f: string) => onGpu.has(f), values: () => onGpu.values(), bytes: 0 };
  const gpu: GpuChunks = {
    upload: (c) => onGpu.set(c.file, { file: c.file, bbox: c.bbox, kind: 'surfaces', lastUsed: 0 } as unknown as GpuChunk),
    evict: () => [],
    store,
  };
  const residency = new ChunkResidency(source, gpu, 1e9, () => undefined);
  const renderer = {
    store,
    lost: false,
    targetBytes: 0,
    render: (_f: unknown, chunks: GpuChunk[]) => {
      drawn.push(chunks.map((c) => c.file));
      return { triangles: 0, segments: 0 };
    },
    present: () => undefined,
  } as unknown as Renderer;
  const canvas = { geometry: (v: MapView) => v.geometry(400, 200, 1), deviceRatio: () => 1 } as unknown as MapCanvas;
  const idles: boolean[] = [];
  const loop = new FrameLoop(view, canvas, renderer, residency, SETTINGS, { render: () => undefined, load: () => undefined, complete: () => undefined, idle: (c) => idles.push(c) });
  const answer = (o: Partial<NeededChunks>): void => residency.answer({ seq: sent.at(-1) ?? 0, visible: [], margin: [], ahead: [], interim: [], indexComplete: true, queryMs: 0, ...o });
  return { loop, residency, drawn, idles, answer, sent };
}

describe('the frame loop', () => {
  beforeEach(() => {
    // One animation frame a task, as a browser would give them.
    globalThis.requestAnimationFrame = (cb: FrameRequestCallback): number => setTimeout(() => cb(performance.now()), 1) as unknown as number;
    globalThis.cancelAnimationFrame = (id: number): void => clearTimeout(id);
  });
  afterEach(() => {
    Reflect.deleteProperty(globalThis, 'requestAnimationFrame');
    Reflect.deleteProperty(globalThis, 'cancelAnimationFrame');
  });

  test('draws the interim floor under a view whose z range it does not meet until the view\'s own chunks are all on the GPU, then those alone', async () => {
    const h = harness();
    h.loop.viewChanged(true);
    await eventually(() => h.sent.length > 0, 'the view sent to the worker');
    h.answer({ visible: ['c-1'], interim: ['b-1'] });
    h.residency.arrived(payload('b-1', FLOOR));
    h.loop.schedule();
    await eventually(() => h.drawn.at(-1)?.join() === 'b-1', 'the floor alone, under the view');
    h.residency.arrived(payload('c-1', CUBE));
    h.loop.schedule();
    await eventually(() => h.drawn.at(-1)?.join() === 'c-1', 'complete: the view\'s own chunk alone');
    assert.ok(h.drawn.every((files) => files.join() === 'b-1' || files.join() === 'c-1' || files.length === 0), `never both: ${JSON.stringify(h.drawn)}`);
    h.loop.stop();
  });

  test('a hold keeps the map from going idle until it is let go', async () => {
    const h = harness();
    let letGo = (): void => undefined;
    h.loop.holdIdle(new Promise<void>((resolve) => (letGo = resolve)));
    h.loop.viewChanged(true);
    await eventually(() => h.sent.length > 0, 'the view sent to the worker');
    h.answer({});
    h.loop.schedule();
    await eventually(() => h.drawn.length > 0, 'a frame drawn');
    await new Promise((resolve) => setTimeout(resolve, 20));
    await settle();
    assert.deepEqual(h.idles, [], 'held');
    letGo();
    await eventually(() => h.idles.length > 0, 'idle once let go');
    assert.deepEqual(h.idles, [true], 'idle, and complete (the view needs no chunk)');
    h.loop.stop();
  });
});
