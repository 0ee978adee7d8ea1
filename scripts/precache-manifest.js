#!/usr/bin/env node
// After the client and service worker builds: workbox-build lists the demo's app shell
// (demo.html and its assets, with revisions) into the service worker, dist/client/sw.js.
// Vite's asset names carry their content hash, so only demo.html needs a revision of its own.
import { renameSync, rmSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { injectManifest } from 'workbox-build';

const dir = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../dist/client');
const src = path.join(dir, 'sw.src.js');
const tmp = path.join(dir, 'sw.js.tmp');

const { count, size, warnings } = await injectManifest({
  swSrc: src,
  swDest: tmp,
  globDirectory: dir,
  globPatterns: ['demo.html', 'assets/*.{js,css}'],
  dontCacheBustURLsMatching: /-[0-9a-f]{8,}\.(?:js|css)$/,
  // The shell is small; this only guards against a build that swallowed a dataset by mistake.
  maximumFileSizeToCacheInBytes: 4 * 1024 * 1024,
});
if (warnings.length > 0) {
  rmSync(tmp, { force: true });
  console.error(`precache manifest: ${warnings.join('; ')}`);
  process.exit(1);
}
// Written beside and renamed, so a failed build never leaves a service worker without its list.
renameSync(tmp, path.join(dir, 'sw.js'));
rmSync(src, { force: true });
if (process.env.SSC_VERBOSE) console.log(`service worker: ${count} files precached, ${(size / 1024).toFixed(0)} KiB`);
