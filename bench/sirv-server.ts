// The library bench:serve weighs against `ssc serve` (issue 10: replace the hand-written server
// unless the library falls below 0.8x nginx): sirv as it would serve a map directory, run in
// its own process like `ssc serve`: precompressed siblings, ETags, our Cache-Control and types.
//   node dist/bench/sirv-server.js <dir>   prints "serving <dir> at http://127.0.0.1:<port>/"
import { createServer } from 'node:http';
import type { AddressInfo } from 'node:net';
import sirv from 'sirv';
import { CachePolicy } from '../server/cache-control.js';
import { contentTypeFor } from '../server/content-types.js';

const dir = process.argv[2];
if (dir === undefined) throw new Error('usage: sirv-server.js <dir>');
const cachePolicy = new CachePolicy();
const handler = sirv(dir, {
  // Dev mode looks at the disk on every request; otherwise sirv lists the directory once at
  // start and never finds a file published later (a new index.json, its chunks).
  dev: true,
  etag: true,
  brotli: true,
  gzip: true,
  extensions: [],
  setHeaders(res, pathname) {
    const name = pathname.slice(pathname.lastIndexOf('/') + 1);
    res.setHeader('cache-control', cachePolicy.headerFor(name));
    res.setHeader('content-type', contentTypeFor(name));
    res.setHeader('x-content-type-options', 'nosniff');
  },
});
const server = createServer((req, res) => handler(req, res));
server.listen(0, '127.0.0.1', () => {
  process.stdout.write(`serving ${dir} at http://127.0.0.1:${(server.address() as AddressInfo).port}/\n`);
});
process.once('SIGTERM', () => server.close());
