// The chunk file (docs/FORMAT.md, "Chunk file", version 6): surface triangles of one chunk,
// compact. Ground points relative to the chunk's origin on a power-of-two grid, each once (the
// corners of several surfaces share it), and each z (float32) once; a vertex is a point, a z
// and the faces above and below, all as indices into chunk-local tables (the face table gives
// each face's class). The face table, points, z values and the vertices' faces are compressed
// with meshoptimizer's vertex codec, the vertices' point and z indices with its index sequence
// codec and the triangles with its index codec (the glTF EXT_meshopt_compression codecs). A
// level piece comes as the rings round it, which the decoder cuts (chunk-rings.ts). The
// decoder expands a file to the vertex columns the GPU binds as they are (chunk-layout.ts).
// Pure: used by the CPU slicer and the map's worker; the encoder is in chunk-encode.ts so that
// the map does not load its WebAssembly.
import { MeshoptDecoder } from 'meshoptimizer/decoder';
import { VERTEX_BYTES, vertexColumnOffset, type VertexColumn } from './chunk-layout.js';
import { cutRingPieces, type CutPieces } from './chunk-rings.js';
import { FormatError } from './format-error.js';

export const CHUNK_MAGIC = 0x43435353; // "SSCC"
export const CHUNK_VERSION = 6;
/** An older version this reader still reads: every triangle given as such (100-byte header). */
export const CHUNK_VERSION_5 = 5;
/** An older version this reader still reads: one vertex stream of four lanes (88-byte header). */
export const CHUNK_VERSION_4 = 4;
/** An older version this reader still reads: no z table, a vertex holds its z (80-byte header). */
export const CHUNK_VERSION_3 = 3;
/** Version 3's layout with the grid always the box's own. */
export const CHUNK_VERSION_2 = 2;
/** The coarsest position grid a reader accepts, 2^MAX_POSITION_EXPONENT (every grid value stays finite in float32). */
export const MAX_POSITION_EXPONENT = 64;
export const NO_CLASS = 0xffff;
/** Header bytes (docs/FORMAT.md). */
export const CHUNK_HEADER_BYTES = 124;
/**
 * Bits of the position grid: x and y are whole steps of `2^e`, with `e` at least the box's own
 * exponent, the smallest with its largest |x| or |y| below `2^(e + POSITION_BITS)`. Every grid
 * value is then exact in float32 (at most 2^24 steps). A build gives every chunk of a cube the
 * same, coarser grid when the box allows (preprocess/ssc/position-grid.ts).
 */
export const POSITION_BITS = 24;

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
  /** The file's position grid exponent, so that an encoder given this chunk puts it on the same grid (and writes the same file where earcut left out no point of a ring). */
  gridExponent: number;
  /** Byte offset and length of the vertex columns (positions, upper, lower, classes). */
  vertexByteOffset: number;
  vertexByteLength: number;
}

/** `n` rounded up to a multiple of 4; plain arithmetic, so that a length from a damaged header cannot wrap round 32 bits. */
export const pad4 = (n: number): number => Math.ceil(n / 4) * 4;

/** Bytes per index: 2 while every vertex fits a u16. */
export const indexSizeFor = (vertices: number): 2 | 4 => (vertices <= 0xffff ? 2 : 4);

/**
 * Bytes per table index in an encoded vertex: 2 while the tables its lanes name fit a u16 (the
 * face table; in version 4 the point, z and face tables; in versions 2 and 3 the face table,
 * and the point index was a u32).
 */
export const tableIndexSizeFor = (largestTable: number): 2 | 4 => (largestTable <= 0xffff ? 2 : 4);

/** Bytes of one encoded point: i32 x, i32 y in grid steps. */
export const POINT_BYTES = 8;

/** Bytes of one encoded z: f32. */
export const Z_BYTES = 4;

/** Bytes of one record of the face stream: u32 face id, u32 class index (the floor chunk file's face record too). */
export const FACE_RECORD_BYTES = 8;

