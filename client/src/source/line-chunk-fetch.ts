// One line chunk from the network to drawable segments: fetched and checked as a surface chunk
// is (chunk-fetch.ts), then every segment its lines have at some z listed with that z range
// (format/line-chunk.ts, lineSegments): the GPU tests each pixel's slice z against its
// segment's range, as the CPU slicer does.
import type { LineChunkLeaf } from '../../../format/cube-index.js';
import { decodeLineChunk, lineOfChunk, lineSegments, type LineChunkData } from '../../../format/line-chunk.js';
import { fetchChunkFile } from './chunk-fetch.js';
import type { RetryOptions } from './fetch-retry.js';
import type { LinePayload } from './worker-protocol.js';

export async function fetchLineChunk(leaf: LineChunkLeaf, url: string, retry: RetryOptions, signal: AbortSignal): Promise<LinePayload> {
  const { data, verified } = await fetchChunkFile(leaf, url, retry, signal, decodeLineChunk);
  return { ...lineSegmentPayload(data), file: leaf.file, bbox: leaf.bbox, verified };
}

/** A decoded line chunk's segments, relative to its origin, in line order. */
export function lineSegmentPayload(c: LineChunkData): Omit<LinePayload, 'file' | 'bbox' | 'verified'> {
  const coords: number[] = [];
  const owner: number[] = [];
  for (let i = 0; i < c.lineCount; i++) {
    for (const s of lineSegments(lineOfChunk(c, i))) {
      // lineOfChunk adds the origin in float64: taking it off again gives the stored float32 back.
      coords.push(s.ax - c.originX, s.ay - c.originY, s.bx - c.originX, s.by - c.originY, s.z0, s.z1);
      owner.push(i);
    }
  }
  const segmentLine = Uint32Array.from(owner);
  const segmentRule = new Uint16Array(owner.length);
  for (let k = 0; k < owner.length; k++) segmentRule[k] = c.lineClass[owner[k]!]!;
  return {
    kind: 'lines',
    originX: c.originX,
    originY: c.originY,
    segmentCount: owner.length,
    segments: Float32Array.from(coords),
    segmentLine,
    segmentRule,
    lineClass: c.lineClass.slice(),
    lineFeature: c.lineFeature.slice(),
    lineZ: Float32Array.from({ length: 2 * c.lineCount }, (_, k) => (k % 2 === 0 ? c.zStart : c.zEnd)[k >> 1]!),
  };
}
