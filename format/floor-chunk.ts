// The floor chunk file (docs/FORMAT.md, "Floor chunk file", versions 2 and 1): the cube's floor
// (every input face at z = 0, over face 0) over part of the ground as the faces' boundaries
// instead of triangles. Each piece of boundary is stored once, as a run of points on the cube's
// grid. Version 2 names no face per edge: the edges go round cycles (floorCycles, the plane's
// own order of the edges at each point), and each cycle names the face it bounds; version 1
// (still written where a cycle does not bound one face) names the faces on each edge's left and
// right. A face the build's earcut could not cut comes with its triangles. The reader joins each
// face's boundary into rings and cuts them with earcut (face-rings.ts, the build's own code),
// giving what decodeChunk gives for a triangle chunk.
// Pure; the encoder is in floor-chunk-encode.ts so that the map does not load its WebAssembly.
import { MeshoptDecoder } from 'meshoptimizer/decoder';
import { VERTEX_BYTES } from './chunk-layout.js';
import {
  ChunkFormatError, columnViews, decodedByteLength, FACE_RECORD_BYTES, faceTableOf, indexSizeFor, NO_CLASS, pad4, POINT_BYTES, positionGridProblem, tableIndexSizeFor,
  type DecodedChunk,
} from './chunk.js';
import { earcutFace, type FaceEdge } from './face-rings.js';

export const FLOOR_MAGIC = 0x46435353; // "SSCF"
export const FLOOR_VERSION = 2;
/** Header bytes of version 2; version 1's is FLOOR_V1_HEADER_BYTES. */
export const FLOOR_HEADER_BYTES = 84;
export const FLOOR_V1_HEADER_BYTES = 72;
/** Bytes of one triangle record: three point indices and the face's table position (u32 each). */
export const FLOOR_TRIANGLE_BYTES = 16;
/** Bytes of one cycle record (version 2): the face it bounds (table position + 1; 0 none), u32. */
export const FLOOR_CYCLE_BYTES = 4;

/** More than meshoptimizer's vertex codec (version 1) packs into a byte: 1,000 bytes of zeros in about one. */
const MAX_CODEC_RATIO = 2048;

/** An edge record's flag: the edge starts at the last point of the edge before it, which is not stored again. */
export const FLOOR_CONTINUES = 1;

/**
 * Bytes of one edge record, lanes of `size` bytes: the points it stores and its flags (version
 * 2); version 1 has its left and right face between them.
 */
export const floorEdgeBytes = (size: 2 | 4, version: 1 | 2): number => (version === 1 ? 4 : 2) * size;

/** The lane size of the edge records: 2 while the point count (and in version 1 the face table) fits a u16. */
export const floorEdgeLaneSize = (points: number, faces: number, version: 1 | 2): 2 | 4 => tableIndexSizeFor(version === 1 ? Math.max(points, faces) : points);

/** Where the sections after the header start, from the header's counts and stream lengths. */
export interface FloorSections {
  /** Version 1: the face ids and classes, raw. */
  faceIds: number;
  faceClasses: number;
  /** Version 2: the face stream and the cycle stream. */
  faces: number;
  cycles: number;
  edges: number;
  points: number;
  triangles: number;
  end: number;
}

/** Stream lengths in bytes (`faces` and `cycles` only in version 2). */
export interface FloorStreamLengths {
  faces: number;
  cycles: number;
  edges: number;
  points: number;
  triangles: number;
}