/** Bytes of one record of the vertex stream: its upper and lower face as face table indices of `size` bytes each. */
export const encodedVertexBytes = (size: 2 | 4): number => 2 * size;

/** Bytes of one decoded index of the index sequence streams (the vertices' points and z values). */
const SEQUENCE_INDEX_BYTES = 4;

/** The grid exponent `e` of a box (x0, y0, _, x1, y1, _): the smallest with every |x|, |y| of it below 2^(e + POSITION_BITS). */
function positionExponent(box: ArrayLike<number>): number {
  const m = Math.max(1, Math.abs(box[0]!), Math.abs(box[1]!), Math.abs(box[3]!), Math.abs(box[4]!));
  let b = Math.ceil(Math.log2(m));
  while (2 ** b <= m) b++;
  while (2 ** (b - 1) > m) b--;
  return b - POSITION_BITS;
}

/** The grid an encoder uses: the `wanted` one (the cube's) unless the box needs a coarser one. */
export function gridExponentFor(box: ArrayLike<number>, wanted?: number): number {
  const e = Math.max(positionExponent(box), wanted ?? -Infinity);
  if (e > MAX_POSITION_EXPONENT) throw new Error(`position step 2^${e} is coarser than a reader accepts (2^${MAX_POSITION_EXPONENT})`);
  return e;
}

/**
 * What is wrong with a file's grid exponent `e` for its box, or null: never finer than the box
 * needs, nor coarser than MAX_POSITION_EXPONENT; exactly the box's in files of the versions
 * before a cube-wide grid (`boxOwn`).
 */
export function positionGridProblem(e: number, box: ArrayLike<number>, boxOwn: boolean): string | null {
  const boxE = positionExponent(box);
  if (boxOwn ? e === boxE : e >= boxE && e <= MAX_POSITION_EXPONENT) return null;
  return `position step 2^${e} does not fit its box (2^${boxE}${boxOwn ? '' : ` to 2^${MAX_POSITION_EXPONENT}`})`;
}

/**
 * x or y (relative to the origin) as whole steps of the grid `2^e`: the nearest, at most half a
 * step off (a division by a power of two is exact, so only the rounding moves it); NaN beyond
 * the grid's 2^POSITION_BITS steps either side, where float32 would no longer hold it exactly.
 */
export function gridSteps(v: number, e: number): number {
  const q = Math.round(v / 2 ** e);
  return Math.abs(q) <= 2 ** POSITION_BITS ? q : NaN;
}

/** One number for a point in grid steps (|x|, |y| at most 2^POSITION_BITS, as gridSteps gives them): exact, and equal only for equal points. */
export const gridPointKey = (x: number, y: number): number => (x + 2 ** POSITION_BITS) * 2 ** (POSITION_BITS + 2) + (y + 2 ** POSITION_BITS);

/**
 * Where the sections after the header start (docs/FORMAT.md), from the header's counts. A
 * stream an older version lacks has no length: it starts and ends where the next one starts.
 */
export interface ChunkSections {
  /** The face table, raw (versions 2 to 4). */
  faceIds: number;
  faceClasses: number;
  /** The face table through the codec (versions 5 and 6). */
  faces: number;
  points: number;
  /** The z stream (none in versions 2 and 3). */
  zs: number;
  /** The vertices' point indices and z indices (versions 5 and 6). */
  vertexPoints: number;
  vertexZs: number;
  /** The vertex stream: the vertices' faces (versions 5 and 6), or all of each vertex (versions 2 to 4). */
  vertices: number;
  indices: number;
  /** The ring pieces: their records, their rings' lengths, the rings' points (version 6). */
  pieces: number;
  ringLengths: number;
  ringPoints: number;
  /** The file's length. */
  end: number;
}

