// The floor chunk file (docs/FORMAT.md, "Floor chunk file", version 1): the cube's floor (every
// input face at z = 0, over face 0) over part of the ground as the faces' boundaries instead of
// triangles. Each piece of boundary is stored once, as a run of points on the cube's grid with
// the face on its left and the face on its right; a face the build's earcut could not cut comes
// with its triangles. The reader joins each face's boundary into rings and cuts them with earcut
// (face-rings.ts, the build's own code), giving what decodeChunk gives for a triangle chunk.
// Pure; the encoder is in floor-chunk-encode.ts so that the map does not load its WebAssembly.
import { MeshoptDecoder } from 'meshoptimizer/decoder';
import { VERTEX_BYTES } from './chunk-layout.js';
import {
  ChunkFormatError, columnViews, decodedByteLength, indexSizeFor, NO_CLASS, pad4, POINT_BYTES, positionGridProblem, tableIndexSizeFor,
  type DecodedChunk,
} from './chunk.js';
import { earcutFace, type FaceEdge } from './face-rings.js';

export const FLOOR_MAGIC = 0x46435353; // "SSCF"
export const FLOOR_VERSION = 1;
export const FLOOR_HEADER_BYTES = 72;
/** Bytes of one triangle record: three point indices and the face's table position (u32 each). */
export const FLOOR_TRIANGLE_BYTES = 16;

/** More than meshoptimizer's vertex codec (version 1) packs into a byte: 1,000 bytes of zeros in about one. */
const MAX_CODEC_RATIO = 2048;

/** An edge record's flag: the edge starts at the last point of the edge before it, which is not stored again. */
export const FLOOR_CONTINUES = 1;

/** Bytes of one edge record: the points it stores, its left and right face, its flags, of `size` bytes each. */
export const floorEdgeBytes = (size: 2 | 4): number => 4 * size;

/** The lane size of the edge records: 2 while the point count and the face table fit a u16. */
export const floorEdgeLaneSize = (points: number, faces: number): 2 | 4 => tableIndexSizeFor(Math.max(points, faces));

/** Where the sections after the header start, from the header's counts and stream lengths. */
export interface FloorSections {
  faceIds: number;
  faceClasses: number;
  edges: number;
  points: number;
  triangles: number;
  end: number;
}

export function floorSections(faces: number, edgeBytes: number, pointBytes: number, triangleBytes: number): FloorSections {
  const faceIds = FLOOR_HEADER_BYTES;
  const faceClasses = faceIds + 4 * faces;
  const edges = pad4(faceClasses + 2 * faces);
  const points = pad4(edges + edgeBytes);
  const triangles = pad4(points + pointBytes);
  return { faceIds, faceClasses, edges, points, triangles, end: pad4(triangles + triangleBytes) };
}

/** A floor chunk's content as grid steps and table positions: what the encoder writes and the reader reads. */
export interface FloorContent {
  /** Point x, y in grid steps, edge after edge, then those of given triangles on no edge. */
  points: Int32Array;
  /** Per edge: its first point, its point count, the faces on its left and right (table position + 1; 0 a face not in the table). */
  edgeStart: Uint32Array;
  edgeCount: Uint32Array;
  left: Uint32Array;
  right: Uint32Array;
  faceCount: number;
  /** Triangles given as such: three point indices and the face (table position + 1) each. */
  triangles: Uint32Array;
}

/** One number for a point in grid steps (|x|, |y| at most 2^24, POSITION_BITS): exact, and equal only for equal points. */
export const gridPointKey = (x: number, y: number): number => (x + 2 ** 24) * 2 ** 26 + (y + 2 ** 24);

/** One vertex id per distinct grid point, and each id's x, y in grid steps. */
function distinctPoints(points: Int32Array): { id: Uint32Array; xs: Float64Array; ys: Float64Array } {
  const n = points.length / 2;
  const id = new Uint32Array(n);
  const xs = new Float64Array(n), ys = new Float64Array(n);
  // Open addressing over a power-of-two table at most half full: a point's slot holds its id + 1.
  let size = 2;
  while (size < 2 * n) size *= 2;
  const slots = new Uint32Array(size);
  let m = 0;
  for (let k = 0; k < n; k++) {
    const x = points[2 * k]!, y = points[2 * k + 1]!;
    let h = (Math.imul(x, 0x9e3779b1) ^ Math.imul(y, 0x85ebca77)) & (size - 1);
    for (;;) {
      const s = slots[h]!;
      if (s === 0) {
        slots[h] = ++m;
        xs[m - 1] = x;
        ys[m - 1] = y;
        id[k] = m - 1;
        break;
      }
      if (xs[s - 1] === x && ys[s - 1] === y) {
        id[k] = s - 1;
        break;
      }
      h = (h + 1) & (size - 1);
    }
  }
  return { id, xs: xs.subarray(0, m), ys: ys.subarray(0, m) };
}

