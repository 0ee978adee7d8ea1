// Our server weighs Accept-Encoding q-values as RFC 9110 says (nginx's config only tells
// accepted from refused): the client's preference first, brotli on a tie, identity last. The
// order itself is tested beside accept-encoding.ts; here, that the chosen copy is what is sent.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { bytesOf } from './fixture.js';
import { request } from './http-client.js';
import { serveFixture } from './start-server.js';

const served = serveFixture();

const cases: [string, 'br' | 'gzip' | undefined][] = [
  ['gzip;q=1, br;q=0.5', 'gzip'],
  ['br;q=0.2, gzip;q=0.8', 'gzip'],
  ['gzip;q=0.5, br;q=0.5', 'br'],
  ['*', 'br'],
  ['*;q=0.5, gzip', 'gzip'],
  ['br;q=0, *', 'gzip'],
  ['*;q=0', undefined],
  ['identity;q=0', undefined], // nothing else acceptable: identity is sent anyway
  ['gzip;q=0.1, identity', undefined],
  ['br;q=0.000', undefined],
  ['br;q=1.5', undefined], // an impossible weight: that entry is ignored
  ['br;q=abc, gzip', 'gzip'],
  ['x-gzip', 'gzip'],
  ['  BR  ', 'br'],
  ['', undefined],
];

for (const [accept, coding] of cases) {
  test(`Accept-Encoding ${JSON.stringify(accept)} gets ${coding ?? 'identity'}`, async () => {
    const r = await request(served.ours().base, '/index.json', { headers: { 'accept-encoding': accept } });
    assert.equal(r.status, 200);
    assert.equal(r.headers['content-encoding'], coding);
    const file = coding === 'br' ? '/index.json.br' : coding === 'gzip' ? '/index.json.gz' : '/index.json';
    assert.ok(r.body.equals(bytesOf(served.fx(), file)));
  });
}

test('a file without siblings is sent as it is, whatever the client accepts', async () => {
  const r = await request(served.ours().base, '/notes.txt', { headers: { 'accept-encoding': 'br, gzip' } });
  assert.equal(r.headers['content-encoding'], undefined);
  assert.ok(r.body.equals(bytesOf(served.fx(), '/notes.txt')));
});

test('reported no internal errors', () => assert.deepEqual(served.ours().errors, []));
