// CubeReader: a chunk is read only when its bytes are the ones its name (index version 2) or the
// index's SHA-256 (version 1) names. faceEnds: each face's stepHigh from every face page of a
// cube directory, Infinity for a face alive to the top; a page that cannot be read or decoded is
// an error naming the file.
import assert from 'node:assert/strict';
import { mkdtemp, rm, unlink, writeFile } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { test } from 'node:test';
import { encodeFacePage, type FaceFields } from '../../format/face-page.js';
import { handMadeCube, indexFile, leafFor, namedLeaf, squareChunk } from '../../testing/hand-made-cube.js';
import { InputError } from '../io/errors.js';
import { CubeReader } from './read-cube.js';

test('chunks: read when their bytes are the ones named, refused by file when not', async (t) => {
  const dir = await mkdtemp(path.join(tmpdir(), 'read-cube-'));
  t.after(() => rm(dir, { recursive: true, force: true }));
  const a = squareChunk(0), b = squareChunk(1);
  const named = namedLeaf([0, 0, 0, 1, 1, 10], a);
  const v1 = leafFor('c-b.bin', [1, 0, 0, 2, 1, 10], b);
  await writeFile(path.join(dir, 'index.json'), indexFile({ bbox: [0, 0, 0, 2, 1, 10], children: [named, v1] }));
  await writeFile(path.join(dir, named.file), a);
  await writeFile(path.join(dir, 'c-b.bin'), b);
  const cube = await CubeReader.open(dir);
  assert.equal((await cube.chunk(named)).originX, 1000);
  assert.equal((await cube.chunk(v1)).originX, 1001);
  // Each file replaced by the other's bytes: the same length, a valid chunk, the wrong one.
  await writeFile(path.join(dir, named.file), b);
  await writeFile(path.join(dir, 'c-b.bin'), a);
  await assert.rejects(cube.chunk(named), (e: unknown) => e instanceof InputError && e.file === path.join(dir, named.file) && /is corrupt: its SHA-256 does not match its name/.test(e.message));
  await assert.rejects(cube.chunk(v1), (e: unknown) => e instanceof InputError && e.file === path.join(dir, 'c-b.bin') && /is corrupt: its SHA-256 does not match the index/.test(e.message));
});

test('face ends: each face\'s stepHigh from every page, Infinity for a face alive to the top', async (t) => {
  const dir = await mkdtemp(path.join(tmpdir(), 'read-cube-'));
  t.after(() => rm(dir, { recursive: true, force: true }));
  // A cube of 100 steps; faces 0..4: 0 the outside and 3 alive to the top (stepHigh 101),
  // 1 ends at 3, 2 at 8, 4 at the top, step 100.
  const faces: FaceFields[] = [
    { classIndex: 0, feature: -1, stepLow: 0, stepHigh: 101, mergedInto: -1 },
    { classIndex: 0, feature: 0, stepLow: 0, stepHigh: 3, mergedInto: 2 },
    { classIndex: 0, feature: 1, stepLow: 0, stepHigh: 8, mergedInto: 3 },
    { classIndex: 0, feature: 2, stepLow: 3, stepHigh: 101, mergedInto: -1 },
    { classIndex: 0, feature: 3, stepLow: 8, stepHigh: 100, mergedInto: 0 },
  ];
  const files = handMadeCube([{ file: 'c-0.bin', bbox: [0, 0, 0, 10, 10, 100] }]).files;
  const index = JSON.parse(new TextDecoder().decode(files.get('index.json'))) as { meta: { faces: unknown } };
  index.meta.faces = { count: 5, pageSize: 3, pages: [{ first: 0, file: 'f-0.bin' }, { first: 3, file: 'f-1.bin' }] };
  await writeFile(path.join(dir, 'index.json'), JSON.stringify(index));
  await writeFile(path.join(dir, 'f-0.bin'), encodeFacePage(faces, 0, 3));
  await writeFile(path.join(dir, 'f-1.bin'), encodeFacePage(faces, 3, 2));
  const cube = await CubeReader.open(dir);
  assert.deepEqual([...(await cube.faceEnds())], [Infinity, 3, 8, Infinity, 100]);
  await writeFile(path.join(dir, 'f-1.bin'), new Uint8Array(8));
  await assert.rejects(cube.faceEnds(), (e: unknown) => e instanceof InputError && e.file === path.join(dir, 'f-1.bin') && /is not a valid face page/.test(e.message));
  await unlink(path.join(dir, 'f-1.bin'));
  await assert.rejects(cube.faceEnds(), (e: unknown) => e instanceof InputError && e.file === path.join(dir, 'f-1.bin') && /cannot read face page/.test(e.message));
});
