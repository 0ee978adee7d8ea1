// Range requests beyond the shared rules: headers we ignore (the whole file, 200), empty
// files, HEAD, and how Range meets If-None-Match.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { bytesOf, CHUNK, CHUNK_SIZE } from './fixture.js';
import { request } from './http-client.js';
import { serveFixture } from './start-server.js';

const served = serveFixture();

const get = (path: string, headers: Record<string, string>, method = 'GET') => request(served.ours().base, path, { method, headers });

test('a Range we cannot understand is ignored: the whole file, 200', async () => {
  for (const range of ['bytes=5-2', 'items=0-5', 'bytes=abc', 'bytes=', 'bytes=1-2-3', 'bytes 0-5']) {
    const r = await get('/' + CHUNK, { range });
    assert.equal(r.status, 200, range);
    assert.equal(r.headers['content-range'], undefined, range);
    assert.equal(r.body.length, CHUNK_SIZE, range);
  }
});

test('no range of an empty file, and no empty suffix, can be satisfied', async () => {
  for (const range of ['bytes=0-', 'bytes=-5', 'bytes=0-0']) {
    const r = await get('/empty.json', { range });
    assert.equal(r.status, 416, range);
    assert.equal(r.headers['content-range'], 'bytes */0', range);
  }
  const r = await get('/' + CHUNK, { range: 'bytes=-0' });
  assert.equal(r.status, 416);
  assert.equal(r.headers['content-range'], `bytes */${CHUNK_SIZE}`);
});

test('a suffix longer than the file is the whole file, as a 206', async () => {
  const r = await get('/index.json', { range: 'bytes=-99999999' });
  const whole = bytesOf(served.fx(), '/index.json');
  assert.equal(r.status, 206);
  assert.equal(r.headers['content-range'], `bytes 0-${whole.length - 1}/${whole.length}`);
  assert.ok(r.body.equals(whole));
});

test('HEAD with a Range has the 206 headers and no body', async () => {
  const r = await get('/' + CHUNK, { range: 'bytes=10-19' }, 'HEAD');
  assert.equal(r.status, 206);
  assert.equal(r.headers['content-range'], `bytes 10-19/${CHUNK_SIZE}`);
  assert.equal(r.headers['content-length'], '10');
  assert.equal(r.body.length, 0);
});

test('a Range for a copy the client already has is a 304', async () => {
  const etag = (await get('/' + CHUNK, {})).headers.etag!;
  const r = await get('/' + CHUNK, { range: 'bytes=0-9', 'if-none-match': etag });
  assert.equal(r.status, 304);
});

test('reported no internal errors', () => assert.deepEqual(served.ours().errors, []));
