// Remembered lookups: a name found inside the root is answered from memory for at most the
// bound, then looked at again; a missing name is never remembered; and a symlink swapped in to
// lead out of the root is never followed, not even right after the name was remembered.
import assert from 'node:assert/strict';
import { mkdirSync, realpathSync, renameSync, symlinkSync, unlinkSync, utimesSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { after, before, describe, it } from 'node:test';
import { DEFAULT_REVALIDATE_AFTER_MS, LookupCache } from '../lookup-cache.js';
import { isInside, type Resolved } from '../resolve-file.js';
import { makeFixture, SECRET, type Fixture } from './fixture.js';
import { request, type Reply } from './http-client.js';
import { startOurs, type Started } from './start-server.js';

const sleep = (ms: number): Promise<void> => new Promise((r) => setTimeout(r, ms));
// Past the default bound whatever the timers' granularity.
const pastTheBound = (): Promise<void> => sleep(DEFAULT_REVALIDATE_AFTER_MS + 50);

/** Replaces `file` by a symlink to `target` in one step, as a deploy script would. */
function swapForSymlink(file: string, target: string): void {
  const tmp = `${file}.swap-tmp`;
  symlinkSync(target, tmp);
  renameSync(tmp, file);
}

/** Writes a new file over `file` in one step, as the preprocessing does. */
function replaceFile(file: string, text: string): void {
  writeFileSync(`${file}.tmp`, text);
  renameSync(`${file}.tmp`, file);
}

function realPathOf(r: Resolved): string | undefined {
  return r.kind === 'missing' ? undefined : r.realPath;
}

function assertNoSecret(r: Reply, what: string): void {
  assert.ok(!r.body.toString('latin1').includes(SECRET), `${what}: leaked the secret`);
}

let fx: Fixture;
let root: string;
before(() => {
  fx = makeFixture();
  root = realpathSync(fx.root);
});
after(() => fx.remove());

describe('LookupCache, on a clock of its own', () => {
  let clock = 0;
  const now = (): number => clock;

  it('answers a known name from memory within the bound, and looks at the disk after it', async () => {
    writeFileSync(path.join(root, 'clock-a.json'), '{"v":1}');
    const cache = new LookupCache(root, { revalidateAfterMs: 100, now });
    const first = await cache.resolve(['clock-a.json']);
    assert.equal(first.kind, 'file');
    replaceFile(path.join(root, 'clock-a.json'), '{"v":2}');
    clock += 99;
    assert.equal(await cache.resolve(['clock-a.json']), first, 'within the bound: the remembered answer');
    clock += 1;
    const second = await cache.resolve(['clock-a.json']);
    assert.ok(second.kind === 'file' && first.kind === 'file');
    assert.notEqual(second.stats.ino, first.stats.ino, 'after the bound: the new file');
  });

  it('keeps an unchanged name after the bound without a full check', async () => {
    writeFileSync(path.join(root, 'clock-b.json'), '{"v":1}');
    const cache = new LookupCache(root, { revalidateAfterMs: 100, now });
    const first = await cache.resolve(['clock-b.json']);
    clock += 1000;
    // The very same object: a stat showed the same version, so nothing was looked up again.
    assert.equal(await cache.resolve(['clock-b.json']), first);
  });

  it('with a bound of 0, sees every change at the next lookup', async () => {
    writeFileSync(path.join(root, 'clock-c.json'), '{"v":1}');
    const cache = new LookupCache(root, { revalidateAfterMs: 0, now });
    const first = await cache.resolve(['clock-c.json']);
    replaceFile(path.join(root, 'clock-c.json'), '{"v":2}');
    const second = await cache.resolve(['clock-c.json']);
    assert.ok(first.kind === 'file' && second.kind === 'file');
    assert.notEqual(second.stats.ino, first.stats.ino);
    unlinkSync(path.join(root, 'clock-c.json'));
    assert.equal((await cache.resolve(['clock-c.json'])).kind, 'missing');
  });

  it('never remembers a missing name: a file written after a miss is found at once', async () => {
    const cache = new LookupCache(root, { revalidateAfterMs: 100, now });
    assert.equal((await cache.resolve(['clock-new.json'])).kind, 'missing');
    writeFileSync(path.join(root, 'clock-new.json'), '{}');
    assert.equal((await cache.resolve(['clock-new.json'])).kind, 'file');
  });

  it('within the bound gives only the file that was checked inside the root, then refuses the swapped symlink', async () => {
    const file = path.join(root, 'clock-swap.json');
    writeFileSync(file, '{"inside":true}');
    const cache = new LookupCache(root, { revalidateAfterMs: 100, now });
    const before = await cache.resolve(['clock-swap.json']);
    swapForSymlink(file, '../secret.txt');
    const within = realPathOf(await cache.resolve(['clock-swap.json']));
    assert.equal(within, realPathOf(before));
    assert.ok(within !== undefined && isInside(root, within));
    clock += 100;
    assert.equal((await cache.resolve(['clock-swap.json'])).kind, 'missing');
  });

  it('with a bound of 0, refuses the swapped symlink at the next lookup', async () => {
    const file = path.join(root, 'clock-swap0.json');
    writeFileSync(file, '{"inside":true}');
    const cache = new LookupCache(root, { revalidateAfterMs: 0, now });
    assert.equal((await cache.resolve(['clock-swap0.json'])).kind, 'file');
    swapForSymlink(file, '../secret.txt');
    assert.equal((await cache.resolve(['clock-swap0.json'])).kind, 'missing');
  });
});

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