/**
 * Each face's counterclockwise triangles, as vertex ids over the distinct points (`xs`, `ys`
 * in grid steps): earcut over its rings, or the triangles given for it. `failed` lists the
 * faces (table positions) earcut could not cut and no triangles were given for.
 */
export function floorFaceTriangles(c: FloorContent): { xs: Float64Array; ys: Float64Array; byFace: number[][]; failed: number[] } {
  const F = c.faceCount;
  const { id, xs, ys } = distinctPoints(c.points);
  const edgesOf: FaceEdge[][] = Array.from({ length: F }, () => []);
  for (let e = 0; e < c.edgeStart.length; e++) {
    const verts = id.subarray(c.edgeStart[e], c.edgeStart[e]! + c.edgeCount[e]!);
    if (c.left[e]! > 0) edgesOf[c.left[e]! - 1]!.push({ verts, forward: true });
    if (c.right[e]! > 0) edgesOf[c.right[e]! - 1]!.push({ verts, forward: false });
  }
  const byFace: number[][] = Array.from({ length: F }, () => []);
  const given = new Uint8Array(F);
  for (let t = 0; t < c.triangles.length; t += 4) {
    const f = c.triangles[t + 3]! - 1;
    given[f] = 1;
    byFace[f]!.push(id[c.triangles[t]!]!, id[c.triangles[t + 1]!]!, id[c.triangles[t + 2]!]!);
  }
  const failed: number[] = [];
  for (let f = 0; f < F; f++) {
    if (!given[f] && !earcutFace(edgesOf[f]!, xs, ys, byFace[f]!)) failed.push(f);
  }
  return { xs, ys, byFace, failed };
}

/**
 * Reads a floor chunk, checking everything a corrupt or truncated file could break, and expands
 * it to the layout decodeChunk gives: the floor's triangles at z = 0, each face over face 0.
 */
