// Offline use of the demo: registers the service worker (sw.js beside the page, built from
// src/offline/service-worker.ts) with workbox-window. On the first visit the map starts before
// the service worker controls the page, so the cube files loaded until then are handed to it
// (workbox's CACHE_URLS message) once it does; after that every request goes through it.
// When it finds a new build of the cube, `onNewBuild` is called (the demo offers a reload).
import { Workbox } from 'workbox-window';
import type { VarioMap } from '../src/lib/bundle.js';

interface BroadcastUpdate {
  meta: 'workbox-broadcast-update';
  type: 'CACHE_UPDATED';
  payload: { cacheName: string; updatedURL: string };
}

const isBroadcastUpdate = (d: unknown): d is BroadcastUpdate =>
  typeof d === 'object' && d !== null && (d as { meta?: unknown }).meta === 'workbox-broadcast-update';

/** When the files loaded before the service worker took over are handed to it once more. */
const HAND_OVER_AGAIN_MS = 3000;

export function enableOffline(map: VarioMap, onNewBuild: () => void): void {
  if (!('serviceWorker' in navigator)) return;
  const wb = new Workbox('sw.js');
  const handOver = async (): Promise<void> => {
    const urls = await map.getLoadedUrls();
    if (urls.length > 0) wb.messageSW({ type: 'CACHE_URLS', payload: { urlsToCache: urls } }).catch(() => undefined);
  };
  wb.addEventListener('controlling', () => {
    // Now, and again once the requests already under way (outside its control) have finished:
    // at the next idle, and a few seconds on for what comes after it (the margin after the view
    // has rested, the cube's sub-index files after the floor chunks on screen).
    void handOver();
    void map.whenIdle().then(handOver);
    setTimeout(() => void handOver(), HAND_OVER_AGAIN_MS);
  });
  navigator.serviceWorker.addEventListener('message', (ev: MessageEvent<unknown>) => {
    if (isBroadcastUpdate(ev.data) && ev.data.payload.updatedURL === map.getSourceUrl()) onNewBuild();
  });
  wb.register().catch((err: unknown) => console.warn(`offline use is off: ${(err as Error).message}`));
}
