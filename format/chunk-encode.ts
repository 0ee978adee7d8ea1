// The chunk file's encoder (docs/FORMAT.md, "Chunk file", version 5), beside the decoder in
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
import {
  CHUNK_MAGIC, CHUNK_VERSION, chunkSections, encodedVertexBytes, FACE_RECORD_BYTES, gridExponentFor, gridPointKey, gridSteps, indexSizeFor,
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

/** Indices through meshoptimizer's index sequence codec (`meshopt_encodeIndexSequence`): the vertices' points and z values. */
const encodeSequence = (indices: Uint32Array): Uint8Array => MeshoptEncoder.encodeIndexSequence(new Uint8Array(indices.buffer, indices.byteOffset, indices.byteLength), indices.length, 4);

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

/** The faces named by the vertices, in order of first mention (upper before lower), with their classes. */
function faceTable(c: ChunkInput): { ids: number[]; classes: number[]; local: Map<number, number> } {
  const local = new Map<number, number>();
  const ids: number[] = [], classes: number[] = [];
  const add = (face: number, cls: number): void => {
    const i = local.get(face);
    if (i === undefined) {
      // A u32 id and a class of the decoder's u16 column (NO_CLASS, 0xffff, is face 0's).
      if (!(Number.isInteger(face) && face >= 0 && face <= 0xffffffff)) throw new Error(`chunk encoder: face id ${face} is not a u32`);
      if (!(Number.isInteger(cls) && cls >= 0 && cls <= NO_CLASS)) throw new Error(`chunk encoder: face ${face} has class ${cls}, a class index is 0 to ${NO_CLASS}`);
      local.set(face, ids.length);
      ids.push(face);
      classes.push(cls);
    } else if (classes[i] !== cls) {
      throw new Error(`chunk encoder: face ${face} has class ${classes[i]} at one vertex and ${cls} at another`);
    }
  };
  for (let k = 0; k < c.upper.length; k++) {
    add(c.upper[k]!, c.upperClass[k]!);
    add(c.lower[k]!, c.lowerClass[k]!);
  }
  return { ids, classes, local };
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
  const faces = faceTable(c);
  const F = faces.ids.length;
  const indexSize = indexSizeFor(V);
  const e = gridExponentFor(c.box, c.gridExponent);

  // The points (x, y on the grid) and z values (float32), each once, in order of first use by
  // the vertices, as docs/FORMAT.md lays them out; a vertex names them by index.
  const pointIds = new Map<number, number>(), zIds = new Map<number, number>();
  const points: number[] = [], zs: number[] = [];
  const pointOf = new Uint32Array(V), zOf = new Uint32Array(V);
  for (let k = 0; k < V; k++) {
    const qx = gridSteps(c.positions[3 * k]!, e), qy = gridSteps(c.positions[3 * k + 1]!, e);
    if (Number.isNaN(qx) || Number.isNaN(qy)) throw new Error(`chunk encoder: vertex ${k} lies outside the chunk's box`);
    const z = Math.fround(c.positions[3 * k + 2]!);
    if (!Number.isFinite(z)) throw new Error(`chunk encoder: vertex ${k} has z ${c.positions[3 * k + 2]}`);
    const key = gridPointKey(qx, qy);
    let p = pointIds.get(key);
    if (p === undefined) {
      pointIds.set(key, (p = points.length / 2));
      points.push(qx, qy);
    }
    let zi = zIds.get(z);
    if (zi === undefined) {
      zIds.set(z, (zi = zs.length));
      zs.push(z);
    }
    pointOf[k] = p;
    zOf[k] = zi;
  }
  const P = points.length / 2, Z = zs.length;
  const size = tableIndexSizeFor(F);
  const records = size === 2 ? new Uint16Array(2 * V) : new Uint32Array(2 * V);
  for (let k = 0; k < V; k++) {
    records[2 * k] = faces.local.get(c.upper[k]!)!;
    records[2 * k + 1] = faces.local.get(c.lower[k]!)!;
  }
  const tri = indexSize === 2 ? Uint16Array.from(c.indices) : Uint32Array.from(c.indices);
  const faceStream = encodeFaceStream(faces.ids, faces.classes);
  const pointStream = encodeRecords(Int32Array.from(points).buffer, P, POINT_BYTES);
  const zStream = encodeRecords(Float32Array.from(zs).buffer, Z, Z_BYTES);
  // Mostly the next new point or z, else one named shortly before: the index sequence codec
  // codes such a run a byte an index (bgt_otterlo_1800m, gzip: the point indices 310 -> 231 kB,
  // the z indices 120 -> 100 kB, against lanes of the vertex codec).
  const vertexPointStream = encodeSequence(pointOf);
  const vertexZStream = encodeSequence(zOf);
  const vertexStream = encodeRecords(records.buffer, V, encodedVertexBytes(size));
  const indexStream = MeshoptEncoder.encodeIndexBuffer(new Uint8Array(tri.buffer), 3 * T, indexSize);

  const sec = chunkSections({
    faceTable: 0, faces: faceStream.byteLength, points: pointStream.byteLength, zs: zStream.byteLength, vertexPoints: vertexPointStream.byteLength, vertexZs: vertexZStream.byteLength,
    vertices: vertexStream.byteLength, indices: indexStream.byteLength,
  });
  const out = new Uint8Array(sec.end);
  const dv = new DataView(out.buffer);
  dv.setUint32(0, CHUNK_MAGIC, true);
  dv.setUint32(4, CHUNK_VERSION, true);
  dv.setUint32(8, V, true);
  dv.setUint32(12, T, true);
  dv.setFloat64(16, c.originX, true);
  dv.setFloat64(24, c.originY, true);
  for (let i = 0; i < 6; i++) dv.setFloat32(32 + 4 * i, c.box[i]!, true);
  dv.setInt32(56, e, true);
  dv.setUint32(60, F, true);
  dv.setUint32(64, P, true);
  dv.setUint32(68, Z, true);
  dv.setUint32(72, faceStream.byteLength, true);
  dv.setUint32(76, pointStream.byteLength, true);
  dv.setUint32(80, zStream.byteLength, true);
  dv.setUint32(84, vertexPointStream.byteLength, true);
  dv.setUint32(88, vertexZStream.byteLength, true);
  dv.setUint32(92, vertexStream.byteLength, true);
  dv.setUint32(96, indexStream.byteLength, true);
  out.set(faceStream, sec.faces);
  out.set(pointStream, sec.points);
  out.set(zStream, sec.zs);
  out.set(vertexPointStream, sec.vertexPoints);
  out.set(vertexZStream, sec.vertexZs);
  out.set(vertexStream, sec.vertices);
  out.set(indexStream, sec.indices);
  return out;
}