export async function decodeFloorChunk(input: Uint8Array | ArrayBuffer, name = 'floor chunk'): Promise<DecodedChunk> {
  const bytes = input instanceof Uint8Array ? input : new Uint8Array(input);
  const fail = (why: string): ChunkFormatError => new ChunkFormatError(`${name}: ${why}`);
  if (bytes.byteLength < FLOOR_HEADER_BYTES) throw fail(`truncated (${bytes.byteLength} bytes, the header alone is ${FLOOR_HEADER_BYTES})`);
  const b = bytes.byteOffset % 4 === 0 ? bytes : bytes.slice();
  const dv = new DataView(b.buffer, b.byteOffset, b.byteLength);
  const u32 = (o: number): number => dv.getUint32(o, true);
  if (u32(0) !== FLOOR_MAGIC) throw fail('not a floor chunk file (bad magic)');
  if (u32(4) !== FLOOR_VERSION) throw fail(`floor chunk version ${u32(4)}, this reader knows only version ${FLOOR_VERSION} (rebuild the cube with ssc build)`);
  const F = u32(8), E = u32(12), P = u32(52), Tg = u32(56);
  const ground = [0, 1, 2, 3].map((i) => dv.getFloat32(32 + 4 * i, true));
  if (!ground.every(Number.isFinite)) throw fail('its box is not finite');
  const box = Float32Array.of(ground[0]!, ground[1]!, 0, ground[2]!, ground[3]!, 0);
  const e = dv.getInt32(48, true);
  const gridProblem = positionGridProblem(e, box, false);
  if (gridProblem) throw fail(gridProblem);
  // Every edge stores a point at least, every face has an edge.
  if (E > P || F > 2 * E || F === 0) throw fail(`counts out of bounds (${F} faces, ${E} edges, ${P} points)`);
  const sec = floorSections(F, u32(60), u32(64), u32(68));
  if (b.byteLength !== sec.end) throw fail(`${b.byteLength} bytes, its header (${F} faces, ${u32(60)} + ${u32(64)} + ${u32(68)} bytes of streams) needs ${sec.end}`);
  const size = floorEdgeLaneSize(P, F);
  // meshoptimizer's vertex codec packs at most about 1,000 bytes into one (all zeros): a count
  // beyond what its stream could hold is refused before anything is allocated for it.
  const holds = (n: number, stride: number, length: number): boolean => n * stride <= MAX_CODEC_RATIO * length;
  if (!holds(E, floorEdgeBytes(size), u32(60)) || !holds(P, POINT_BYTES, u32(64)) || !holds(Tg, FLOOR_TRIANGLE_BYTES, u32(68)) || (Tg === 0 && u32(68) > 0)) {
    throw fail(`counts out of bounds for their streams (${E} edges in ${u32(60)} bytes, ${P} points in ${u32(64)}, ${Tg} triangles in ${u32(68)})`);
  }
  const rawEdges = new Uint8Array(E * floorEdgeBytes(size));
  const rawPoints = new Uint8Array(P * POINT_BYTES);
  const rawTriangles = new Uint8Array(Tg * FLOOR_TRIANGLE_BYTES);
  await MeshoptDecoder.ready;
  const stream = (at: number, length: number): Uint8Array => b.subarray(at, at + length);
  try {
    MeshoptDecoder.decodeVertexBuffer(rawEdges, E, floorEdgeBytes(size), stream(sec.edges, u32(60)));
    MeshoptDecoder.decodeVertexBuffer(rawPoints, P, POINT_BYTES, stream(sec.points, u32(64)));
    if (Tg > 0) MeshoptDecoder.decodeVertexBuffer(rawTriangles, Tg, FLOOR_TRIANGLE_BYTES, stream(sec.triangles, u32(68)));
  } catch (err) {
    throw fail(`its compressed edges, points or triangles do not decode (${(err as Error).message})`);
  }
  const lanes = size === 2 ? new Uint16Array(rawEdges.buffer) : new Uint32Array(rawEdges.buffer);
  const c: FloorContent = {
    points: new Int32Array(rawPoints.buffer), faceCount: F, triangles: new Uint32Array(rawTriangles.buffer),
    edgeStart: new Uint32Array(E), edgeCount: new Uint32Array(E), left: new Uint32Array(E), right: new Uint32Array(E),
  };
  let at = 0;
  for (let k = 0; k < E; k++) {
    const stored = lanes[4 * k]!, l = lanes[4 * k + 1]!, r = lanes[4 * k + 2]!, flags = lanes[4 * k + 3]!;
    const skip = flags === FLOOR_CONTINUES ? 1 : 0;
    if (flags > FLOOR_CONTINUES || (skip && k === 0)) throw fail(`edge ${k} has flags ${flags}`);
    if (stored + skip < 2 || at + stored > P) throw fail(`edge ${k} has ${stored + skip} points (${P - at} left of ${P})`);
    if (l > F || r > F || l === r) throw fail(`edge ${k} lies between faces ${l} and ${r} of a table of ${F}`);
    c.edgeStart[k] = at - skip;
    c.edgeCount[k] = stored + skip;
    c.left[k] = l;
    c.right[k] = r;
    at += stored;
  }
  for (let t = 0; t < c.triangles.length; t += 4) {
    const [p, q, r, f] = c.triangles.subarray(t, t + 4);
    if (p! >= P || q! >= P || r! >= P || f! < 1 || f! > F) throw fail(`triangle ${t / 4} names points ${p}, ${q}, ${r} of ${P} and face ${f} of ${F}`);
  }
  for (let k = 0; k < P; k++) {
    if (Math.abs(c.points[2 * k]!) > 2 ** 24 || Math.abs(c.points[2 * k + 1]!) > 2 ** 24) throw fail(`point ${k} lies outside the grid`);
  }
  const faceIds = new Uint32Array(b.buffer, b.byteOffset + sec.faceIds, F);
  const faceClasses = new Uint16Array(b.buffer, b.byteOffset + sec.faceClasses, F);
  const { xs, ys, byFace, failed } = floorFaceTriangles(c);
  if (failed.length > 0) throw fail(`the boundaries of face ${failed.map((f) => faceIds[f]).join(', ')} do not close into rings that triangulate`);

  // Each face's own vertices: a point on two faces' boundary is a vertex of each. `seen[v]` is
  // the last face (+ 1) that took point v, `slot[v]` its vertex there: two passes, one to count.
  const seen = new Uint32Array(xs.length), slot = new Uint32Array(xs.length);
  let V = 0, T = 0;
  for (let f = 0; f < F; f++) {
    const tris = byFace[f]!;
    for (const v of tris) if (seen[v] !== f + 1) { seen[v] = f + 1; V++; }
    T += tris.length / 3;
  }
  const out = new ArrayBuffer(decodedByteLength(V, T));
  const { positions, upper, lower, upperClass, lowerClass } = columnViews(out, V);
  const indexOffset = pad4(V * VERTEX_BYTES);
  const indices = indexSizeFor(V) === 2 ? new Uint16Array(out, indexOffset, 3 * T) : new Uint32Array(out, indexOffset, 3 * T);
  const step = 2 ** e;
  seen.fill(0);
  let i = 0, k = 0;
  for (let f = 0; f < F; f++) {
    const tris = byFace[f]!;
    for (const v of tris) {
      if (seen[v] !== f + 1) {
        seen[v] = f + 1;
        slot[v] = k;
        positions[3 * k] = xs[v]! * step;
        positions[3 * k + 1] = ys[v]! * step;
        upper[k] = faceIds[f]!;
        upperClass[k] = faceClasses[f]!;
        k++;
      }
      indices[i++] = slot[v]!;
    }
  }
  // z = 0, face 0 below: as the buffer starts.
  lowerClass.fill(NO_CLASS);
  return {
    vertexCount: V, triangleCount: T, originX: dv.getFloat64(16, true), originY: dv.getFloat64(24, true), box,
    positions, upper, lower, upperClass, lowerClass, indices, gridExponent: e, vertexByteOffset: 0, vertexByteLength: VERTEX_BYTES * V,
  };
}
