// The demo's service worker (workbox): the app shell precached (the list is injected at build
// time by scripts/precache-manifest.js), a cube's content-hashed files cache-first within an
// entry budget, and its index.json stale-while-revalidate. When a revalidated index differs
// from the cached one (a new build), the pages are told (workbox-broadcast-update); once a page
// starts on the new index, the older build's files are dropped from the cache. Options in the script's URL:
// sw.js?maxFiles=<n> (cube files kept, default 1000) &maxAgeDays=<n> (default 30).
import { BroadcastUpdatePlugin } from 'workbox-broadcast-update';
import { CacheableResponsePlugin } from 'workbox-cacheable-response';
import { clientsClaim, type WorkboxPlugin } from 'workbox-core';
import { ExpirationPlugin } from 'workbox-expiration';
import { cleanupOutdatedCaches, precacheAndRoute, type PrecacheEntry } from 'workbox-precaching';
import { registerRoute } from 'workbox-routing';
import { CacheFirst, StaleWhileRevalidate } from 'workbox-strategies';
import { isSubIndex, referencedFiles, unusedCubeFiles } from './cube-files.js';

declare const self: ServiceWorkerGlobalScope & { __WB_MANIFEST: (string | PrecacheEntry)[] };

const INDEX_CACHE = 'vario-cube-index';
const FILES_CACHE = 'vario-cube-files';

const params = new URL(self.location.href).searchParams;
const positive = (name: string, fallback: number): number => {
  const v = Number(params.get(name));
  return Number.isFinite(v) && v > 0 ? v : fallback;
};
const maxFiles = positive('maxFiles', 1000);
const maxAgeDays = positive('maxAgeDays', 30);

// A new version of the app takes over at once: its shell is complete and the cube's files are
// content-addressed, so pages already open cannot mix old and new code with the wrong data.
void self.skipWaiting();
clientsClaim();

// "/" is the demo; query parameters (?source=...) do not change the shell.
precacheAndRoute(self.__WB_MANIFEST, { directoryIndex: 'demo.html', ignoreURLParametersMatching: [/.*/] });
cleanupOutdatedCaches();

const isIndex = (url: URL): boolean => url.pathname.endsWith('/index.json');
// c- chunks, b- floor chunks, l- line chunks, f- face pages, a- attribute pages, i- sub-indexes:
// their names change with their content.
const isCubeFile = (url: URL): boolean => /\/[cbflai]-[0-9a-f]{8,}\.(?:bin|json)$/.test(url.pathname);

/**
 * The files of the cube that the index about to be used does not refer to are deleted: they
 * belong to an older build. This runs when a page starts on a cached index, not when a new
 * index arrives, since the page that fetched it is still drawing the old build from the cache.
 */
async function pruneOtherBuilds(indexUrl: string, index: Response): Promise<void> {
  const referenced = new Set(referencedFiles(await index.text()));
  const files = await caches.open(FILES_CACHE);
  // Sub-indexes of this build that are cached name files that must stay too, at any depth.
  const subIndexes = [...referenced].filter(isSubIndex);
  for (let name = subIndexes.pop(); name !== undefined; name = subIndexes.pop()) {
    const cached = await files.match(new URL(name, indexUrl).href);
    if (!cached) continue;
    for (const f of referencedFiles(await cached.text())) {
      if (referenced.has(f)) continue;
      referenced.add(f);
      if (isSubIndex(f)) subIndexes.push(f);
    }
  }
  const keys = await files.keys();
  await Promise.all(unusedCubeFiles(keys.map((k) => k.url), indexUrl, referenced).map((u) => files.delete(u)));
}

const pruneOnUse: WorkboxPlugin = {
  cachedResponseWillBeUsed: async ({ request, cachedResponse, event }) => {
    if (cachedResponse) {
      const pruning = pruneOtherBuilds(request.url, cachedResponse.clone()).catch(() => undefined);
      if (event instanceof ExtendableEvent) event.waitUntil(pruning);
    }
    return cachedResponse ?? null;
  },
};

registerRoute(
  ({ url }) => isIndex(url),
  new StaleWhileRevalidate({
    cacheName: INDEX_CACHE,
    plugins: [new CacheableResponsePlugin({ statuses: [200] }), new BroadcastUpdatePlugin(), pruneOnUse],
  }),
);

registerRoute(
  ({ url }) => isCubeFile(url),
  new CacheFirst({
    cacheName: FILES_CACHE,
    plugins: [
      new CacheableResponsePlugin({ statuses: [200] }),
      new ExpirationPlugin({ maxEntries: maxFiles, maxAgeSeconds: maxAgeDays * 86400, purgeOnQuotaError: true }),
    ],
  }),
);
