// One chunk from the network to GPU-ready arrays: fetch (with retries), gunzip when the body
// is still gzip, decode and check it, and compare its SHA-256 with its name (or the index's).
import { expectedDigest, type ChunkLeaf } from '../../../format/cube-index.js';
import { decodeSurfaceFile } from '../../../format/surface-file.js';
import { FormatError } from '../../../format/format-error.js';
import { gunzipIfNeeded } from './gunzip.js';
import { sha256Hex } from './sha256.js';
import { orderForDrawing } from './draw-ranges.js';
import { keepUpwardTriangles } from './upward-triangles.js';
import { fetchBytes, type RetryOptions } from './fetch-retry.js';
import type { ChunkPayload } from './worker-protocol.js';

export class ChunkCorrupt extends Error {
  constructor(message: string) {
    super(message);
    this.name = 'ChunkCorrupt';
  }
}

/**
 * A chunk file of either kind, fetched, gunzipped when the body is still gzip, decoded by
 * `decode` (which checks the structure) and its SHA-256 compared with the digits in its name (or
 * the whole SHA-256 in a version 1 index); `verified` is false where no crypto.subtle could check
 * the hash. Every failure of the file is ChunkCorrupt.
 */
export async function fetchChunkFile<T>(leaf: { file: string; sha256?: string | undefined }, url: string, retry: RetryOptions, signal: AbortSignal, decode: (bytes: ArrayBuffer, name: string) => T | Promise<T>): Promise<{ data: T; verified: boolean }> {
  const raw = await fetchBytes(url, retry, signal);
  let bytes: ArrayBuffer;
  try {
    bytes = await gunzipIfNeeded(raw);
  } catch (err) {
    throw new ChunkCorrupt(`${leaf.file}: bad gzip body (${(err as Error).message})`);
  }
  let data: T;
  try {
    data = await decode(bytes, leaf.file);
  } catch (err) {
    if (err instanceof FormatError) throw new ChunkCorrupt(err.message);
    throw err;
  }
  const hash = await sha256Hex(bytes);
  const expected = expectedDigest(leaf);
  if (hash !== null && !hash.startsWith(expected)) throw new ChunkCorrupt(`${leaf.file}: SHA-256 ${hash} does not match ${leaf.sha256 ? 'the index' : 'its name'} (${expected})`);
  return { data, verified: hash !== null };
}

export async function fetchChunk(leaf: ChunkLeaf, url: string, retry: RetryOptions, signal: AbortSignal): Promise<ChunkPayload> {
  const { data: chunk, verified } = await fetchChunkFile(leaf, url, retry, signal, decodeSurfaceFile);
  // After the hash check: this rewrites the index section in place.
  const triangleCount = keepUpwardTriangles(chunk.positions, chunk.indices);
  const blocks = orderForDrawing(chunk.positions, chunk.indices, triangleCount);
  return {
    kind: 'surfaces',
    file: leaf.file,
    bbox: leaf.bbox,
    buffer: chunk.positions.buffer as ArrayBuffer,
    vertexCount: chunk.vertexCount,
    triangleCount,
    originX: chunk.originX,
    originY: chunk.originY,
    vertexByteOffset: chunk.vertexByteOffset,
    vertexByteLength: chunk.vertexByteLength,
    indexByteOffset: chunk.indices.byteOffset,
    indexSize: chunk.indices.BYTES_PER_ELEMENT as 2 | 4,
    blocks,
    verified,
  };
}
