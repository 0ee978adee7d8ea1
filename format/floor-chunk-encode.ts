// The floor chunk file's encoder (docs/FORMAT.md, "Floor chunk file", version 2, or 1 where a
// cycle of edges does not bound one face), beside the
// decoder in floor-chunk.ts: a file of its own so that the map does not load the encoder's
// WebAssembly. Used by the build (Node). Same input, same bytes.
import { gridExponentFor, gridPointKey, gridSteps, NO_CLASS, POINT_BYTES } from './chunk.js';
import { encodeFaceStream, encodeRecords } from './chunk-encode.js';
import {
  cycleFaces, distinctPoints, FLOOR_CONTINUES, FLOOR_CYCLE_BYTES, FLOOR_MAGIC, FLOOR_TRIANGLE_BYTES, floorCycles, floorEdgeBytes,
  floorEdgeLaneSize, floorFaceTriangles, floorSections, type FloorContent,
} from './floor-chunk.js';

/** A piece of boundary: x, y pairs relative to the origin, the faces on its left and right (ids). */
export interface FloorEdgeInput {
  xy: ArrayLike<number>;
  left: number;
  right: number;
}

export interface FloorChunkInput {
  originX: number;
  originY: number;
  /** The faces drawn from this chunk (ids) and their classes. */
  faces: ArrayLike<number>;
  classes: ArrayLike<number>;
  /**
   * The boundaries of those faces, each piece once; a side's face not among `faces` (another
   * chunk's, or 0 for none) is stored as 0.
   */
  edges: FloorEdgeInput[];
  /** The cube's grid (chunk.ts, gridExponentFor). */
  gridExponent?: number;
  /**
   * The triangles of a face earcut cannot cut from its rings, as the x, y of their corners
   * relative to the origin (6 numbers a triangle, counterclockwise); they are written as such.
   * Without it such a face is an error.
   */
  triangles?: (face: number) => ArrayLike<number>;
}

/**
 * The file, the number of triangles a reader cuts from it, and its ground box (x0, y0, x1, y1
 * relative to the origin, as given).
 */
