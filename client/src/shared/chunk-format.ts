// The chunk file (docs/FORMAT.md, "Chunk file"): surface triangles with per-vertex positions
// relative to the chunk's origin, the faces above and below, and their classes. Pure: used by
// the build (Node), the CPU slicer and the map's worker.

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

const pad4 = (n: number): number => (n + 3) & ~3;

export function chunkByteLength(vertices: number, triangles: number): number {
  const indexSize = vertices <= 0xffff ? 2 : 4;
  return HEADER + pad4(vertices * (12 + 4 + 4 + 2 + 2)) + pad4(triangles * 3 * indexSize);
}

export function encodeChunk(c: Omit<ChunkData, 'vertexCount' | 'triangleCount'>): Uint8Array {
  const V = c.upper.length, T = c.indices.length / 3;
  const indexSize = V <= 0xffff ? 2 : 4;
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
  let o = HEADER;
  // Typed arrays are little-endian on every platform we run on; the DataView header is explicit.
  new Float32Array(buf, o, 3 * V).set(c.positions);
  o += 12 * V;
  new Uint32Array(buf, o, V).set(c.upper);
  o += 4 * V;
  new Uint32Array(buf, o, V).set(c.lower);
  o += 4 * V;
  new Uint16Array(buf, o, V).set(c.upperClass);
  o += 2 * V;
  new Uint16Array(buf, o, V).set(c.lowerClass);
  o = pad4(o + 2 * V);
  if (indexSize === 2) new Uint16Array(buf, o, 3 * T).set(c.indices);
  else new Uint32Array(buf, o, 3 * T).set(c.indices);
  return new Uint8Array(buf);
}

export class ChunkFormatError extends Error {
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
  if (indexSize !== (V <= 0xffff ? 2 : 4)) throw new ChunkFormatError(`${name}: index size ${indexSize} does not fit ${V} vertices`);
  const expected = chunkByteLength(V, T);
  if (b.byteLength !== expected) throw new ChunkFormatError(`${name}: ${b.byteLength} bytes, ${V} vertices and ${T} triangles need ${expected}`);
  const box = new Float32Array(6);
  for (let i = 0; i < 6; i++) box[i] = dv.getFloat32(32 + 4 * i, true);
  const base = b.byteOffset;
  let o = HEADER;
  const positions = new Float32Array(b.buffer, base + o, 3 * V);
  o += 12 * V;
  const upper = new Uint32Array(b.buffer, base + o, V);
  o += 4 * V;
  const lower = new Uint32Array(b.buffer, base + o, V);
  o += 4 * V;
  const upperClass = new Uint16Array(b.buffer, base + o, V);
  o += 2 * V;
  const lowerClass = new Uint16Array(b.buffer, base + o, V);
  o = pad4(o + 2 * V);
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
    vertexByteOffset: base + HEADER, vertexByteLength: 24 * V,
  };
}