/** The lengths a header gives: of the face table (entries) and of each compressed stream (bytes). */
export interface ChunkStreams {
  /** Entries of the raw face table (versions 2 to 4; 0 in versions 5 and 6). */
  faceTable: number;
  /** Bytes of the face stream (versions 5 and 6). */
  faces: number;
  points: number;
  zs: number;
  vertexPoints: number;
  vertexZs: number;
  vertices: number;
  indices: number;
  /** Bytes of the ring piece streams (version 6). */
  pieces: number;
  ringLengths: number;
  ringPoints: number;
}

export function chunkSections(s: ChunkStreams, headerBytes = CHUNK_HEADER_BYTES): ChunkSections {
  const faceIds = headerBytes;
  const faceClasses = faceIds + 4 * s.faceTable;
  const faces = pad4(faceClasses + 2 * s.faceTable);
  const points = pad4(faces + s.faces);
  const zs = pad4(points + s.points);
  const vertexPoints = pad4(zs + s.zs);
  const vertexZs = pad4(vertexPoints + s.vertexPoints);
  const vertices = pad4(vertexZs + s.vertexZs);
  const indices = pad4(vertices + s.vertices);
  const pieces = pad4(indices + s.indices);
  const ringLengths = pad4(pieces + s.pieces);
  const ringPoints = pad4(ringLengths + s.ringLengths);
  return { faceIds, faceClasses, faces, points, zs, vertexPoints, vertexZs, vertices, indices, pieces, ringLengths, ringPoints, end: pad4(ringPoints + s.ringPoints) };
}

/**
 * The face table from a face stream's decoded records (u32 id, u32 class: the chunk file's and
 * the floor chunk file's), refused with `fail` where a class is above `highestClass`.
 */
export function faceTableOf(records: Uint32Array, highestClass: number, fail: (why: string) => Error): { ids: Uint32Array; classes: Uint16Array } {
  const F = records.length / 2;
  const ids = new Uint32Array(F), classes = new Uint16Array(F);
  for (let f = 0; f < F; f++) {
    const id = records[2 * f]!, cls = records[2 * f + 1]!;
    if (cls > highestClass) throw fail(`face ${id} has class ${cls}`);
    ids[f] = id;
    classes[f] = cls;
  }
  return { ids, classes };
}

/** Bytes of a decoded chunk: the vertex columns, then the indices. */
export function decodedByteLength(vertices: number, triangles: number): number {
  return pad4(vertices * VERTEX_BYTES) + pad4(triangles * 3 * indexSizeFor(vertices));
}

type Columns = Pick<ChunkData, VertexColumn['name']>;

/** The vertex columns of a decoded chunk's buffer of `V` vertices (decodedByteLength). */
export function columnViews(buf: ArrayBufferLike, V: number): Columns {
  const at = (i: number): number => vertexColumnOffset(i, V);
  return {
    positions: new Float32Array(buf, at(0), 3 * V),
    upper: new Uint32Array(buf, at(1), V),
    lower: new Uint32Array(buf, at(2), V),
    upperClass: new Uint16Array(buf, at(3), V),
    lowerClass: new Uint16Array(buf, at(4), V),
  };
}

/** How a version lays out its header and its vertex stream (docs/FORMAT.md, "Chunk file" and its older versions). */
export interface ChunkLayout {
  headerBytes: number;
  /** The stream lengths its header gives, the face table's entries `F` among them when the table is raw. */
  streams(u32: (offset: number) => number, F: number): ChunkStreams;
  /** It has ring pieces (version 6). */
  rings: boolean;
  /** Its z count is in the header (a z table); else each vertex holds its z. */
  zTable: boolean;
  /** The vertices' point and z indices are index sequence streams of their own; else they are in the vertex stream. */
  sequences: boolean;
  /** Its grid is always the box's own (before a cube-wide grid). */
  boxOwnGrid: boolean;
  /** Bytes per table index in the vertex stream, from the counts of faces, points and z values. */
  laneSize(F: number, P: number, Z: number): 2 | 4;
  /** Bytes of a vertex stream record, with lanes of `size` bytes. */
  stride(size: 2 | 4): number;
  /** The lane of a record that holds the upper face (the lower one follows). */
  faceLane(size: 2 | 4): number;
}

