// The chunk file's encoder (docs/FORMAT.md, "Chunk file", version 6), beside the decoder in
// chunk.ts: a file of its own so that the map, which only decodes, does not load the
// encoder's WebAssembly. Used by the build (Node). Same input, same bytes.
//
// A vertex carries its faces although a triangle's three corners always share them. Tried on
// bgt_otterlo_1800m: vertices as a point and a z only, each triangle's two faces in a stream of
// their own (the worker splitting the vertices again). The vertex, face and index streams grew
// from 136 to 198 kB gzip in the floor chunks and from 619 to 665 kB in the others: the index
// stream doubled (floor 42 -> 85 kB), as a face's own vertices are what keep its triangles in
// the runs the index codec codes cheaply. Triangles grouped by face: 191 kB in the floor.
import { MeshoptEncoder } from 'meshoptimizer/encoder';
import { findRingPieces } from './chunk-rings.js';
import {
  CHUNK_MAGIC, CHUNK_VERSION, chunkSections, type ChunkStreams, encodedVertexBytes, FACE_RECORD_BYTES, gridExponentFor, gridPointKey, gridSteps, indexSizeFor,
  NO_CLASS, POINT_BYTES, tableIndexSizeFor, Z_BYTES,
} from './chunk.js';

await MeshoptEncoder.ready;

/**
 * Records of `stride` bytes through meshoptimizer's vertex codec at the settings every chunk
 * file uses (level 2, codec version 1): the surface chunks' points and vertices, the line
 * chunks' records.
 */
export const encodeRecords = (records: ArrayBufferLike, count: number, stride: number): Uint8Array =>
  MeshoptEncoder.encodeVertexBufferLevel(new Uint8Array(records), count, stride, 2, 1);

/**
 * A face table (ids and their classes) as the face stream of the chunk file and of the floor
 * chunk file: records of u32 id, u32 class through the vertex codec. Over the chunks of
 * bgt_otterlo_1800m 35.7 kB gzip, where the raw table (u32 ids, then u16 classes) took 51.6 kB;
 * over nlcd_zion's 174 kB where it took 278.
 */
export function encodeFaceStream(ids: ArrayLike<number>, classes: ArrayLike<number>): Uint8Array {
  const records = new Uint32Array(2 * ids.length);
  for (let i = 0; i < ids.length; i++) {
    records[2 * i] = ids[i]!;
    records[2 * i + 1] = classes[i]!;
  }
  return encodeRecords(records.buffer, ids.length, FACE_RECORD_BYTES);
}

/** Indices through meshoptimizer's index sequence codec (`meshopt_encodeIndexSequence`): the vertices' points and z values, the ring pieces. */
export const encodeSequence = (indices: Uint32Array): Uint8Array => MeshoptEncoder.encodeIndexSequence(new Uint8Array(indices.buffer, indices.byteOffset, indices.byteLength), indices.length, 4);

/**
 * An order of a mesh's triangles and vertices that the codecs compress well (meshoptimizer's
 * vertex cache and fetch order, for size): `indices` (vertex ids below `vertexCount`) are
 * reordered and renumbered in place; returns each old vertex's new number. The triangles keep
 * their winding. A chunk's order carries no meaning: the map orders a chunk's triangles by z.
 */
export function orderForCodecs(indices: Uint32Array, vertexCount: number): Uint32Array {
  const [remap, unique] = MeshoptEncoder.reorderMesh(indices, true, true);
  if (unique !== vertexCount) throw new Error(`chunk encoder: ${vertexCount - unique} of ${vertexCount} vertices are in no triangle`);
  return remap;
}

/** What a chunk holds, per vertex as the decoder gives it back (positions may be float64). */
export interface ChunkInput {
  originX: number;
  originY: number;
  /** x0, y0, z0, x1, y1, z1 with x, y relative to the origin: every x, y lies in it. */
  box: Float32Array;
  /** x, y relative to the origin, z: per vertex. x, y go to the grid (gridExponent); z to float32. */
  positions: ArrayLike<number>;
  upper: ArrayLike<number>;
  lower: ArrayLike<number>;
  /** Each face's class: the same wherever the face is named. */
  upperClass: ArrayLike<number>;
  lowerClass: ArrayLike<number>;
  /** Counterclockwise triangles as vertex indices. */
  indices: ArrayLike<number>;
  /**
   * The exponent of the position grid wanted (the cube's, so that a point shared by two chunks
   * decodes to the same value in both); the box's own exponent when that is coarser or when absent.
   */
  gridExponent?: number;
}

/** Each value's place in a table of the values in order of first use. */
class FirstUse<K> {
  readonly values: K[] = [];
  private readonly at = new Map<K, number>();

