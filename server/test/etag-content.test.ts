// Our ETags come from the bytes, not from file times: equal contents share a tag, a touched
// file keeps it, and a rewritten file gets a new one (and is never served stale from memory).
// The server here looks at the disk on every request (revalidateAfterMs: 0), so each change
// must show in the very next response; the default bound is tested in disk-changes.test.ts.
import assert from 'node:assert/strict';
import { copyFileSync, renameSync, utimesSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { test } from 'node:test';

import { request } from './http-client.js';
import { serveFixture } from './start-server.js';

const served = serveFixture({ revalidateAfterMs: 0 });

const get = (p: string, headers: Record<string, string> = {}) => request(served.ours().base, p, { headers });

test('files with the same bytes have the same ETag', async () => {
  copyFileSync(path.join(served.fx().root, 'index.json'), path.join(served.fx().root, 'copy.json'));
  const a = await get('/index.json');
  const b = await get('/copy.json');
  assert.equal(a.headers.etag, b.headers.etag);
  assert.notEqual(a.headers.etag, (await get('/meta.json')).headers.etag);
});

test('touching a file changes Last-Modified but not the ETag', async () => {
  const before = await get('/meta.json');
  const file = path.join(served.fx().root, 'meta.json');
  utimesSync(file, new Date('2020-01-02T03:04:05Z'), new Date('2020-01-02T03:04:05Z'));
  const after = await get('/meta.json');
  assert.equal(after.headers.etag, before.headers.etag);
  assert.equal(after.headers['last-modified'], 'Thu, 02 Jan 2020 03:04:05 GMT');
  assert.equal((await get('/meta.json', { 'if-none-match': before.headers.etag! })).status, 304);
  assert.equal((await get('/meta.json', { 'if-modified-since': 'Fri, 03 Jan 2020 00:00:00 GMT' })).status, 304);
  assert.equal((await get('/meta.json', { 'if-modified-since': 'Wed, 01 Jan 2020 00:00:00 GMT' })).status, 200);
});

test('a rebuilt index.json is served at once, with a new ETag', async () => {
  const old = await get('/index.json');
  // As the preprocessing writes: a new file renamed over the old one.
  const tmp = path.join(served.fx().root, 'index.json.tmp');
  writeFileSync(tmp, '{"version":2}');
  renameSync(tmp, path.join(served.fx().root, 'index.json'));
  const fresh = await get('/index.json', { 'if-none-match': old.headers.etag! });
  assert.equal(fresh.status, 200);
  assert.equal(fresh.body.toString(), '{"version":2}');
  assert.notEqual(fresh.headers.etag, old.headers.etag);
  // Rewritten in place, same size: still noticed.
  writeFileSync(path.join(served.fx().root, 'index.json'), '{"version":3}');
  const again = await get('/index.json');
  assert.equal(again.body.toString(), '{"version":3}');
  assert.notEqual(again.headers.etag, fresh.headers.etag);
});

test('reported no internal errors', () => assert.deepEqual(served.ours().errors, []));
