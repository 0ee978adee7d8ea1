// createStaticServer as a library: where it listens, what it reports, how it stops, and what
// it refuses to start with.
import assert from 'node:assert/strict';
import { symlinkSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { accepts } from './nginx-process.js';
import { createStaticServer } from './static-server.js';
import { makeFixture, type Fixture } from './test/fixture.js';
import { request } from './test/http-client.js';

let fx: Fixture;
before(() => {
  fx = makeFixture();
});
after(() => fx.remove());

test('listens on 127.0.0.1 by default and reports the bound address', async () => {
  const server = createStaticServer({ root: fx.root });
  assert.equal(server.address, null);
  assert.equal(server.url, null);
  const address = await server.listen();
  try {
    assert.equal(address.address, '127.0.0.1');
    assert.ok(address.port > 0);
    assert.deepEqual(server.address, address);
    assert.equal(server.url, `http://127.0.0.1:${address.port}/`);
    assert.equal((await request(server.url, '/index.json')).status, 200);
  } finally {
    await server.close();
  }
});

test('close() stops accepting connections, and may be called again', async () => {
  const server = createStaticServer({ root: fx.root });
  const { port } = await server.listen(0, '127.0.0.1');
  await server.close();
  assert.equal(server.address, null);
  assert.ok(!(await accepts(port)));
  await server.close();
});

test('a port in use is an error from listen(), not a crash', async () => {
  const first = createStaticServer({ root: fx.root });
  const { port } = await first.listen(0);
  const second = createStaticServer({ root: fx.root });
  try {
    await assert.rejects(second.listen(port), { code: 'EADDRINUSE' });
  } finally {
    await first.close();
  }
});

test('a root that is missing or not a directory is refused at creation', () => {
  assert.throws(() => createStaticServer({ root: path.join(fx.dir, 'nope') }), { code: 'ENOENT' });
  const file = path.join(fx.dir, 'file.txt');
  writeFileSync(file, 'x');
  assert.throws(() => createStaticServer({ root: file }), /not a directory/);
});

test('a root reached through a symlink is served, and its own symlinks inside it too', async () => {
  const link = path.join(fx.dir, 'root-link');
  symlinkSync(fx.root, link);
  const server = createStaticServer({ root: link });
  await server.listen();
  try {
    const r = await request(server.url!, '/link-in.json');
    assert.equal(r.status, 200);
    assert.ok(r.body.equals(fx.files.get('/index.json')!));
  } finally {
    await server.close();
  }
});