const NO_RINGS = { pieces: 0, ringLengths: 0, ringPoints: 0 };

/** Versions 2 and 3 (which differ only in their grid rule). */
const V2_V3: Omit<ChunkLayout, 'boxOwnGrid'> = {
  headerBytes: 80,
  streams: (u32, F) => ({ ...NO_RINGS, faceTable: F, faces: 0, points: u32(68), zs: 0, vertexPoints: 0, vertexZs: 0, vertices: u32(72), indices: u32(76) }),
  rings: false,
  zTable: false,
  sequences: false,
  laneSize: (F) => tableIndexSizeFor(F),
  stride: (size) => 8 + 2 * size,
  faceLane: (size) => 8 / size,
};
/** Version 5: the face table through the codec; a vertex's point and z in sequence streams, its faces in the vertex stream. */
const V5: ChunkLayout = {
  headerBytes: 100,
  streams: (u32) => ({ ...NO_RINGS, faceTable: 0, faces: u32(72), points: u32(76), zs: u32(80), vertexPoints: u32(84), vertexZs: u32(88), vertices: u32(92), indices: u32(96) }),
  rings: false,
  zTable: true,
  sequences: true,
  boxOwnGrid: false,
  laneSize: (F) => tableIndexSizeFor(F),
  stride: encodedVertexBytes,
  faceLane: () => 0,
};
/**
 * Version 6: version 5 and ring pieces after the triangles. Version 4: the raw face table;
 * point, z and faces in the vertex stream, on lanes sized for the largest table. Versions 2 and
 * 3: no z table; a vertex is a u32 point, an f32 z and its faces.
 */
const LAYOUTS: ReadonlyMap<number, ChunkLayout> = new Map([
  [CHUNK_VERSION, {
    ...V5,
    headerBytes: CHUNK_HEADER_BYTES,
    streams: (u32, F) => ({ ...V5.streams(u32, F), pieces: u32(112), ringLengths: u32(116), ringPoints: u32(120) }),
    rings: true,
  }],
  [CHUNK_VERSION_5, V5],
  [CHUNK_VERSION_4, {
    headerBytes: 88,
    streams: (u32, F) => ({ ...NO_RINGS, faceTable: F, faces: 0, points: u32(72), zs: u32(76), vertexPoints: 0, vertexZs: 0, vertices: u32(80), indices: u32(84) }),
    rings: false,
    zTable: true,
    sequences: false,
    boxOwnGrid: false,
    laneSize: (F, P, Z) => tableIndexSizeFor(Math.max(P, Z, F)),
    stride: (size) => 4 * size,
    faceLane: () => 2,
  }],
  [CHUNK_VERSION_3, { ...V2_V3, boxOwnGrid: false }],
  [CHUNK_VERSION_2, { ...V2_V3, boxOwnGrid: true }],
]);

/** The layout of a chunk file version this reader reads, or undefined. */
export const chunkLayout = (version: number): ChunkLayout | undefined => LAYOUTS.get(version);

export class ChunkFormatError extends FormatError {
  constructor(message: string) {
    super(message);
    this.name = 'ChunkFormatError';
  }
}

/**
 * Reads a chunk, checking everything a corrupt or truncated file could break, and expands it to
 * the GPU's layout: the arrays are views into one new buffer (vertex columns from offset 0, then
 * the indices). Asynchronous only because the codec's WebAssembly is compiled on first use.
 */
