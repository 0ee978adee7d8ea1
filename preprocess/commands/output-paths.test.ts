// Paths that cannot be read or written end in one clear line and a non-zero exit code, with
// nothing written: no stack trace, no half-written file, no folder made on the way.
import test, { after, before } from 'node:test';
import assert from 'node:assert/strict';
import { chmodSync, existsSync, mkdirSync, readdirSync } from 'node:fs';
import path from 'node:path';
import { startSscSession, type SscSession } from '../../testing/run-ssc.js';
import { collection, feature, polygon, rect, writeCase, type Case } from '../../testing/topology-cases.js';

let ssc: SscSession;
before(() => {
  ssc = startSscSession();
});
after(() => ssc.close());

function twoSquares(t: { after: (fn: () => void) => void }): Case {
  return writeCase(t, 'two.geojson', collection([feature('a', polygon(rect(0, 0, 10, 10))), feature('b', polygon(rect(10, 0, 20, 10)))]));
}

/** Runs ssc and expects exactly one line on stderr, equal to `line` (or matching it), exit code 1. */
async function expectOneLine(args: string[], line: string | RegExp): Promise<void> {
  const r = await ssc.run(args);
  assert.equal(r.code, 1, r.stderr);
  assert.equal(r.stdout, '');
  const lines = r.stderr.trimEnd().split('\n');
  assert.equal(lines.length, 1, `one line:\n${r.stderr}`);
  if (typeof line === 'string') assert.equal(lines[0], line);
  else assert.match(lines[0]!, line);
}

test('--out in a folder that does not exist', async (t) => {
  const c = twoSquares(t);
  const missing = path.join(c.dir, 'no-such-folder');
  await expectOneLine(['generalize', c.input, '--style', c.style, '--out', path.join(missing, 'x.tgap')],
    `ssc generalize: --out ${path.join(missing, 'x.tgap')}: the folder ${missing} does not exist`);
  await expectOneLine(['build', c.input, '--style', c.style, '--out', path.join(missing, 'cube')],
    `ssc build: --out ${path.join(missing, 'cube')}: the folder ${missing} does not exist`);
  await expectOneLine(['generalize', c.input, '--style', c.style, '--out', path.join(c.dir, 'x.tgap'), '--problems', path.join(missing, 'p.geojson')],
    `ssc generalize: --problems ${path.join(missing, 'p.geojson')}: the folder ${missing} does not exist`);
  assert.equal(existsSync(missing), false, 'the folder is not made');
  assert.deepEqual(readdirSync(c.dir).sort(), c.files, 'nothing written');
});

test('an output that is a directory, or a directory output that is a file', async (t) => {
  const c = twoSquares(t);
  const dir = path.join(c.dir, 'a-folder');
  mkdirSync(dir);
  await expectOneLine(['generalize', c.input, '--style', c.style, '--out', dir], `ssc generalize: --out ${dir}: is a directory (a file is written here)`);
  await expectOneLine(['build', c.input, '--style', c.style, '--out', c.style], `ssc build: --out ${c.style}: is a file (a directory is written here)`);
  assert.deepEqual(readdirSync(dir), [], 'nothing written into the folder');
});

test('an image written into a folder that does not exist (ssc map)', async (t) => {
  const c = twoSquares(t);
  const tgap = path.join(c.dir, 'two.tgap');
  assert.equal((await ssc.run(['generalize', c.input, '--style', c.style, '--out', tgap, '--quiet'])).code, 0);
  const png = path.join(c.dir, 'missing', 'map.png');
  await expectOneLine(['map', tgap, '--step', '0', '--size', '16x16', '--out', png], `ssc map: cannot write ${png}: the folder ${path.dirname(png)} does not exist`);
});

test('an input that is missing, a directory, or unreadable', async (t) => {
  const c = twoSquares(t);
  const out = path.join(c.dir, 'x.tgap');
  const missing = path.join(c.dir, 'missing.geojson');
  await expectOneLine(['generalize', missing, '--out', out], `ssc generalize: ${missing}: cannot read input: no such file or directory`);
  await expectOneLine(['build', missing, '--out', path.join(c.dir, 'cube')], `ssc build: ${missing}: cannot read input: no such file or directory`);
  await expectOneLine(['generalize', c.dir, '--out', out], `ssc generalize: ${c.dir}: cannot read input: it is a directory`);
  await t.test('unreadable (not as root, who reads everything)', { skip: process.getuid?.() === 0 }, async () => {
    chmodSync(c.input, 0);
    await expectOneLine(['generalize', c.input, '--style', c.style, '--out', out], `ssc generalize: ${c.input}: cannot read input: permission denied`);
  });
  assert.equal(existsSync(out), false);
});
