// The chunk worker's entry point: takes the index the map read, then answers the map's messages
// (views, upload and eviction notices, feature lookups) with chunks, statuses and errors; the
// first view's floor chunks may come from the map too (head-start.ts).
//
// One worker decodes every chunk. A pool (MapLibre's way: more copies of this script, each
// handed bodies through a MessagePort by this one when free) was built and measured at stop 50,
// and not kept: on this machine's two cores, first complete maps with 2 and 3 workers took
// 0.96-1.14x and 1.02-1.12x the time of one (a benchmark written for it and not kept: a 160x90
// canvas showing the 1280x720 views' ground, so that the software GPU took little; median of 5). A trace showed both
// cores taken by this worker and the GPU process, and each extra worker starts cold: its first
// chunks decode at a third of a warm worker's speed (node: 286 ms cold, 94 warm, for nlcd_zion's
// 34 first floor chunks), which a view of a few dozen chunks does not earn back. A device with
// free cores may gain; it was not measurable here.
import { ChunkScheduler } from './chunk-scheduler.js';
import { FeaturePages } from './feature-pages.js';
import { HeadStart } from './head-start.js';
import { IndexTree } from './index-tree.js';
import type { FromWorker, ToWorker, ViewRequest } from './worker-protocol.js';

// The DOM lib types `self` as a Window; this is the part of a dedicated worker's scope used here.
interface WorkerScope {
  postMessage(message: FromWorker, transfer: Transferable[]): void;
  addEventListener(type: 'message', fn: (ev: MessageEvent<ToWorker>) => void): void;
}
const scope = self as unknown as WorkerScope;
const post = (msg: FromWorker, transfer: Transferable[] = []): void => scope.postMessage(msg, transfer);

let scheduler: ChunkScheduler | null = null;
let pages: FeaturePages | null = null;
let pendingView: ViewRequest | null = null;
let ready: Promise<void> | null = null;
/** Takes the index the map read, or why it has none (the map has reported that). */
let indexCame: (msg: Extract<ToWorker, { type: 'index' | 'index-unavailable' }>) => void = () => undefined;
// Every file received whole, in order: what a service worker must cache to show these views offline.
const loadedUrls = new Set<string>();
const headStart = new HeadStart();
let tree: IndexTree | null = null;

/** A view to the scheduler (kept until there is one); the bodies the map fetched for a view left behind are let go. */
function show(view: ViewRequest): void {
  const t = tree;
  if (!scheduler || !t) {
    pendingView = view;
    return;
  }
  scheduler.setView(view);
  // Once every body has been taken (after the first view, as a rule) this costs nothing per view.
  if (!headStart.holding) return;
  const needed = new Set([...scheduler.neededFiles].map((f) => t.url(f)));
  headStart.keepOnly((url) => needed.has(url));
}

scope.addEventListener('message', (ev) => {
  const msg = ev.data;
  switch (msg.type) {
    case 'init': {
      const options = { ...msg.options, onLoaded: (url: string) => loadedUrls.add(url), headStart };
      ready = new Promise<void>((resolve, reject) => {
        indexCame = (m) => {
          if (m.type === 'index-unavailable') return reject(new Error(m.error.message));
          options.onLoaded(msg.url);
          const t = IndexTree.of(m.index, msg.url, options);
          tree = t;
          scheduler = new ChunkScheduler(t, options, post);
          pages = new FeaturePages(t.index.meta.faces, t.index.meta.attributes, (f) => t.url(f), options);
          const waiting = pendingView;
          pendingView = null;
          if (waiting) show(waiting);
          resolve();
        };
      });
      ready.catch(() => undefined);
      break;
    }
    case 'index':
    case 'index-unavailable':
      indexCame(msg);
      break;
    case 'head-start':
      headStart.expect(msg.urls);
      break;
    case 'head-start-result':
      headStart.arrived(msg.url, msg.result);
      break;
    case 'view':
      show(msg.view);
      break;
    case 'uploaded':
      scheduler?.uploaded(msg.file);
      break;
    case 'evicted':
      scheduler?.evicted(msg.files);
      break;
    case 'features': {
      const { id, faces } = msg;
      const run = async (): Promise<void> => {
        await ready;
        const p = pages!;
        const features = await Promise.all(faces.map((f) => (f > 0 ? p.lookup(f) : Promise.resolve(null))));
        post({ type: 'features', id, features });
      };
      run().catch((err: unknown) => post({ type: 'features', id, features: [], error: (err as Error).message }));
      break;
    }
    case 'attributes': {
      const { id, features } = msg;
      const run = async (): Promise<void> => {
        await ready;
        const p = pages!;
        post({ type: 'attributes', id, properties: await Promise.all(features.map((f) => p.properties(f))) });
      };
      run().catch((err: unknown) => post({ type: 'attributes', id, properties: [], error: (err as Error).message }));
      break;
    }
    case 'online':
      scheduler?.retryFailed();
      break;
    case 'loaded-urls':
      post({ type: 'loaded-urls', id: msg.id, urls: [...loadedUrls] });
      break;
  }
});
