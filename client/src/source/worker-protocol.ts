// Messages between the map (main thread) and the chunk worker.
import type { Box3, CubeMeta } from '../../../format/cube-index.js';
import type { FaceRecord } from '../../../format/face-page.js';

/** not-requested -> requested -> received -> gpu -> evicted (-> requested ...); failed: corrupt or gave up. */
export type ChunkStatus = 'not-requested' | 'requested' | 'received' | 'gpu' | 'evicted' | 'failed';

export interface SourceOptions {
  /** Chunk requests in flight at once. */
  concurrency: number;
  retries: number;
  backoffMs: number;
  maxBackoffMs: number;
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
  | { type: 'view'; view: ViewRequest }
  | { type: 'uploaded'; file: string }
  | { type: 'evicted'; files: string[] }
  | { type: 'features'; id: number; faces: number[] }
  | { type: 'loaded-urls'; id: number };

export interface SourceErrorInfo {
  /** 'style': the `style` option does not fit the cube (the map draws the cube's own). */
  kind: 'http' | 'network' | 'corrupt' | 'index' | 'style';
  message: string;
  url: string;
  status?: number;
  /** The chunk file, when a chunk failed. */
  file?: string;
}

/** A decoded chunk as transferred: views over one buffer (moved, not copied). */
export interface ChunkPayload {
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
  /** False when crypto.subtle was unavailable (not a secure context) to check the hash. */
  verified: boolean;
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
  /** False while sub-index files the view reaches are still loading. */
  indexComplete: boolean;
  queryMs: number;
}

export type FromWorker =
  | { type: 'meta'; meta: CubeMeta }
  | ({ type: 'needed'; visited: number } & NeededChunks)
  | { type: 'status'; file: string; status: ChunkStatus }
  | { type: 'chunk'; chunk: ChunkPayload }
  | { type: 'error'; error: SourceErrorInfo }
  // The index could not be loaded: nothing will follow.
  | { type: 'index-failed'; error: SourceErrorInfo }
  | { type: 'features'; id: number; features: (FeatureInfo | null)[]; error?: string }
  | { type: 'loaded-urls'; id: number; urls: string[] };
