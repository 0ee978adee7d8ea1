// The chunk worker's entry point: loads the index, then answers the map's messages (views,
// upload and eviction notices, feature lookups) with chunks, statuses and errors.
import { ChunkScheduler, indexError } from './chunk-scheduler.js';
import { FeaturePages } from './feature-pages.js';
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
// Every file received whole, in order: what a service worker must cache to show these views offline.
const loadedUrls = new Set<string>();

scope.addEventListener('message', (ev) => {
  const msg = ev.data;
  switch (msg.type) {
    case 'init': {
      const options = { ...msg.options, onLoaded: (url: string) => loadedUrls.add(url) };
      ready = IndexTree.load(msg.url, options).then(
        (tree) => {
          scheduler = new ChunkScheduler(tree, options, post);
          pages = new FeaturePages(tree.index.meta.faces, tree.index.meta.attributes, (f) => tree.url(f), options);
          post({ type: 'meta', meta: tree.index.meta });
          if (pendingView) scheduler.setView(pendingView);
          pendingView = null;
        },
        (err: unknown) => {
          post({ type: 'index-failed', error: indexError(err, msg.url) });
          throw err;
        },
      );
      ready.catch(() => undefined);
      break;
    }
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
