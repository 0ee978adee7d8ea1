// The chunk file (docs/FORMAT.md, "Chunk file"): surface triangles with per-vertex positions
// relative to the chunk's origin, the faces above and below, and their classes. Encoder,
// decoder and the vertex layout the GPU binds as it is. Pure: used by the build (Node), the
// CPU slicer and the map's worker.
import { FormatError } from './format-error.js';

export const CHUNK_MAGIC = 0x43435353; // "SSCC"
export const CHUNK_VERSION = 1;
export const NO_CLASS = 0xffff;
const HEADER = 64;

export interface ChunkData {
  vertexCount: number;
  triangleCount: number;
  originX: number;
  originY: number;
  /** x0, y0, z0, x1, y1, z1 with x, y relative to the origin. */
  box: Float32Array;
  /** x, y (relative), z per vertex. */
  positions: Float32Array;
  upper: Uint32Array;
  lower: Uint32Array;
  upperClass: Uint16Array;
  lowerClass: Uint16Array;
  indices: Uint16Array | Uint32Array;
}

/** A decoded chunk also tells where its vertex columns lie in its buffer (one GPU upload). */
export interface DecodedChunk extends ChunkData {
  /** Byte offset and length of the vertex columns (positions, upper, lower, classes). */
  vertexByteOffset: number;
  vertexByteLength: number;
}

/**
 * The vertex section: one column after the other, each `vertexCount` entries long, in this
 * order. The renderer binds these columns as vertex attributes straight from the file's bytes.
 */
export const VERTEX_COLUMNS = [
  { name: 'positions', components: 3, type: 'f32', bytes: 12 },
  { name: 'upper', components: 1, type: 'u32', bytes: 4 },
  { name: 'lower', components: 1, type: 'u32', bytes: 4 },
  { name: 'upperClass', components: 1, type: 'u16', bytes: 2 },
  { name: 'lowerClass', components: 1, type: 'u16', bytes: 2 },
] as const;

export type VertexColumn = (typeof VERTEX_COLUMNS)[number];

/** Bytes per vertex over all columns (24). */
export const VERTEX_BYTES = VERTEX_COLUMNS.reduce((n, c) => n + c.bytes, 0);

/** Byte offset of column `i` from the start of the vertex section. */
export function vertexColumnOffset(i: number, vertexCount: number): number {
  let o = 0;
  for (let k = 0; k < i; k++) o += VERTEX_COLUMNS[k]!.bytes * vertexCount;
  return o;
}

const pad4 = (n: number): number => (n + 3) & ~3;

/** Bytes per index: 2 while every vertex fits a u16. */
export const indexSizeFor = (vertices: number): 2 | 4 => (vertices <= 0xffff ? 2 : 4);

export function chunkByteLength(vertices: number, triangles: number): number {
  return HEADER + pad4(vertices * VERTEX_BYTES) + pad4(triangles * 3 * indexSizeFor(vertices));
}

type Columns = Pick<ChunkData, VertexColumn['name']>;

function columnViews(buf: ArrayBufferLike, base: number, V: number): Columns {
  const at = (i: number): number => base + HEADER + vertexColumnOffset(i, V);
  return {
    positions: new Float32Array(buf, at(0), 3 * V),
    upper: new Uint32Array(buf, at(1), V),
    lower: new Uint32Array(buf, at(2), V),
    upperClass: new Uint16Array(buf, at(3), V),
    lowerClass: new Uint16Array(buf, at(4), V),
  };
}

