// CubeReader.faceEnds: each face's stepHigh from every face page of a cube directory, Infinity
// for a face alive to the top; a page that cannot be read or decoded is an error naming the file.
import assert from 'node:assert/strict';
import { mkdtemp, rm, unlink, writeFile } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { test } from 'node:test';
import { encodeFacePage, type FaceFields } from '../../format/face-page.js';
import { handMadeCube } from '../../testing/hand-made-cube.js';
import { InputError } from '../io/errors.js';
import { CubeReader } from './read-cube.js';

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
