// One file's bytes for the surfaces of several chunks: the vertices a chunk border split are
// counted once, so two halves of a square weigh what the square does as one chunk file.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { decodeChunk } from '../../format/chunk.js';
import { encodeChunk, type ChunkInput } from '../../format/chunk-encode.js';
import { unchunkedBytes } from './unchunked-bytes.js';

const faces = { upper: [7, 7, 7], lower: [0, 0, 0], upperClass: [2, 2, 2], lowerClass: [0xffff, 0xffff, 0xffff] };
/** One triangle of the square (0,0) (4,0) (4,4) (0,4) at z 5, in a chunk with its origin at (100, 200). */
const half = (corners: number[][]): ChunkInput => ({
  originX: 100, originY: 200, box: Float32Array.of(0, 0, 5, 4, 4, 5),
  positions: corners.flatMap(([x, y]) => [x!, y!, 5]), ...faces, indices: [0, 1, 2],
});

test('two chunks splitting a square weigh, unchunked, what the square weighs as one chunk file', async () => {
  const a = await decodeChunk(encodeChunk(half([[0, 0], [4, 0], [4, 4]])));
  const b = await decodeChunk(encodeChunk(half([[0, 0], [4, 4], [0, 4]])));
  const whole = encodeChunk({
    originX: 100, originY: 200, box: Float32Array.of(0, 0, 5, 4, 4, 5),
    positions: [0, 0, 5, 4, 0, 5, 4, 4, 5, 0, 4, 5], upper: [7, 7, 7, 7], lower: [0, 0, 0, 0], upperClass: [2, 2, 2, 2],
    lowerClass: [0xffff, 0xffff, 0xffff, 0xffff], indices: [0, 1, 2, 0, 2, 3],
  });
  assert.equal(unchunkedBytes([a, b]), whole.byteLength);
  assert.ok(unchunkedBytes([a, b]) < encodeChunk(half([[0, 0], [4, 0], [4, 4]])).byteLength * 2, 'less than the two chunks');
});
