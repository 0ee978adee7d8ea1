// Which names count as content-hashed (cached for a year) with the default pattern and with
// one of the caller's own; index.json and meta.json stay revalidated whatever the pattern.
import assert from 'node:assert/strict';
import { writeFileSync } from 'node:fs';
import path from 'node:path';
import { after, before, describe, it } from 'node:test';
import { makeFixture, type Fixture } from './fixture.js';
import { request } from './http-client.js';
import { startOurs, type Started } from './start-server.js';

const IMMUTABLE = 'public, max-age=31536000, immutable';

let fx: Fixture;
before(() => {
  fx = makeFixture();
  for (const name of ['c-3fa9b2c1.bin', 'c-3fa9b2c.bin', 'deadbeefcafe.json', '3fa9b2c1d4e5f607', 'abcdef0123g.json', 'C-3FA9B2C1D4.bin', 'report-2024010x.json', 'v2-app.js', 'chunk.3fa9b2c1d4.bin', 'x 1234567.bin']) {
    writeFileSync(path.join(fx.root, name), 'x');
  }
});
after(() => fx.remove());

async function cacheControl(base: string, name: string): Promise<string | undefined> {
  const r = await request(base, '/' + encodeURIComponent(name));
  assert.equal(r.status, 200, name);
  return r.headers['cache-control'];
}

describe('the default pattern: a run of 8 or more lowercase hex digits standing alone', () => {
  let ours: Started;
  before(async () => {
    ours = await startOurs({ root: fx.root });
  });
  after(() => ours.server.close());

  for (const [name, immutable] of [
    ['c-3fa9b2c1.bin', true],
    ['chunk.3fa9b2c1d4.bin', true],
    ['deadbeefcafe.json', true],
    ['3fa9b2c1d4e5f607', true],
    ['c-3fa9b2c.bin', false], // 7 digits
    ['abcdef0123g.json', false], // the run runs on into a letter
    ['C-3FA9B2C1D4.bin', false], // hashes are written in lowercase
    ['report-2024010x.json', false],
    ['index.json', false],
    ['v2-app.js', false],
    ['x 1234567.bin', false], // the decoded name, as nginx's $uri: the %20 it was sent as adds no digits
  ] as const) {
    it(`${name}: ${immutable ? 'immutable' : 'revalidated'}`, async () => {
      assert.equal(await cacheControl(ours.base, name), immutable ? IMMUTABLE : 'no-cache');
    });
  }
});

describe('a pattern of our own (even a global one, whose lastIndex must not leak)', () => {
  let ours: Started;
  before(async () => {
    ours = await startOurs({ root: fx.root, immutablePattern: /^(v\d+-|index|meta|c-)/g });
  });
  after(() => ours.server.close());

  it('decides, again and again', async () => {
    for (let i = 0; i < 3; i++) {
      assert.equal(await cacheControl(ours.base, 'v2-app.js'), IMMUTABLE);
      assert.equal(await cacheControl(ours.base, 'c-3fa9b2c.bin'), IMMUTABLE);
      assert.equal(await cacheControl(ours.base, 'deadbeefcafe.json'), 'no-cache');
    }
  });

  it('never makes index.json or meta.json immutable', async () => {
    assert.equal(await cacheControl(ours.base, 'index.json'), 'no-cache');
    assert.equal(await cacheControl(ours.base, 'meta.json'), 'no-cache');
  });
});
