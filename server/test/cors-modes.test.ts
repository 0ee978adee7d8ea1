// CORS settings of our server beyond the shared rules: any origin, no CORS at all, and
// origins that are refused at start because they cannot be origins.
import assert from 'node:assert/strict';
import { after, before, describe, it, test } from 'node:test';
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
