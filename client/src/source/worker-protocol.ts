// Messages between the map (main thread) and the chunk worker.
import type { Box3, CubeIndex } from '../../../format/cube-index.js';
import type { FaceRecord } from '../../../format/face-page.js';
import type { DrawBlocks } from './draw-ranges.js';
import type { HeadStartResult } from './head-start.js';

/** not-requested -> requested -> received -> gpu -> evicted (-> requested ...); failed: corrupt or gave up. */
export type ChunkStatus = 'not-requested' | 'requested' | 'received' | 'gpu' | 'evicted' | 'failed';

export interface SourceOptions {
  /** Chunk requests on the network (or waiting to be retried) at once: a chunk whose body has come no longer counts while it is checked and decoded. */
  concurrency: number;
  retries: number;
  backoffMs: number;
  maxBackoffMs: number;
  /**
   * The prefetch margin is fetched once the view has rested this long (ms): during a zoom or a
   * pan each view's margin is soon left behind, and would only take bandwidth and data. Longer
   * where the map's frames take longer (ViewRequest.frameMs): one and a half frames. 0: no wait.
   */
  marginRestMs: number;
}

export interface ViewRequest {
  seq: number;
  /** The ground box on screen and the box with the prefetch margin. */
  visible: [number, number, number, number];
  margin: [number, number, number, number];
  /** The z range of the slicing surface over the margin box. */
  zMin: number;
  zMax: number;
  /** View centre and base z, to fetch the nearest chunks first. */
  centerX: number;
  centerY: number;
  z: number;
  /** Views the map will show soon, in order (a flight's path): their chunks are fetched after the view's own. */
  ahead?: AheadView[];
  /** How long the map's frames take on this device (ms, FramePace); 0 or absent: not known. */
  frameMs?: number;
}

/** A view to come: its ground box, the z range of its surface, its centre and base z. */
export interface AheadView {
  box: [number, number, number, number];
  zMin: number;
  zMax: number;
  centerX: number;
  centerY: number;
  z: number;
}

export type ToWorker =
  | { type: 'init'; url: string; options: SourceOptions }
  /** index.json read and checked, or why it could not be had: the map reads it while the worker starts (ChunkSource). */
  | { type: 'index'; index: CubeIndex }
  | { type: 'index-unavailable'; error: SourceErrorInfo }
  /** The map is fetching these files for the worker (its first view's floor chunks, head-start.ts), */
  | { type: 'head-start'; urls: string[] }
  /** and here is what became of one (its body, a client error's status, or null: failed otherwise). */
  | { type: 'head-start-result'; url: string; result: HeadStartResult }
  | { type: 'view'; view: ViewRequest }
  | { type: 'uploaded'; file: string }
  | { type: 'evicted'; files: string[] }
  | { type: 'features'; id: number; faces: number[] }
  | { type: 'attributes'; id: number; features: number[] }
  | { type: 'loaded-urls'; id: number }
  /** The page is online again: files that failed for a passing cause are asked for again (ChunkScheduler.retryFailed). */
  | { type: 'online' };

export interface SourceErrorInfo {
  /** 'style': the `style` option does not fit the cube (the map draws the cube's own). */
  /** worker: the map's worker could not be started (its url is the cube's index.json). */
  kind: 'http' | 'network' | 'corrupt' | 'index' | 'style' | 'worker';
  message: string;
  url: string;
  status?: number;
  /** The chunk file, when a chunk failed. */
  file?: string;
}

/** A decoded chunk as transferred: views over one buffer (moved, not copied). */
export interface ChunkPayload {
  kind: 'surfaces';
  file: string;
  /** The index leaf's box (z1: the top of its relevance). */
  bbox: Box3;
  buffer: ArrayBuffer;
  vertexCount: number;
  triangleCount: number;
  originX: number;
  originY: number;
  vertexByteOffset: number;
  vertexByteLength: number;
  indexByteOffset: number;
  indexSize: 2 | 4;
  /** The triangles' order for drawing: how many a slice up to some z can show (draw-ranges.ts). */
  blocks: DrawBlocks;
  /** False when crypto.subtle was unavailable (not a secure context) to check the hash. */
  verified: boolean;
}

/**
 * A decoded line chunk as transferred: every segment its lines have at some z (format/line-chunk.ts,
 * lineSegments), ready to be drawn as instances, and per line what picking names.
 */
export interface LinePayload {
  kind: 'lines';
  file: string;
  /** The index entry's box (z0, z1: the lines' z range). */
  bbox: Box3;
  originX: number;
  originY: number;
  segmentCount: number;
  /**
   * Per segment (14 floats): ax, ay, bx, by (relative to the origin), z0, z1: drawn for
   * z0 <= z < z1; where a and b glide to (atx, aty, btx, bty) and when (aFrom, aTo, bFrom, bTo),
   * as format/line-glide.ts says.
   */
  segments: Float32Array;
  /** Per segment: the line it belongs to, and that line's style rule (format/line-style.ts). */
  segmentLine: Uint32Array;
  segmentRule: Uint16Array;
  /**
   * Per line: its class, its input feature (-1: none) and its z range with its ramps (z0,
   * z0Full, z1Full, z1: format/line-ramp.ts).
   */
  lineClass: Uint16Array;
  lineFeature: Int32Array;
  lineRamp: Float32Array;
  verified: boolean;
}

/** Either kind of chunk, as the map receives it. */
export type Payload = ChunkPayload | LinePayload;

/** Bytes a line segment takes on the GPU (gpu-line-chunk.ts): its 14 floats and its line's ramp (float32), and its rule (u16). */
export const GPU_SEGMENT_BYTES = 4 * 18 + 2;

/** Bytes a payload takes on the GPU. */
export function payloadBytes(p: Payload): number {
  return p.kind === 'lines' ? p.segmentCount * GPU_SEGMENT_BYTES : p.vertexByteLength + p.indexSize * 3 * p.triangleCount;
}

/** A face's record from its face page, with its input feature's attributes. */
export interface FeatureInfo extends FaceRecord {
  properties: Record<string, unknown> | null;
}

/** The worker's answer to a view: the chunks it needs. */
export interface NeededChunks {
  seq: number;
  visible: string[];
  margin: string[];
  /** Chunks of the views ahead that the view itself does not need, in fetch order. */
  ahead: string[];
  /**
   * Floor chunks drawn under a first view just above the floor's top until every chunk it shows
   * is on the GPU (interimFloor in floor-choice.ts); usually none.
   */
  interim: string[];
  /** False while sub-index files the view reaches are still loading. */
  indexComplete: boolean;
  queryMs: number;
}

export type FromWorker =
  | ({ type: 'needed'; visited: number } & NeededChunks)
  | { type: 'status'; file: string; status: ChunkStatus }
  | { type: 'chunk'; chunk: Payload }
  | { type: 'error'; error: SourceErrorInfo }
  | { type: 'features'; id: number; features: (FeatureInfo | null)[]; error?: string }
  | { type: 'attributes'; id: number; properties: (Record<string, unknown> | null)[]; error?: string }
  | { type: 'loaded-urls'; id: number; urls: string[] };