export async function decodeChunk(input: Uint8Array | ArrayBuffer, name = 'chunk'): Promise<DecodedChunk> {
  const bytes = input instanceof Uint8Array ? input : new Uint8Array(input);
  const fail = (why: string): ChunkFormatError => new ChunkFormatError(`${name}: ${why}`);
  if (bytes.byteLength < 8) throw fail(`truncated (${bytes.byteLength} bytes, the header alone is ${CHUNK_HEADER_BYTES})`);
  // Aligned copy when the bytes do not start on a 4-byte boundary (versions 2 to 4 read the face table in place).
  const b = bytes.byteOffset % 4 === 0 ? bytes : bytes.slice();
  const dv = new DataView(b.buffer, b.byteOffset, b.byteLength);
  if (dv.getUint32(0, true) !== CHUNK_MAGIC) throw fail('not a chunk file (bad magic)');
  const version = dv.getUint32(4, true);
  const layout = chunkLayout(version);
  if (!layout) throw fail(`chunk version ${version}, this reader knows only versions ${CHUNK_VERSION_2} to ${CHUNK_VERSION} (rebuild the cube with ssc build)`);
  const { headerBytes, zTable, sequences, rings } = layout;
  if (b.byteLength < headerBytes) throw fail(`truncated (${b.byteLength} bytes, the header alone is ${headerBytes})`);
  const V = dv.getUint32(8, true), T = dv.getUint32(12, true);
  const box = new Float32Array(6);
  for (let i = 0; i < 6; i++) box[i] = dv.getFloat32(32 + 4 * i, true);
  if (!box.every(Number.isFinite)) throw fail('its box is not finite');
  const e = dv.getInt32(56, true);
  const gridProblem = positionGridProblem(e, box, layout.boxOwnGrid);
  if (gridProblem) throw fail(gridProblem);
  const F = dv.getUint32(60, true), P = dv.getUint32(64, true);
  const u32 = (o: number): number => dv.getUint32(o, true);
  const Z = zTable ? u32(68) : 0;
  // Ring pieces, their rings and the rings' points (version 6).
  const G = rings ? u32(100) : 0, R = rings ? u32(104) : 0, RP = rings ? u32(108) : 0;
  const streams = layout.streams(u32, F);
  // Bounds that hold in every chunk (each point and z used by a vertex or a ring piece, each
  // vertex by a triangle, a piece's rings of 3 points or more, the codecs' byte per triangle and
  // per index): a damaged count is refused before anything is allocated.
  if (T > streams.indices) throw fail(`${T} triangles cannot fit an index stream of ${streams.indices} bytes`);
  if (V > 3 * T || P > V + RP || Z > V + G || F > 2 * (V + G)) {
    throw fail(`counts out of bounds (${T} triangles, ${V} vertices, ${P} points,${zTable ? ` ${Z} z values,` : ''} ${F} faces${rings ? `, ${G} ring pieces, ${RP} ring points` : ''})`);
  }
  if (sequences && (V > streams.vertexPoints || V > streams.vertexZs)) {
    throw fail(`${V} vertices cannot fit point and z index streams of ${streams.vertexPoints} and ${streams.vertexZs} bytes`);
  }
  if (G > R || 3 * R > RP || 4 * G > streams.pieces || R > streams.ringLengths || RP > streams.ringPoints) {
    throw fail(`ring counts out of bounds (${G} pieces, ${R} rings, ${RP} ring points in ${streams.pieces} + ${streams.ringLengths} + ${streams.ringPoints} bytes)`);
  }
  const sec = chunkSections(streams, headerBytes);
  if (b.byteLength !== sec.end) {
    const lengths = [
      ...(sequences ? [streams.faces] : []), streams.points, ...(zTable ? [streams.zs] : []), ...(sequences ? [streams.vertexPoints, streams.vertexZs] : []), streams.vertices, streams.indices,
      ...(rings ? [streams.pieces, streams.ringLengths, streams.ringPoints] : []),
    ].join(' + ');
    throw fail(`${b.byteLength} bytes, its header (${F} faces, ${lengths} bytes of streams) needs ${sec.end}`);
  }
  const localSize = layout.laneSize(F, P, Z);
  await MeshoptDecoder.ready;

  const stride = layout.stride(localSize);
  const rawFaces = new Uint32Array(sequences ? 2 * F : 0);
  const rawPoints = new Uint8Array(P * POINT_BYTES);
  const rawZs = new Uint8Array(Z * Z_BYTES);
  const pointOf = new Uint32Array(sequences ? V : 0), zOf = new Uint32Array(sequences ? V : 0);
  const raw = new Uint8Array(V * stride);
  const tri = new Uint32Array(3 * T);
  const pieceRecords = new Uint32Array(4 * G), ringLengths = new Uint32Array(R), ringPoints = new Uint32Array(RP);
  const stream = (at: number, length: number): Uint8Array => b.subarray(at, at + length);
  const sequence = (to: Uint32Array, at: number, length: number): void => {
    if (to.length > 0) MeshoptDecoder.decodeIndexSequence(new Uint8Array(to.buffer), to.length, SEQUENCE_INDEX_BYTES, stream(at, length));
  };
  try {
    if (sequences && F > 0) MeshoptDecoder.decodeVertexBuffer(new Uint8Array(rawFaces.buffer), F, FACE_RECORD_BYTES, stream(sec.faces, streams.faces));
    if (P > 0) MeshoptDecoder.decodeVertexBuffer(rawPoints, P, POINT_BYTES, stream(sec.points, streams.points));
    if (Z > 0) MeshoptDecoder.decodeVertexBuffer(rawZs, Z, Z_BYTES, stream(sec.zs, streams.zs));
    if (sequences) {
      sequence(pointOf, sec.vertexPoints, streams.vertexPoints);
      sequence(zOf, sec.vertexZs, streams.vertexZs);
    }
    if (V > 0) MeshoptDecoder.decodeVertexBuffer(raw, V, stride, stream(sec.vertices, streams.vertices));
    if (T > 0) MeshoptDecoder.decodeIndexBuffer(new Uint8Array(tri.buffer), 3 * T, 4, stream(sec.indices, streams.indices));
    sequence(pieceRecords, sec.pieces, streams.pieces);
    sequence(ringLengths, sec.ringLengths, streams.ringLengths);
    sequence(ringPoints, sec.ringPoints, streams.ringPoints);
  } catch (err) {
    throw fail(`its compressed ${sequences ? 'faces, ' : ''}points, z values, vertices${rings ? ', triangles or ring pieces' : ' or triangles'} do not decode (${(err as Error).message})`);
  }
  for (let i = 0; i < tri.length; i++) {
    if (tri[i]! >= V) throw fail(`triangle ${Math.floor(i / 3)} names vertex ${tri[i]} of ${V}`);
  }

  let faceIds: Uint32Array, faceClasses: Uint16Array;
  if (sequences) {
    // NO_CLASS is face 0's: nothing below.
    ({ ids: faceIds, classes: faceClasses } = faceTableOf(rawFaces, NO_CLASS, fail));
  } else {
    faceIds = new Uint32Array(b.buffer, b.byteOffset + sec.faceIds, F);
    faceClasses = new Uint16Array(b.buffer, b.byteOffset + sec.faceClasses, F);
  }
  const points = new Int32Array(rawPoints.buffer);
  const zs = new Float32Array(rawZs.buffer);
  const cut = rings ? cutPieces(pieceRecords, ringLengths, ringPoints, points, Z, F, fail) : { vertexPoints: [], vertexPiece: [], triangles: [] };
  const Vt = V + cut.vertexPoints.length, Tt = T + cut.triangles.length / 3;
  const out = new ArrayBuffer(decodedByteLength(Vt, Tt));
  const { positions, upper, lower, upperClass, lowerClass } = columnViews(out, Vt);
  const lanes = localSize === 2 ? new Uint16Array(raw.buffer) : new Uint32Array(raw.buffer);
  const words = new Uint32Array(raw.buffer), floats = new Float32Array(raw.buffer);
  const w = stride / 4, h = stride / localSize, faceLane = layout.faceLane(localSize);
  const step = 2 ** e;
  const put = (k: number, p: number, z: number, u: number, d: number): void => {
    positions[3 * k] = points[2 * p]! * step;
    positions[3 * k + 1] = points[2 * p + 1]! * step;
    positions[3 * k + 2] = z;
    upper[k] = faceIds[u]!;
    lower[k] = faceIds[d]!;
    upperClass[k] = faceClasses[u]!;
    lowerClass[k] = faceClasses[d]!;
  };
  // A vertex's point and z: from the sequence streams (versions 5 and 6), its record's first two
  // lanes (version 4), or its record's u32 and f32 (versions 2 and 3).
  for (let k = 0; k < V; k++) {
    const p = sequences ? pointOf[k]! : zTable ? lanes[k * h]! : words[k * w]!;
    if (p >= P) throw fail(`vertex ${k} names point ${p} of ${P}`);
    let z: number;
    if (zTable) {
      const zi = sequences ? zOf[k]! : lanes[k * h + 1]!;
      if (zi >= Z) throw fail(`vertex ${k} names z value ${zi} of ${Z}`);
      z = zs[zi]!;
    } else {
      z = floats[k * w + 1]!;
    }
    if (!Number.isFinite(z)) throw fail(`vertex ${k} has a non-finite coordinate`);
    const u = lanes[k * h + faceLane]!, d = lanes[k * h + faceLane + 1]!;
    if (u >= F || d >= F) throw fail(`vertex ${k} names face ${Math.max(u, d)} of a table of ${F}`);
    put(k, p, z, u, d);
  }
  // The ring pieces' vertices: a point once per piece.
  for (let k = 0; k < cut.vertexPoints.length; k++) {
    const g = cut.vertexPiece[k]!;
    const z = zs[pieceRecords[4 * g]!]!;
    if (!Number.isFinite(z)) throw fail(`ring piece ${g} has a non-finite z`);
    put(V + k, cut.vertexPoints[k]!, z, pieceRecords[4 * g + 1]!, pieceRecords[4 * g + 2]!);
  }
  const indexOffset = pad4(Vt * VERTEX_BYTES);
  const indices = indexSizeFor(Vt) === 2 ? new Uint16Array(out, indexOffset, 3 * Tt) : new Uint32Array(out, indexOffset, 3 * Tt);
  indices.set(tri);
  for (let i = 0; i < cut.triangles.length; i++) indices[3 * T + i] = V + cut.triangles[i]!;
  return {
    vertexCount: Vt, triangleCount: Tt,
    originX: dv.getFloat64(16, true), originY: dv.getFloat64(24, true), box, positions, upper, lower, upperClass, lowerClass, indices, gridExponent: e,
    vertexByteOffset: 0, vertexByteLength: VERTEX_BYTES * Vt,
  };
}

/** The pieces' rings cut into triangles (chunk-rings.ts), each piece's z and faces checked against their tables. */
function cutPieces(records: Uint32Array, lengths: Uint32Array, ringPoints: Uint32Array, points: Int32Array, Z: number, F: number, fail: (why: string) => Error): CutPieces {
  const G = records.length / 4;
  const ringCounts = new Uint32Array(G);
  for (let g = 0; g < G; g++) {
    const zi = records[4 * g]!, u = records[4 * g + 1]!, d = records[4 * g + 2]!;
    if (zi >= Z || u >= F || d >= F) throw fail(`ring piece ${g} names z value ${zi} of ${Z} or faces ${u} and ${d} of ${F}`);
    ringCounts[g] = records[4 * g + 3]!;
  }
  const P = points.length / 2;
  const xs = new Int32Array(P), ys = new Int32Array(P);
  for (let p = 0; p < P; p++) {
    xs[p] = points[2 * p]!;
    ys[p] = points[2 * p + 1]!;
  }
  return cutRingPieces(ringCounts, lengths, ringPoints, xs, ys, fail);
}
