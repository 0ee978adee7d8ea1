// LookupCache on a clock of its own: a name found inside the root is answered from memory for
// at most the bound, then looked at again; a missing name is never remembered; and a symlink
// swapped in to lead out of the root is never followed, not even right after the name was
// remembered. What the server makes of it is in test/disk-changes.test.ts.
import assert from 'node:assert/strict';
import { realpathSync, unlinkSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { after, before, describe, it } from 'node:test';
import { LookupCache } from './lookup-cache.js';
import { isInside, type Resolved } from './resolve-file.js';
import { makeFixture, replaceFile, swapForSymlink, type Fixture } from './test/fixture.js';

function realPathOf(r: Resolved): string | undefined {
  return r.kind === 'missing' ? undefined : r.realPath;
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
