// Face ends from the face pages: a face's stepHigh, from the pages that hold the faces asked for,
// each fetched once, and Infinity for a face alive to the top of the cube; on two hand-made pages.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { encodeFacePage, type FaceFields } from '../../../format/face-page.js';
import { installFakeFetch } from '../../../testing/fake-fetch.js';
import { serveFiles } from '../../../testing/hand-made-cube.js';
import { FeaturePages } from './feature-pages.js';

const BASE = 'https://maps.test/cube/';

test('face ends: each face\'s stepHigh, Infinity for a face alive to the top, from the pages that hold the faces asked for', async (t) => {
  // Faces 0..4: 0 the outside; 1 ends at 3, 2 at 8; 3 lives to the top (stepHigh above the
  // cube's 10 steps); 4 ends at the top, step 10.
  const faces: FaceFields[] = [
    { classIndex: 0, feature: -1, stepLow: 0, stepHigh: 11, mergedInto: -1 },
    { classIndex: 1, feature: 0, stepLow: 0, stepHigh: 3, mergedInto: 2 },
    { classIndex: 2, feature: 1, stepLow: 0, stepHigh: 8, mergedInto: 3 },
    { classIndex: 2, feature: 2, stepLow: 3, stepHigh: 11, mergedInto: -1 },
    { classIndex: 1, feature: 3, stepLow: 8, stepHigh: 10, mergedInto: 0 },
  ];
  const files = new Map([['f-0.bin', encodeFacePage(faces, 0, 3)], ['f-1.bin', encodeFacePage(faces, 3, 2)]]);
  const fetch = installFakeFetch(t, serveFiles(BASE, files));
  const pages = new FeaturePages(
    { count: 5, pageSize: 3, pages: [{ first: 0, file: 'f-0.bin' }, { first: 3, file: 'f-1.bin' }] },
    { count: 0, pageSize: 1, pages: [] },
    (f) => BASE + f,
    { retries: 0, backoffMs: 0, maxBackoffMs: 0 },
  );
  // Faces of the first page only: the second is not fetched.
  const first = await pages.faceEnds(Uint32Array.of(1, 2, 1), 10);
  assert.deepEqual([0, 1, 2].map(first), [Infinity, 3, 8]);
  assert.deepEqual(fetch.urls(), [`${BASE}f-0.bin`]);
  const all = await pages.faceEnds(Uint32Array.of(4, 0, 3), 10);
  assert.deepEqual([0, 1, 2, 3, 4, 5].map(all), [Infinity, 3, 8, Infinity, 10, Infinity]);
  // Picking afterwards reads the same pages: nothing fetched again.
  assert.equal((await pages.lookup(2))?.stepHigh, 8);
  assert.deepEqual(fetch.urls(), [`${BASE}f-0.bin`, `${BASE}f-1.bin`]);
});
