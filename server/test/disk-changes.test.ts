// Files changed on disk while the server runs (it remembers lookups, see lookup-cache.ts):
// a file rewritten, touched or deleted is served as it is now once the bound has passed, a new
// file is found at once, and a file, sibling or directory swapped for a symlink out of the root
// is served as it was or not at all, never the target.
import assert from 'node:assert/strict';
import { mkdirSync, renameSync, symlinkSync, unlinkSync, utimesSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { after, before, describe, it } from 'node:test';
import { DEFAULT_REVALIDATE_AFTER_MS } from '../lookup-cache.js';
import { makeFixture, replaceFile, SECRET, swapForSymlink, type Fixture } from './fixture.js';
import { request, type Reply } from './http-client.js';
import { startOurs, type Started } from './start-server.js';

const sleep = (ms: number): Promise<void> => new Promise((r) => setTimeout(r, ms));
// Past the default bound whatever the timers' granularity.
const pastTheBound = (): Promise<void> => sleep(DEFAULT_REVALIDATE_AFTER_MS + 50);

function assertNoSecret(r: Reply, what: string): void {
  assert.ok(!r.body.toString('latin1').includes(SECRET), `${what}: leaked the secret`);
}

let fx: Fixture;
before(() => {
  fx = makeFixture();
});
after(() => fx.remove());

describe('the server with the default bound', () => {
  let ours: Started;
  before(async () => {
    ours = await startOurs({ root: fx.root });
  });
  after(() => ours.server.close());
  const get = (p: string, headers: Record<string, string> = {}): Promise<Reply> => request(ours.base, p, { headers });

  it('serves a file swapped for a symlink out of the root as it was, or not at all, never the target', async () => {
    const file = path.join(fx.root, 'swap.json');
    writeFileSync(file, '{"inside":true}');
    assert.equal((await get('/swap.json')).status, 200); // now remembered, bytes and all
    swapForSymlink(file, '../secret.txt');
    const right = await get('/swap.json');
    assertNoSecret(right, 'right after the swap');
    assert.ok(right.status === 404 || right.body.toString() === '{"inside":true}', `right after the swap: ${right.status}`);
    await pastTheBound();
    const later = await get('/swap.json');
    assertNoSecret(later, 'after the bound');
    assert.equal(later.status, 404);
  });

  it('stops sending a precompressed sibling swapped for a symlink out of the root', async () => {
    writeFileSync(path.join(fx.root, 'sib.json'), '{"sibling":"test"}');
    writeFileSync(path.join(fx.root, 'sib.json.gz'), 'gzip bytes stand-in');
    assert.equal((await get('/sib.json', { 'accept-encoding': 'gzip' })).headers['content-encoding'], 'gzip');
    swapForSymlink(path.join(fx.root, 'sib.json.gz'), '../secret.txt');
    assertNoSecret(await get('/sib.json', { 'accept-encoding': 'gzip' }), 'right after the swap');
    await pastTheBound();
    const later = await get('/sib.json', { 'accept-encoding': 'gzip' });
    assertNoSecret(later, 'after the bound');
    assert.equal(later.headers['content-encoding'], undefined);
    assert.equal(later.body.toString(), '{"sibling":"test"}');
  });

  it('serves a rewritten, touched or deleted file as it is now once the bound has passed', async () => {
    const file = path.join(fx.root, 'rebuilt.json');
    writeFileSync(file, '{"version":1}');
    const old = await get('/rebuilt.json');
    replaceFile(file, '{"version":2}');
    await pastTheBound();
    const fresh = await get('/rebuilt.json', { 'if-none-match': old.headers.etag! });
    assert.equal(fresh.status, 200);
    assert.equal(fresh.body.toString(), '{"version":2}');
    assert.notEqual(fresh.headers.etag, old.headers.etag);

    utimesSync(file, new Date('2020-01-02T03:04:05Z'), new Date('2020-01-02T03:04:05Z'));
    await pastTheBound();
    assert.equal((await get('/rebuilt.json')).headers['last-modified'], 'Thu, 02 Jan 2020 03:04:05 GMT');

    unlinkSync(file);
    await pastTheBound();
    assert.equal((await get('/rebuilt.json')).status, 404);
  });

  it('finds a new file at once, even one asked for just before it was written', async () => {
    assert.equal((await get('/fresh-chunk.bin')).status, 404);
    writeFileSync(path.join(fx.root, 'fresh-chunk.bin'), 'chunk');
    assert.equal((await get('/fresh-chunk.bin')).body.toString(), 'chunk');
  });

  it('reported no internal errors', () => assert.deepEqual(ours.errors, []));
});

describe('the server streaming from disk', () => {
  let ours: Started;
  before(async () => {
    // Nothing held in memory: every body is read from a file opened by its remembered path.
    ours = await startOurs({ root: fx.root, maxCachedFileBytes: 0, revalidateAfterMs: 60_000 });
  });
  after(() => ours.server.close());

  it('never reads through a directory swapped for a symlink out of the root, though its files were remembered', async () => {
    mkdirSync(path.join(fx.root, 'swapdir'));
    writeFileSync(path.join(fx.root, 'swapdir', 'inner.json'), '{"inside":true}');
    const first = await request(ours.base, '/swapdir/inner.json');
    assert.equal(first.body.toString(), '{"inside":true}');
    // The remembered real path, root/swapdir/inner.json, now leads to outside/inner.json.
    renameSync(path.join(fx.root, 'swapdir'), path.join(fx.root, 'swapdir-old'));
    symlinkSync('../outside', path.join(fx.root, 'swapdir'));
    const r = await request(ours.base, '/swapdir/inner.json');
    assertNoSecret(r, 'through the swapped directory');
    assert.equal(r.status, 404);
    assertNoSecret(await request(ours.base, '/swapdir/inner.json', { method: 'HEAD' }), 'HEAD');
  });

  it('answers 404, not 500, for a remembered file deleted since', async () => {
    writeFileSync(path.join(fx.root, 'deleted.bin'), 'chunk');
    assert.equal((await request(ours.base, '/deleted.bin')).status, 200);
    unlinkSync(path.join(fx.root, 'deleted.bin'));
    assert.equal((await request(ours.base, '/deleted.bin')).status, 404);
  });

  it('reported no internal errors', () => assert.deepEqual(ours.errors, []));
});
