// The chunk worker's entry point: reads the index the map fetched, then answers the map's
// messages (views, upload and eviction notices, feature lookups) with chunks, statuses and errors.
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
import { indexError } from './index-error.js';
import { FeaturePages } from './feature-pages.js';
import { IndexTree } from './index-tree.js';
import type { FromWorker, SourceErrorInfo, ToWorker, ViewRequest } from './worker-protocol.js';

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
/** Takes index.json's body when the map sends it, or why it has none. */
let indexCame: (msg: Extract<ToWorker, { type: 'index' | 'index-unavailable' }>) => void = () => undefined;
// Every file received whole, in order: what a service worker must cache to show these views offline.
const loadedUrls = new Set<string>();

scope.addEventListener('message', (ev) => {
  const msg = ev.data;
  switch (msg.type) {
    case 'init': {
      const options = { ...msg.options, onLoaded: (url: string) => loadedUrls.add(url) };
      // Rejected with the map's SourceErrorInfo when the fetch failed; an Error when the body is no index.
      const body = new Promise<ArrayBuffer>((resolve, reject) => (indexCame = (m) => (m.type === 'index' ? resolve(m.body) : reject(m.error))));
      ready = body.then((b) => {
        options.onLoaded(msg.url);
        return IndexTree.fromBody(b, msg.url, options);
      }).then(
        (tree) => {
          scheduler = new ChunkScheduler(tree, options, post);
          pages = new FeaturePages(tree.index.meta.faces, tree.index.meta.attributes, (f) => tree.url(f), options);
          post({ type: 'meta', meta: tree.index.meta });
          if (pendingView) scheduler.setView(pendingView);
          pendingView = null;
        },
        (err: unknown) => {
          post({ type: 'index-failed', error: err instanceof Error ? indexError(err, msg.url) : (err as SourceErrorInfo) });
          throw err;
        },
      );
      ready.catch(() => undefined);
      break;
    }
    case 'index':
    case 'index-unavailable':
      indexCame(msg);
      break;
    case 'view':
      if (scheduler) scheduler.setView(msg.view);
      else pendingView = msg.view;
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
    case 'loaded-urls':
      post({ type: 'loaded-urls', id: msg.id, urls: [...loadedUrls] });
      break;
  }
});
