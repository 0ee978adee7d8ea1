// The chunk file's encoder (docs/FORMAT.md, "Chunk file", version 3), beside the decoder in
// chunk.ts: a file of its own so that the map, which only decodes, does not load the
// encoder's WebAssembly. Used by the build (Node). Same input, same bytes.
import { MeshoptEncoder } from 'meshoptimizer/encoder';
import {
  CHUNK_MAGIC, CHUNK_VERSION, chunkSections, encodedVertexBytes, faceIndexSizeFor, gridExponentFor, gridSteps, indexSizeFor,
  POINT_BYTES, POSITION_BITS,
} from './chunk.js';

await MeshoptEncoder.ready;

/**
 * Records of `stride` bytes through meshoptimizer's vertex codec at the settings every chunk
 * file uses (level 2, codec version 1): the surface chunks' points and vertices, the line
 * chunks' records.
 */
export const encodeRecords = (records: ArrayBufferLike, count: number, stride: number): Uint8Array =>
  MeshoptEncoder.encodeVertexBufferLevel(new Uint8Array(records), count, stride, 2, 1);

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
  const faceIndexSize = faceIndexSizeFor(F), indexSize = indexSizeFor(V);
  const e = gridExponentFor(c.box, c.gridExponent), limit = 2 ** POSITION_BITS;

  // One record per vertex and one per point (x, y on the grid, in order of first use), as
  // docs/FORMAT.md lays them out, for the vertex codec.
  const stride = encodedVertexBytes(faceIndexSize);
  const records = new ArrayBuffer(V * stride);
  const rv = new DataView(records);
  const pointIds = new Map<number, number>();
  const points: number[] = [];
  for (let k = 0; k < V; k++) {
    const o = k * stride;
    const qx = gridSteps(c.positions[3 * k]!, e), qy = gridSteps(c.positions[3 * k + 1]!, e);
    if (Number.isNaN(qx) || Number.isNaN(qy)) throw new Error(`chunk encoder: vertex ${k} lies outside the chunk's box`);
    // |q| <= 2^24: one exact key.
    const key = (qx + limit) * (2 * limit + 1) + (qy + limit);
    let p = pointIds.get(key);
    if (p === undefined) {
      pointIds.set(key, (p = points.length / 2));
      points.push(qx, qy);
    }
    rv.setUint32(o, p, true);
    rv.setFloat32(o + 4, c.positions[3 * k + 2]!, true);
    const u = faces.local.get(c.upper[k]!)!, d = faces.local.get(c.lower[k]!)!;
    if (faceIndexSize === 2) {
      rv.setUint16(o + 8, u, true);
      rv.setUint16(o + 10, d, true);
    } else {
      rv.setUint32(o + 8, u, true);
      rv.setUint32(o + 12, d, true);
    }
  }
  const P = points.length / 2;
  const tri = indexSize === 2 ? Uint16Array.from(c.indices) : Uint32Array.from(c.indices);
  const pointStream = encodeRecords(Int32Array.from(points).buffer, P, POINT_BYTES);
  const vertexStream = encodeRecords(records, V, stride);
  const indexStream = MeshoptEncoder.encodeIndexBuffer(new Uint8Array(tri.buffer), 3 * T, indexSize);

  const sec = chunkSections(F, pointStream.byteLength, vertexStream.byteLength, indexStream.byteLength);
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
  dv.setUint32(68, pointStream.byteLength, true);
  dv.setUint32(72, vertexStream.byteLength, true);
  dv.setUint32(76, indexStream.byteLength, true);
  for (let i = 0; i < F; i++) {
    dv.setUint32(sec.faceIds + 4 * i, faces.ids[i]!, true);
    dv.setUint16(sec.faceClasses + 2 * i, faces.classes[i]!, true);
  }
  out.set(pointStream, sec.points);
  out.set(vertexStream, sec.vertices);
  out.set(indexStream, sec.indices);
  return out;
}