  add(v: K): number {
    let i = this.at.get(v);
    if (i === undefined) {
      this.at.set(v, (i = this.values.length));
      this.values.push(v);
    }
    return i;
  }

  place(v: K): number | undefined {
    return this.at.get(v);
  }
}

/** The faces named, in order of first mention, with their classes; a face has one class. */
class FaceTable {
  readonly ids = new FirstUse<number>();
  readonly classes: number[] = [];

  add(face: number, cls: number): number {
    const known = this.ids.place(face);
    if (known !== undefined) {
      if (this.classes[known] !== cls) throw new Error(`chunk encoder: face ${face} has class ${this.classes[known]} at one vertex and ${cls} at another`);
      return known;
    }
    // A u32 id and a class of the decoder's u16 column (NO_CLASS, 0xffff, is face 0's).
    if (!(Number.isInteger(face) && face >= 0 && face <= 0xffffffff)) throw new Error(`chunk encoder: face id ${face} is not a u32`);
    if (!(Number.isInteger(cls) && cls >= 0 && cls <= NO_CLASS)) throw new Error(`chunk encoder: face ${face} has class ${cls}, a class index is 0 to ${NO_CLASS}`);
    this.classes.push(cls);
    return this.ids.add(face);
  }

  classOf(face: number): number {
    return this.classes[this.ids.place(face)!]!;
  }
}

/** Every vertex is used by a triangle (a reader relies on it to bound the counts). */
function checkUsed(indices: ArrayLike<number>, V: number): void {
  const used = new Uint8Array(V);
  for (let i = 0; i < indices.length; i++) {
    const v = indices[i]!;
    if (!(v >= 0 && v < V)) throw new Error(`chunk encoder: triangle ${Math.floor(i / 3)} names vertex ${v} of ${V}`);
    used[v] = 1;
  }
  const unused = used.indexOf(0);
  if (unused >= 0) throw new Error(`chunk encoder: vertex ${unused} is in no triangle`);
}