export function encodeFloorChunk(c: FloorChunkInput): { bytes: Uint8Array; triangles: number; ground: [number, number, number, number] } {
  const F = c.faces.length, E = c.edges.length;
  const classOf = new Map<number, number>();
  for (let f = 0; f < F; f++) {
    if (c.faces[f] === 0 || classOf.has(c.faces[f]!)) throw new Error(`floor chunk encoder: face ${c.faces[f]} is 0 or listed twice`);
    classOf.set(c.faces[f]!, c.classes[f]!);
  }
  // The face table in the order the edges first name the faces (version 1 keeps it: the faces an
  // edge names are then mostly the last few, or the next, which the codec stores in few bits).
  const local = new Map<number, number>();
  let table: number[] = [];
  for (const ed of c.edges) {
    for (const f of [ed.left, ed.right]) {
      if (classOf.has(f) && !local.has(f)) {
        table.push(f);
        local.set(f, table.length);
      }
    }
  }
  if (table.length < F) throw new Error(`floor chunk encoder: face ${[...classOf.keys()].find((f) => !local.has(f))} has no edge`);
  let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  for (const ed of c.edges) {
    for (let k = 0; k < ed.xy.length; k += 2) {
      x0 = Math.min(x0, ed.xy[k]!); x1 = Math.max(x1, ed.xy[k]!);
      y0 = Math.min(y0, ed.xy[k + 1]!); y1 = Math.max(y1, ed.xy[k + 1]!);
    }
  }
  const box = Float32Array.of(x0, y0, 0, x1, y1, 0);
  const e = gridExponentFor(box, c.gridExponent);
  // An edge that starts where the one before it ends does not store that point again.
  const q = (v: number): number => gridSteps(v, e);
  const continues = c.edges.map((ed, k) => {
    const prev = c.edges[k - 1];
    return prev !== undefined && q(ed.xy[0]!) === q(prev.xy[prev.xy.length - 2]!) && q(ed.xy[1]!) === q(prev.xy[prev.xy.length - 1]!);
  });
  const P = c.edges.reduce((n, ed, k) => n + ed.xy.length / 2 - (continues[k] ? 1 : 0), 0);
  const content: FloorContent = {
    points: new Int32Array(2 * P), faceCount: F, triangles: new Uint32Array(0),
    edgeStart: new Uint32Array(E), edgeCount: new Uint32Array(E), left: new Uint32Array(E), right: new Uint32Array(E),
  };
  let at = 0;
  c.edges.forEach((ed, k) => {
    const n = ed.xy.length / 2;
    const l = local.get(ed.left) ?? 0, r = local.get(ed.right) ?? 0;
    if (n < 2 || !Number.isInteger(n)) throw new Error(`floor chunk encoder: edge ${k} has ${ed.xy.length} coordinates`);
    if (l === r) throw new Error(`floor chunk encoder: edge ${k} between faces ${ed.left} and ${ed.right} bounds ${l === 0 ? 'none of the chunk\'s faces' : 'one face on both sides'}`);
    const skip = continues[k] ? 1 : 0;
    content.edgeStart[k] = at - skip;
    content.edgeCount[k] = n;
    content.left[k] = l;
    content.right[k] = r;
    for (let j = 2 * skip; j < 2 * n; j++) {
      const v = q(ed.xy[j]!);
      if (Number.isNaN(v)) throw new Error(`floor chunk encoder: a point of edge ${k} lies outside the grid`);
      content.points[2 * at + j - 2 * skip] = v;
    }
    at += n - skip;
  });

  // The face table in the order the cycles first name the faces (version 2): each cycle's face
  // is then mostly the next, which the codec stores in few bits.
  const pts = distinctPoints(content.points);
  const faces = cycleFaces(content, floorCycles(content, pts));
  if (faces) {
    const place = new Uint32Array(F + 1), order: number[] = [];
    for (const f of faces) if (f > 0 && place[f] === 0) place[f] = order.push(table[f - 1]!);
    for (let k = 0; k < E; k++) {
      content.left[k] = place[content.left[k]!]!;
      content.right[k] = place[content.right[k]!]!;
    }
    table = order;
  }

  // The faces the reader's earcut cannot cut (from these very grid points) get their triangles,
  // their corners as points, those on no edge after the edges' points.
  const cut = floorFaceTriangles(content, pts);
  const triangles: number[] = [], loose: number[] = [];
  if (cut.failed.length > 0) {
    const pointOf = new Map<number, number>();
    for (let k = P - 1; k >= 0; k--) pointOf.set(gridPointKey(content.points[2 * k]!, content.points[2 * k + 1]!), k);
    for (const f of cut.failed) {
      if (!c.triangles) throw new Error(`floor chunk encoder: earcut cannot cut face ${table[f]} from its boundary`);
      const xy = c.triangles(table[f]!);
      if (xy.length === 0 || xy.length % 6 !== 0) throw new Error(`floor chunk encoder: face ${table[f]} is given ${xy.length} coordinates for its triangles`);
      for (let t = 0; t < xy.length; t += 6) {
        for (let j = 0; j < 3; j++) {
          const qx = gridSteps(xy[t + 2 * j]!, e), qy = gridSteps(xy[t + 2 * j + 1]!, e);
          if (Number.isNaN(qx) || Number.isNaN(qy)) throw new Error(`floor chunk encoder: a triangle of face ${table[f]} lies outside the grid`);
          const key = gridPointKey(qx, qy);
          let p = pointOf.get(key);
          if (p === undefined) {
            pointOf.set(key, (p = P + loose.length / 2));
            loose.push(qx, qy);
          }
          triangles.push(p);
        }
        triangles.push(f + 1);
      }
    }
  }
  const all = new Int32Array(2 * P + loose.length);
  all.set(content.points);
  all.set(loose, 2 * P);
  content.points = all;
  content.triangles = Uint32Array.from(triangles);
  const failed = new Set(cut.failed);
  let T = triangles.length / 4;
  cut.byFace.forEach((tris, f) => { if (!failed.has(f)) T += tris.length / 3; });
  const bytes = writeFloorChunk({
    originX: c.originX, originY: c.originY, gridExponent: e, ground: [x0, y0, x1, y1],
    faceIds: table, faceClasses: table.map((f) => classOf.get(f)!), content,
  });
  return { bytes, triangles: T, ground: [x0, y0, x1, y1] };
}

/** A floor chunk file's fields as they are written. */
export interface FloorFile {
  originX: number;
  originY: number;
  gridExponent: number;
  /** x0, y0, x1, y1 relative to the origin. */
  ground: [number, number, number, number];
  faceIds: ArrayLike<number>;
  faceClasses: ArrayLike<number>;
  /**
   * Each edge's points follow the previous edge's, or start at its last point (the flag
   * FLOOR_CONTINUES); the points of given triangles on no edge come last.
   */
  content: FloorContent;
}

