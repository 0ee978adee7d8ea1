// The service worker's cache pruning: which files an index names, and which cached files a new
// build leaves unused (hand-made indexes and URL lists).
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { isSubIndex, referencedFiles, unusedCubeFiles } from './cube-files.js';

describe('cube files named by an index', () => {
  test('chunks, pages and sub-indexes are found, nothing else', () => {
    const index = JSON.stringify({
      format: 'ssc-index',
      meta: { name: 'c-00000000.bin is only a name here', faces: { pages: [{ first: 0, file: 'f-0011223344556677.bin' }] }, attributes: { pages: [{ first: 0, file: 'a-8899aabbccddeeff.json' }] } },
      root: { bbox: [0, 0, 0, 1, 1, 1], children: [{ bbox: [], file: 'c-0123456789abcdef.bin', sha256: 'ab'.repeat(32) }, { bbox: [], ref: 'i-fedcba9876543210.json', chunks: 3 }] },
    });
    assert.deepEqual(referencedFiles(index).sort(), ['a-8899aabbccddeeff.json', 'c-0123456789abcdef.bin', 'f-0011223344556677.bin', 'i-fedcba9876543210.json']);
    // Pretty-printed JSON too.
    assert.deepEqual(referencedFiles('{\n  "file" : "c-0123456789abcdef.bin"\n}'), ['c-0123456789abcdef.bin']);
    assert.equal(isSubIndex('i-fedcba9876543210.json'), true);
    assert.equal(isSubIndex('index.json'), false);
    assert.equal(isSubIndex('c-0123456789abcdef.bin'), false);
  });

  test('the unused files are the cached ones beside the index that it does not name', () => {
    const index = 'https://cdn.example/maps/otterlo/index.json';
    const cached = [
      'https://cdn.example/maps/otterlo/c-1111111111111111.bin', // kept: named
      'https://cdn.example/maps/otterlo/c-2222222222222222.bin', // the old build's
      'https://cdn.example/maps/otterlo/f-3333333333333333.bin?v=1', // named, with a query
      'https://cdn.example/maps/other/c-2222222222222222.bin', // another cube
      'https://cdn.example/maps/otterlo/deeper/c-4444444444444444.bin', // not directly beside it
      'https://elsewhere.example/maps/otterlo/c-5555555555555555.bin', // another origin
    ];
    const named = new Set(['c-1111111111111111.bin', 'f-3333333333333333.bin']);
    assert.deepEqual(unusedCubeFiles(cached, index, named), ['https://cdn.example/maps/otterlo/c-2222222222222222.bin']);
    assert.deepEqual(unusedCubeFiles([], index, named), []);
  });
});