export function encodeChunk(c: ChunkInput): Uint8Array {
  const V = c.upper.length, T = c.indices.length / 3;
  if (!Number.isInteger(T)) throw new Error(`chunk encoder: ${c.indices.length} indices are not whole triangles`);
  checkUsed(c.indices, V);
  const e = gridExponentFor(c.box, c.gridExponent);

  // Each vertex's point (x, y on the grid, by first mention) and z (float32).
  const grid = new FirstUse<number>();
  const xs: number[] = [], ys: number[] = [];
  const gridPoint = new Uint32Array(V), zOf = new Float32Array(V);
  for (let k = 0; k < V; k++) {
    const qx = gridSteps(c.positions[3 * k]!, e), qy = gridSteps(c.positions[3 * k + 1]!, e);
    if (Number.isNaN(qx) || Number.isNaN(qy)) throw new Error(`chunk encoder: vertex ${k} lies outside the chunk's box`);
    const z = Math.fround(c.positions[3 * k + 2]!);
    if (!Number.isFinite(z)) throw new Error(`chunk encoder: vertex ${k} has z ${c.positions[3 * k + 2]}`);
    const p = grid.add(gridPointKey(qx, qy));
    if (p === xs.length) {
      xs.push(qx);
      ys.push(qy);
    }
    gridPoint[k] = p;
    zOf[k] = z;
  }
  const { pieces, ringed } = findRingPieces({ indices: c.indices, pointOf: gridPoint, zOf, upper: c.upper, lower: c.lower, xs, ys });
  // Each face's class, checked here (once) to be one wherever the face is named.
  const named = new FaceTable();
  for (let k = 0; k < V; k++) {
    named.add(c.upper[k]!, c.upperClass[k]!);
    named.add(c.lower[k]!, c.lowerClass[k]!);
  }

  // The tables in order of first use, as docs/FORMAT.md lays them out: by the ring pieces, then
  // by the vertices of the triangles given as such.
  const faces = new FaceTable(), points = new FirstUse<number>(), zs = new FirstUse<number>();
  const pieceRecords: number[] = [], ringLengths: number[] = [], ringPoints: number[] = [];
  for (const piece of pieces) {
    pieceRecords.push(zs.add(piece.z), faces.add(piece.upper, named.classOf(piece.upper)), faces.add(piece.lower, named.classOf(piece.lower)), piece.rings.length);
    for (const r of piece.rings) {
      ringLengths.push(r.length);
      for (const q of r) ringPoints.push(points.add(q));
    }
  }
  // The vertices of the triangles given as such, in the caller's order.
  const vertexOf = new Int32Array(V).fill(-1), kept: number[] = [], tri: number[] = [];
  for (let t = 0; t < T; t++) if (!ringed[t]) for (let j = 0; j < 3; j++) vertexOf[c.indices[3 * t + j]!] = 0;
  for (let v = 0; v < V; v++) if (vertexOf[v] === 0) vertexOf[v] = kept.push(v) - 1;
  for (let t = 0; t < T; t++) if (!ringed[t]) for (let j = 0; j < 3; j++) tri.push(vertexOf[c.indices[3 * t + j]!]!);
  const Vg = kept.length, Tg = tri.length / 3;
  const pointOf = new Uint32Array(Vg), zIndexOf = new Uint32Array(Vg), faceOf = new Uint32Array(2 * Vg);
  kept.forEach((v, k) => {
    pointOf[k] = points.add(gridPoint[v]!);
    zIndexOf[k] = zs.add(zOf[v]!);
    faceOf[2 * k] = faces.add(c.upper[v]!, named.classOf(c.upper[v]!));
    faceOf[2 * k + 1] = faces.add(c.lower[v]!, named.classOf(c.lower[v]!));
  });
  const F = faces.ids.values.length, P = points.values.length, Z = zs.values.length;
  const size = tableIndexSizeFor(F);
  const records = size === 2 ? Uint16Array.from(faceOf) : faceOf;
  const pointRecords = new Int32Array(2 * P);
  points.values.forEach((q, i) => {
    pointRecords[2 * i] = xs[q]!;
    pointRecords[2 * i + 1] = ys[q]!;
  });
  const indexSize = indexSizeFor(Vg);
  const triArray = indexSize === 2 ? Uint16Array.from(tri) : Uint32Array.from(tri);

  const faceStream = encodeFaceStream(faces.ids.values, faces.classes);
  const pointStream = encodeRecords(pointRecords.buffer, P, POINT_BYTES);
  const zStream = encodeRecords(Float32Array.from(zs.values).buffer, Z, Z_BYTES);
  // Mostly the next new point or z, else one named shortly before: the index sequence codec
  // codes such a run a byte an index (bgt_otterlo_1800m, gzip: the point indices 310 -> 231 kB,
  // the z indices 120 -> 100 kB, against lanes of the vertex codec).
  const vertexPointStream = encodeSequence(pointOf);
  const vertexZStream = encodeSequence(zIndexOf);
  const vertexStream = encodeRecords(records.buffer, Vg, encodedVertexBytes(size));
  const indexStream = MeshoptEncoder.encodeIndexBuffer(new Uint8Array(triArray.buffer), 3 * Tg, indexSize);
  const pieceStream = encodeSequence(Uint32Array.from(pieceRecords));
  const ringLengthStream = encodeSequence(Uint32Array.from(ringLengths));
  const ringPointStream = encodeSequence(Uint32Array.from(ringPoints));

  // Each stream with the header field that gives its length and the section it goes to.
  const streams: [number, Uint8Array, Exclude<keyof ChunkStreams, 'faceTable'>][] = [
    [72, faceStream, 'faces'], [76, pointStream, 'points'], [80, zStream, 'zs'], [84, vertexPointStream, 'vertexPoints'], [88, vertexZStream, 'vertexZs'],
    [92, vertexStream, 'vertices'], [96, indexStream, 'indices'], [112, pieceStream, 'pieces'], [116, ringLengthStream, 'ringLengths'], [120, ringPointStream, 'ringPoints'],
  ];
  const lengths: ChunkStreams = { faceTable: 0, faces: 0, points: 0, zs: 0, vertexPoints: 0, vertexZs: 0, vertices: 0, indices: 0, pieces: 0, ringLengths: 0, ringPoints: 0 };
  for (const [, bytes, name] of streams) lengths[name] = bytes.byteLength;
  const sec = chunkSections(lengths);
  const out = new Uint8Array(sec.end);
  const dv = new DataView(out.buffer);
  dv.setUint32(0, CHUNK_MAGIC, true);
  dv.setUint32(4, CHUNK_VERSION, true);
  dv.setFloat64(16, c.originX, true);
  dv.setFloat64(24, c.originY, true);
  for (let i = 0; i < 6; i++) dv.setFloat32(32 + 4 * i, c.box[i]!, true);
  dv.setInt32(56, e, true);
  const counts = [[8, Vg], [12, Tg], [60, F], [64, P], [68, Z], [100, pieces.length], [104, ringLengths.length], [108, ringPoints.length]] as const;
  for (const [at, n] of counts) dv.setUint32(at, n, true);
  for (const [at, bytes, name] of streams) {
    dv.setUint32(at, bytes.byteLength, true);
    out.set(bytes, sec[name]);
  }
  return out;
}