/**
 * The bytes of a floor chunk file (docs/FORMAT.md), as given: encodeFloorChunk makes what it is
 * given. Version 2 where each cycle of the edges bounds one face (the reader finds the faces from
 * the cycles), else version 1 (each edge names its faces).
 */
export function writeFloorChunk(f: FloorFile): Uint8Array {
  const c = f.content, F = c.faceCount, E = c.edgeStart.length, P = c.points.length / 2, Tg = c.triangles.length / 4;
  const faces = cycleFaces(c, floorCycles(c, distinctPoints(c.points)));
  const version = faces ? 2 : 1;
  const size = floorEdgeLaneSize(P, F, version), lanes = version === 1 ? 4 : 2;
  const records = size === 2 ? new Uint16Array(lanes * E) : new Uint32Array(lanes * E);
  let end = 0;
  for (let k = 0; k < E; k++) {
    const skip = k > 0 && c.edgeStart[k] === end - 1 ? 1 : 0;
    if (c.edgeStart[k] !== end - skip) throw new Error(`floor chunk writer: edge ${k} starts at point ${c.edgeStart[k]}, not after the edge before it (${end})`);
    records[lanes * k] = c.edgeCount[k]! - skip;
    if (version === 1) {
      records[4 * k + 1] = c.left[k]!;
      records[4 * k + 2] = c.right[k]!;
    }
    records[lanes * k + lanes - 1] = skip ? FLOOR_CONTINUES : 0;
    end = c.edgeStart[k]! + c.edgeCount[k]!;
  }
  if (f.faceIds.length !== F || f.faceClasses.length !== F) throw new Error(`floor chunk writer: ${f.faceIds.length} face ids and ${f.faceClasses.length} classes for ${F} faces`);
  for (let i = 0; i < F; i++) {
    if (!(f.faceClasses[i]! >= 0 && f.faceClasses[i]! < NO_CLASS)) throw new Error(`floor chunk writer: face ${f.faceIds[i]} has class ${f.faceClasses[i]}, a class index is below ${NO_CLASS}`);
  }
  const faceStream = faces ? encodeFaceStream(f.faceIds, f.faceClasses) : new Uint8Array(0);
  const cycleStream = faces ? encodeRecords(faces.buffer, faces.length, FLOOR_CYCLE_BYTES) : new Uint8Array(0);
  const edgeStream = encodeRecords(records.buffer, E, floorEdgeBytes(size, version));
  const pointStream = encodeRecords(c.points.buffer, P, POINT_BYTES);
  const triangleStream = Tg > 0 ? encodeRecords(c.triangles.buffer, Tg, FLOOR_TRIANGLE_BYTES) : new Uint8Array(0);
  const sec = floorSections(version, F, {
    faces: faceStream.byteLength, cycles: cycleStream.byteLength, edges: edgeStream.byteLength, points: pointStream.byteLength, triangles: triangleStream.byteLength,
  });
  const out = new Uint8Array(sec.end);
  const dv = new DataView(out.buffer);
  dv.setUint32(0, FLOOR_MAGIC, true);
  dv.setUint32(4, version, true);
  dv.setUint32(8, F, true);
  dv.setUint32(12, E, true);
  dv.setFloat64(16, f.originX, true);
  dv.setFloat64(24, f.originY, true);
  f.ground.forEach((v, i) => dv.setFloat32(32 + 4 * i, v, true));
  dv.setInt32(48, f.gridExponent, true);
  dv.setUint32(52, P, true);
  dv.setUint32(56, Tg, true);
  const lengths = faces
    ? [faces.length, faceStream.byteLength, cycleStream.byteLength, edgeStream.byteLength, pointStream.byteLength, triangleStream.byteLength]
    : [edgeStream.byteLength, pointStream.byteLength, triangleStream.byteLength];
  lengths.forEach((v, i) => dv.setUint32(60 + 4 * i, v, true));
  if (faces) {
    out.set(faceStream, sec.faces);
    out.set(cycleStream, sec.cycles);
  } else {
    for (let i = 0; i < F; i++) {
      dv.setUint32(sec.faceIds + 4 * i, f.faceIds[i]!, true);
      dv.setUint16(sec.faceClasses + 2 * i, f.faceClasses[i]!, true);
    }
  }
  out.set(edgeStream, sec.edges);
  out.set(pointStream, sec.points);
  out.set(triangleStream, sec.triangles);
  return out;
}