export function floorSections(version: 1 | 2, faceCount: number, len: FloorStreamLengths): FloorSections {
  let faceIds = 0, faceClasses = 0, faces = 0, cycles = 0, edges: number;
  if (version === 1) {
    faceIds = FLOOR_V1_HEADER_BYTES;
    faceClasses = faceIds + 4 * faceCount;
    edges = pad4(faceClasses + 2 * faceCount);
  } else {
    faces = FLOOR_HEADER_BYTES;
    cycles = pad4(faces + len.faces);
    edges = pad4(cycles + len.cycles);
  }
  const points = pad4(edges + len.edges);
  const triangles = pad4(points + len.points);
  return { faceIds, faceClasses, faces, cycles, edges, points, triangles, end: pad4(triangles + len.triangles) };
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

/** Each stored point's vertex id (points equal on the grid share one), and each vertex's x, y in grid steps. */
export interface DistinctPoints {
  id: Uint32Array;
  xs: Float64Array;
  ys: Float64Array;
}

/** One vertex id per distinct grid point, and each id's x, y in grid steps. */
export function distinctPoints(points: Int32Array): DistinctPoints {
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
 * The cycles the edges go round: half-edge 2e is edge e from its first point to its last, 2e + 1
 * back, each bounding what lies on its left. From a half-edge's last point the cycle goes on
 * along the half-edge leaving that point first clockwise from the way back, as a face's boundary
 * does: at a point two half-edges leave, the other one; at more, by the exact order of their
 * first steps round the point (integer grid steps, so the cross products are exact; equal
 * directions with the lower half-edge first, a step of no length last). The same on every
 * machine, so the writer's cycles are the reader's. Cycles are numbered in the order of their
 * lowest half-edge.
 */
export function floorCycles(c: Pick<FloorContent, 'edgeStart' | 'edgeCount'>, pts: DistinctPoints): { cycleOf: Uint32Array; count: number } {
  const { id, xs, ys } = pts;
  const E = c.edgeStart.length, H = 2 * E, V = xs.length;
  const org = new Uint32Array(H), dx = new Float64Array(H), dy = new Float64Array(H);
  for (let e = 0; e < E; e++) {
    const s = c.edgeStart[e]!, n = c.edgeCount[e]!;
    const a = id[s]!, a1 = id[s + 1]!, b = id[s + n - 1]!, b1 = id[s + n - 2]!;
    org[2 * e] = a;
    dx[2 * e] = xs[a1]! - xs[a]!;
    dy[2 * e] = ys[a1]! - ys[a]!;
    org[2 * e + 1] = b;
    dx[2 * e + 1] = xs[b1]! - xs[b]!;
    dy[2 * e + 1] = ys[b1]! - ys[b]!;
  }
  // The half-edges leaving each point, counterclockwise from the +x axis where there are more than two.
  const first = new Uint32Array(V + 1);
  for (let h = 0; h < H; h++) first[org[h]! + 1]!++;
  for (let v = 0; v < V; v++) first[v + 1]! += first[v]!;
  const around = new Uint32Array(H), fill = first.slice(0, V);
  for (let h = 0; h < H; h++) around[fill[org[h]!]!++] = h;
  // A first step of no length (two equal points) comes after every direction, so that the order is total.
  const half = (h: number): number => (dy[h]! > 0 || (dy[h]! === 0 && dx[h]! > 0) ? 0 : dy[h]! === 0 && dx[h]! === 0 ? 2 : 1);
  const ccw = (g: number, h: number): number => half(g) - half(h) || dy[g]! * dx[h]! - dx[g]! * dy[h]! || g - h;
  const place = new Uint32Array(H);
  for (let v = 0; v < V; v++) {
    const a = first[v]!, b = first[v + 1]!;
    if (b - a > 2) around.subarray(a, b).sort(ccw);
    for (let i = a; i < b; i++) place[around[i]!] = i - a;
  }
  const cycleOf = new Uint32Array(H).fill(0xffffffff);
  let count = 0;
  for (let h0 = 0; h0 < H; h0++) {
    if (cycleOf[h0] !== 0xffffffff) continue;
    // The step from h to the next half-edge is a permutation: every walk comes back to its start.
    for (let h = h0; cycleOf[h] === 0xffffffff;) {
      cycleOf[h] = count;
      const back = h ^ 1, v = org[back]!, a = first[v]!, deg = first[v + 1]! - a;
      h = around[a + ((place[back]! + deg - 1) % deg)]!;
    }
    count++;
  }
  return { cycleOf, count };
}

/**
 * The face each cycle bounds (table position + 1; 0 none), from the faces on each edge's left
 * and right: null when some cycle has half-edges of different faces (a degenerate meeting of
 * edges), which version 2 cannot say.
 */
export function cycleFaces(c: Pick<FloorContent, 'left' | 'right'>, cycles: { cycleOf: Uint32Array; count: number }): Uint32Array | null {
  const face = new Uint32Array(cycles.count).fill(0xffffffff);
  for (let h = 0; h < cycles.cycleOf.length; h++) {
    const f = h & 1 ? c.right[h >> 1]! : c.left[h >> 1]!, k = cycles.cycleOf[h]!;
    if (face[k] === 0xffffffff) face[k] = f;
    else if (face[k] !== f) return null;
  }
  return face;
}

/**
 * Each face's counterclockwise triangles, as vertex ids over the distinct points (`xs`, `ys`
 * in grid steps): earcut over its rings, or the triangles given for it. `failed` lists the
 * faces (table positions) earcut could not cut and no triangles were given for.
 */
export function floorFaceTriangles(c: FloorContent, pts: DistinctPoints = distinctPoints(c.points)): { xs: Float64Array; ys: Float64Array; byFace: number[][]; failed: number[] } {
  const F = c.faceCount;
  const { id, xs, ys } = pts;
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
  if (bytes.byteLength < FLOOR_V1_HEADER_BYTES) throw fail(`truncated (${bytes.byteLength} bytes, the header alone is ${FLOOR_V1_HEADER_BYTES} or more)`);
  const b = bytes.byteOffset % 4 === 0 ? bytes : bytes.slice();
  const dv = new DataView(b.buffer, b.byteOffset, b.byteLength);
  const u32 = (o: number): number => dv.getUint32(o, true);
  if (u32(0) !== FLOOR_MAGIC) throw fail('not a floor chunk file (bad magic)');
  const version = u32(4);
  if (version !== 1 && version !== 2) throw fail(`floor chunk version ${version}, this reader knows versions 1 and 2 (rebuild the cube with ssc build)`);
  if (version === 2 && bytes.byteLength < FLOOR_HEADER_BYTES) throw fail(`truncated (${bytes.byteLength} bytes, the header alone is ${FLOOR_HEADER_BYTES})`);
  const F = u32(8), E = u32(12), P = u32(52), Tg = u32(56);
  // Version 2: cycle count, then the face, cycle, edge, point and triangle streams' lengths.
  const C = version === 2 ? u32(60) : 0;
  const len: FloorStreamLengths = version === 2
    ? { faces: u32(64), cycles: u32(68), edges: u32(72), points: u32(76), triangles: u32(80) }
    : { faces: 0, cycles: 0, edges: u32(60), points: u32(64), triangles: u32(68) };
  const ground = [0, 1, 2, 3].map((i) => dv.getFloat32(32 + 4 * i, true));
  if (!ground.every(Number.isFinite)) throw fail('its box is not finite');
  const box = Float32Array.of(ground[0]!, ground[1]!, 0, ground[2]!, ground[3]!, 0);
  const e = dv.getInt32(48, true);
  const gridProblem = positionGridProblem(e, box, false);
  if (gridProblem) throw fail(gridProblem);
  // Every edge stores a point at least, every face has an edge, every cycle a half-edge.
  if (E > P || F > 2 * E || F === 0 || C > 2 * E || (version === 2 && C === 0)) throw fail(`counts out of bounds (${F} faces, ${E} edges, ${P} points${version === 2 ? `, ${C} cycles` : ''})`);
  const lengths = version === 2 ? Object.values(len) : [len.edges, len.points, len.triangles];
  const sec = floorSections(version, F, len);
  if (b.byteLength !== sec.end) throw fail(`${b.byteLength} bytes, its header (${F} faces, ${lengths.join(' + ')} bytes of streams) needs ${sec.end}`);
  const size = floorEdgeLaneSize(P, F, version), edgeBytes = floorEdgeBytes(size, version);
  // meshoptimizer's vertex codec packs at most about 1,000 bytes into one (all zeros): a count
  // beyond what its stream could hold is refused before anything is allocated for it.
  const holds = (n: number, stride: number, length: number): boolean => n * stride <= MAX_CODEC_RATIO * length;
  if (!holds(E, edgeBytes, len.edges) || !holds(P, POINT_BYTES, len.points) || !holds(Tg, FLOOR_TRIANGLE_BYTES, len.triangles) || (Tg === 0 && len.triangles > 0)
    || (version === 2 && (!holds(F, FACE_RECORD_BYTES, len.faces) || !holds(C, FLOOR_CYCLE_BYTES, len.cycles)))) {
    throw fail(`counts out of bounds for their streams (${E} edges in ${len.edges} bytes, ${P} points in ${len.points}, ${Tg} triangles in ${len.triangles}${version === 2 ? `, ${F} faces in ${len.faces}, ${C} cycles in ${len.cycles}` : ''})`);
  }
  const rawEdges = new Uint8Array(E * edgeBytes);
  const rawPoints = new Uint8Array(P * POINT_BYTES);
  const rawTriangles = new Uint8Array(Tg * FLOOR_TRIANGLE_BYTES);
  const rawFaces = new Uint32Array(2 * (version === 2 ? F : 0)), rawCycles = new Uint32Array(C);
  await MeshoptDecoder.ready;
  const stream = (at: number, length: number): Uint8Array => b.subarray(at, at + length);
  try {
    if (version === 2) {
      MeshoptDecoder.decodeVertexBuffer(new Uint8Array(rawFaces.buffer), F, FACE_RECORD_BYTES, stream(sec.faces, len.faces));
      MeshoptDecoder.decodeVertexBuffer(new Uint8Array(rawCycles.buffer), C, FLOOR_CYCLE_BYTES, stream(sec.cycles, len.cycles));
    }
    MeshoptDecoder.decodeVertexBuffer(rawEdges, E, edgeBytes, stream(sec.edges, len.edges));
    MeshoptDecoder.decodeVertexBuffer(rawPoints, P, POINT_BYTES, stream(sec.points, len.points));
    if (Tg > 0) MeshoptDecoder.decodeVertexBuffer(rawTriangles, Tg, FLOOR_TRIANGLE_BYTES, stream(sec.triangles, len.triangles));
  } catch (err) {
    throw fail(`its compressed ${version === 2 ? 'faces, cycles, ' : ''}edges, points or triangles do not decode (${(err as Error).message})`);
  }
  const lanes = size === 2 ? new Uint16Array(rawEdges.buffer) : new Uint32Array(rawEdges.buffer);
  const c: FloorContent = {
    points: new Int32Array(rawPoints.buffer), faceCount: F, triangles: new Uint32Array(rawTriangles.buffer),
    edgeStart: new Uint32Array(E), edgeCount: new Uint32Array(E), left: new Uint32Array(E), right: new Uint32Array(E),
  };
  const lanesPerEdge = version === 1 ? 4 : 2;
  let at = 0;
  for (let k = 0; k < E; k++) {
    const stored = lanes[lanesPerEdge * k]!, flags = lanes[lanesPerEdge * k + lanesPerEdge - 1]!;
    const skip = flags === FLOOR_CONTINUES ? 1 : 0;
    if (flags > FLOOR_CONTINUES || (skip && k === 0)) throw fail(`edge ${k} has flags ${flags}`);
    if (stored + skip < 2 || at + stored > P) throw fail(`edge ${k} has ${stored + skip} points (${P - at} left of ${P})`);
    c.edgeStart[k] = at - skip;
    c.edgeCount[k] = stored + skip;
    if (version === 1) {
      c.left[k] = lanes[4 * k + 1]!;
      c.right[k] = lanes[4 * k + 2]!;
    }
    at += stored;
  }
  for (let t = 0; t < c.triangles.length; t += 4) {
    const [p, q, r, f] = c.triangles.subarray(t, t + 4);
    if (p! >= P || q! >= P || r! >= P || f! < 1 || f! > F) throw fail(`triangle ${t / 4} names points ${p}, ${q}, ${r} of ${P} and face ${f} of ${F}`);
  }
  for (let k = 0; k < P; k++) {
    if (Math.abs(c.points[2 * k]!) > 2 ** 24 || Math.abs(c.points[2 * k + 1]!) > 2 ** 24) throw fail(`point ${k} lies outside the grid`);
  }
  const pts = distinctPoints(c.points);
  if (version === 2) {
    // Each edge's faces: those of the cycles its two sides go round.
    const cycles = floorCycles(c, pts);
    if (cycles.count !== C) throw fail(`its edges go round ${cycles.count} cycles, its header gives faces for ${C}`);
    for (let h = 0; h < 2 * E; h++) (h & 1 ? c.right : c.left)[h >> 1] = rawCycles[cycles.cycleOf[h]!]!;
  }
  for (let k = 0; k < E; k++) {
    const l = c.left[k]!, r = c.right[k]!;
    if (l > F || r > F || l === r) throw fail(`edge ${k} lies between faces ${l} and ${r} of a table of ${F}`);
  }
  let faceIds: Uint32Array, faceClasses: Uint16Array;
  if (version === 2) {
    // Every face is an input face: none has face 0's NO_CLASS.
    ({ ids: faceIds, classes: faceClasses } = faceTableOf(rawFaces, NO_CLASS - 1, fail));
  } else {
    faceIds = new Uint32Array(b.buffer, b.byteOffset + sec.faceIds, F);
    faceClasses = new Uint16Array(b.buffer, b.byteOffset + sec.faceClasses, F);
  }
  const { xs, ys, byFace, failed } = floorFaceTriangles(c, pts);
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
