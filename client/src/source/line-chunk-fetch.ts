// One line chunk from the network to drawable segments: fetched and checked as a surface chunk
// is (chunk-fetch.ts), then every segment its lines have at some z listed with that z range
// with that z range and how its ends glide as simplification takes them (format/line-glide.ts):
// the GPU tests each pixel's slice z against its segment's range, as the CPU slicer does, and
// draws the segment's ends where they are at that z, the line's width by its ramp there
// (format/line-ramp.ts).
import type { LineChunkLeaf } from '../../../format/cube-index.js';
import { decodeLineChunk, lineOfChunk, type LineChunkData } from '../../../format/line-chunk.js';
import { glidingSegments } from '../../../format/line-glide.js';
import { lineRamp } from '../../../format/line-ramp.js';
import type { ScaleInfo } from '../../../format/scale.js';
import { fetchChunkFile } from './chunk-fetch.js';
import type { RetryOptions } from './fetch-retry.js';
import type { LinePayload } from './worker-protocol.js';

export async function fetchLineChunk(leaf: LineChunkLeaf, url: string, info: ScaleInfo, retry: RetryOptions, signal: AbortSignal): Promise<LinePayload> {
  const { data, verified } = await fetchChunkFile(leaf, url, retry, signal, decodeLineChunk);
  return { ...lineSegmentPayload(data, info), file: leaf.file, bbox: leaf.bbox, verified };
}

/**
 * A decoded line chunk's segments, relative to its origin, lines in the order drawn: by rule,
 * then as stored (a later rule over an earlier one, as the CPU drawer paints them).
 */
export function lineSegmentPayload(c: LineChunkData, info: ScaleInfo): Omit<LinePayload, 'file' | 'bbox' | 'verified'> {
  const coords: number[] = [];
  const owner: number[] = [];
  const order = Array.from({ length: c.lineCount }, (_, i) => i).sort((a, b) => c.lineRule[a]! - c.lineRule[b]! || a - b);
  for (const i of order) {
    for (const s of glidingSegments(lineOfChunk(c, i), info)) {
      // lineOfChunk adds the origin in float64: taking it off again gives the stored float32 back.
      const ox = c.originX, oy = c.originY;
      coords.push(s.ax - ox, s.ay - oy, s.bx - ox, s.by - oy, s.z0, s.z1, s.atx - ox, s.aty - oy, s.btx - ox, s.bty - oy, s.aFrom, s.aTo, s.bFrom, s.bTo);
      owner.push(i);
    }
  }
  const segmentLine = Uint32Array.from(owner);
  const segmentRule = new Uint16Array(owner.length);
  for (let k = 0; k < owner.length; k++) segmentRule[k] = c.lineRule[owner[k]!]!;
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
    lineRamp: Float32Array.from(Array.from({ length: c.lineCount }, (_, i) => lineRamp(info, c.zStart[i]!, c.zEnd[i]!)).flatMap((r) => [r.z0, r.z0Full, r.z1Full, r.z1])),
  };
}