export function encodeChunk(c: Omit<ChunkData, 'vertexCount' | 'triangleCount'>): Uint8Array {
  const V = c.upper.length, T = c.indices.length / 3;
  const indexSize = indexSizeFor(V);
  const buf = new ArrayBuffer(chunkByteLength(V, T));
  const dv = new DataView(buf);
  dv.setUint32(0, CHUNK_MAGIC, true);
  dv.setUint32(4, CHUNK_VERSION, true);
  dv.setUint32(8, V, true);
  dv.setUint32(12, T, true);
  dv.setFloat64(16, c.originX, true);
  dv.setFloat64(24, c.originY, true);
  for (let i = 0; i < 6; i++) dv.setFloat32(32 + 4 * i, c.box[i]!, true);
  dv.setUint32(56, 0, true);
  dv.setUint32(60, indexSize, true);
  // Typed arrays are little-endian on every platform we run on; the DataView header is explicit.
  const cols = columnViews(buf, 0, V);
  for (const col of VERTEX_COLUMNS) cols[col.name].set(c[col.name]);
  const o = HEADER + pad4(V * VERTEX_BYTES);
  if (indexSize === 2) new Uint16Array(buf, o, 3 * T).set(c.indices);
  else new Uint32Array(buf, o, 3 * T).set(c.indices);
  return new Uint8Array(buf);
}

export class ChunkFormatError extends FormatError {
  constructor(message: string) {
    super(message);
    this.name = 'ChunkFormatError';
  }
}

/**
 * Reads a chunk, checking everything a corrupt or truncated file could break. The arrays are
 * views into (a copy aligned for them of) the given bytes, ready for the GPU.
 */
export function decodeChunk(input: Uint8Array | ArrayBuffer, name = 'chunk'): DecodedChunk {
  const bytes = input instanceof Uint8Array ? input : new Uint8Array(input);
  if (bytes.byteLength < HEADER) throw new ChunkFormatError(`${name}: truncated (${bytes.byteLength} bytes, the header alone is ${HEADER})`);
  // Aligned copy when the bytes do not start on a 4-byte boundary.
  const b = bytes.byteOffset % 4 === 0 ? bytes : bytes.slice();
  const dv = new DataView(b.buffer, b.byteOffset, b.byteLength);
  if (dv.getUint32(0, true) !== CHUNK_MAGIC) throw new ChunkFormatError(`${name}: not a chunk file (bad magic)`);
  const version = dv.getUint32(4, true);
  if (version !== CHUNK_VERSION) throw new ChunkFormatError(`${name}: chunk version ${version}, this reader knows ${CHUNK_VERSION}`);
  const V = dv.getUint32(8, true), T = dv.getUint32(12, true);
  const indexSize = dv.getUint32(60, true);
  if (indexSize !== indexSizeFor(V)) throw new ChunkFormatError(`${name}: index size ${indexSize} does not fit ${V} vertices`);
  const expected = chunkByteLength(V, T);
  if (b.byteLength !== expected) throw new ChunkFormatError(`${name}: ${b.byteLength} bytes, ${V} vertices and ${T} triangles need ${expected}`);
  const box = new Float32Array(6);
  for (let i = 0; i < 6; i++) box[i] = dv.getFloat32(32 + 4 * i, true);
  const base = b.byteOffset;
  const { positions, upper, lower, upperClass, lowerClass } = columnViews(b.buffer, base, V);
  const o = HEADER + pad4(V * VERTEX_BYTES);
  const indices = indexSize === 2 ? new Uint16Array(b.buffer, base + o, 3 * T) : new Uint32Array(b.buffer, base + o, 3 * T);
  for (let i = 0; i < indices.length; i++) {
    if (indices[i]! >= V) throw new ChunkFormatError(`${name}: triangle ${Math.floor(i / 3)} names vertex ${indices[i]} of ${V}`);
  }
  for (let i = 0; i < positions.length; i++) {
    if (!Number.isFinite(positions[i]!)) throw new ChunkFormatError(`${name}: vertex ${Math.floor(i / 3)} has a non-finite coordinate`);
  }
  return {
    vertexCount: V, triangleCount: T,
    originX: dv.getFloat64(16, true), originY: dv.getFloat64(24, true), box, positions, upper, lower, upperClass, lowerClass, indices,
    vertexByteOffset: base + HEADER, vertexByteLength: VERTEX_BYTES * V,
  };
}
