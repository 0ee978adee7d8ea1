// CORS settings of our server beyond the shared rules: any origin, no CORS at all, and
// origins that are refused at start because they cannot be origins; and the handler's own 500.
import assert from 'node:assert/strict';
import { after, before, describe, it, test } from 'node:test';
import { createServer, type Server } from 'node:http';
import type { AddressInfo } from 'node:net';
import { CachePolicy } from '../cache-control.js';
import { ContentCache } from '../content-cache.js';
import { CorsPolicy } from '../cors.js';
import { LookupCache } from '../lookup-cache.js';
import { createRequestHandler } from '../request-handler.js';
import type { Resolved } from '../resolve-file.js';
import { createStaticServer } from '../static-server.js';
import { makeFixture, type Fixture } from './fixture.js';
import { request } from './http-client.js';
import { tokens } from './header-rules.js';
import { startOurs, type Started } from './start-server.js';

let fx: Fixture;
before(() => {
  fx = makeFixture();
});
after(() => fx.remove());

describe("cors: '*'", () => {
  let ours: Started;
  before(async () => {
    ours = await startOurs({ root: fx.root, cors: '*' });
  });
  after(() => ours.server.close());

  it('grants every origin, and the answer does not vary by origin', async () => {
    for (const origin of ['https://a.example', 'http://localhost:5173']) {
      const r = await request(ours.base, '/index.json', { headers: { origin } });
      assert.equal(r.headers['access-control-allow-origin'], '*');
      assert.ok(!tokens(r.headers.vary).includes('origin'));
      assert.ok(tokens(r.headers['access-control-expose-headers']).includes('etag'));
    }
  });

  it('answers a preflight', async () => {
    const r = await request(ours.base, '/index.json', { method: 'OPTIONS', headers: { origin: 'https://a.example', 'access-control-request-method': 'GET' } });
    assert.equal(r.status, 204);
    assert.equal(r.headers['access-control-allow-origin'], '*');
    assert.ok(tokens(r.headers['access-control-allow-methods']).includes('get'));
  });
});

describe('cors off (the default)', () => {
  let ours: Started;
  before(async () => {
    ours = await startOurs({ root: fx.root });
  });
  after(() => ours.server.close());

  it('grants no origin', async () => {
    const r = await request(ours.base, '/index.json', { headers: { origin: 'https://map.example.org' } });
    assert.equal(r.status, 200);
    assert.equal(r.headers['access-control-allow-origin'], undefined);
    assert.equal(r.headers['access-control-expose-headers'], undefined);
  });

  it('refuses OPTIONS like any other method', async () => {
    const r = await request(ours.base, '/index.json', { method: 'OPTIONS', headers: { origin: 'https://a.example', 'access-control-request-method': 'GET' } });
    assert.equal(r.status, 405);
    assert.deepEqual(tokens(r.headers.allow), ['get', 'head']);
    assert.equal(r.headers['access-control-allow-origin'], undefined);
  });
});

describe('cors: a list', () => {
  let ours: Started;
  before(async () => {
    ours = await startOurs({ root: fx.root, cors: ['https://Map.Example.org/', 'http://localhost:5173'] });
  });
  after(() => ours.server.close());

  it('matches origins whatever their case, and echoes the one asked', async () => {
    for (const origin of ['https://map.example.org', 'http://localhost:5173']) {
      const r = await request(ours.base, '/index.json', { headers: { origin } });
      assert.equal(r.headers['access-control-allow-origin'], origin);
    }
    const other = await request(ours.base, '/index.json', { headers: { origin: 'http://localhost:5174' } });
    assert.equal(other.headers['access-control-allow-origin'], undefined);
    assert.ok(tokens(other.headers.vary).includes('origin'));
  });
});

test('an origin with a path, a query or no scheme is refused at start', () => {
  for (const bad of ['https://a.example/app', 'https://a.example?x=1', 'a.example', 'null', 'https://user@a.example']) {
    assert.throws(() => createStaticServer({ root: fx.root, cors: [bad] }), /not an origin/, bad);
  }
});

describe('an unexpected failure', () => {
  // A lookup that fails as a broken disk would: the handler's own 500, not a file's answer.
  class FailingLookups extends LookupCache {
    override resolve(): Promise<Resolved> {
      return Promise.reject(new Error('disk failed'));
    }
  }
  let server: Server;
  let base: string;
  const errors: unknown[] = [];
  before(async () => {
    const handler = createRequestHandler({
      cors: new CorsPolicy(['https://a.example']),
      cachePolicy: new CachePolicy(),
      contents: new ContentCache(1 << 20, 1 << 16),
      lookups: new FailingLookups(fx.root),
      onError: (err) => errors.push(err),
    });
    server = createServer(handler);
    await new Promise<void>((resolve) => server.listen(0, '127.0.0.1', resolve));
    base = `http://127.0.0.1:${(server.address() as AddressInfo).port}`;
  });
  after(() => new Promise<void>((resolve) => server.close(() => resolve())));

  it('answers 500 with the CORS headers, so a map on an allowed origin reads the status and retries', async () => {
    const r = await request(base, '/index.json', { headers: { origin: 'https://a.example' } });
    assert.equal(r.status, 500);
    assert.equal(r.headers['access-control-allow-origin'], 'https://a.example');
    assert.ok(tokens(r.headers['access-control-expose-headers']).includes('retry-after'));
    assert.ok(tokens(r.headers.vary).includes('origin'));
    assert.equal(r.headers['x-content-type-options'], 'nosniff');
    assert.match((errors[0] as Error).message, /disk failed/);
  });

  it('grants no other origin', async () => {
    const r = await request(base, '/index.json', { headers: { origin: 'https://b.example' } });
    assert.equal(r.status, 500);
    assert.equal(r.headers['access-control-allow-origin'], undefined);
  });
});
