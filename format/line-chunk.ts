// The line chunk file (docs/FORMAT.md, "Line chunk file"): lines of linear classes with their
// z range in the cube, polylines relative to the chunk's origin (float32, as surface chunks
// store theirs) and, per vertex, the z at which simplification takes it away. Encoder and
// decoder side by side; pure, so the map's worker can use it as the build does.
//
// Per-vertex leave z rather than one polyline per version: each vertex is stored once, and the
// polyline at z is its vertices whose leave z is above z (`linePathsAtZ`): a test a shader can
// make per vertex, as the CPU does, without a copy of the line per version.
import type { Box3 } from './cube-index.js';
import { FormatError } from './format-error.js';

export const LINE_CHUNK_MAGIC = 0x4c435353; // "SSCL"
export const LINE_CHUNK_VERSION = 2;
const HEADER = 64;

/** One line as the build hands it to the encoder (absolute coordinates). */
export interface LineRecord {
  classIndex: number;
  /** Index of the style's line rule that draws it (format/line-style.ts, `lineRules`). */
  rule: number;
  /** Input feature whose attributes the line carries (-1: none). */
  feature: number;
  /** The line is on the map for zStart <= z < zEnd. */
  zStart: number;
  zEnd: number;
  /** Polylines as flat x, y pairs, at least two points each. */
  paths: Float64Array[];
  /** Per polyline, per vertex: the z from which the vertex is gone (zEnd when it stays). */
  leaveZ: Float64Array[];
}

/** A decoded line chunk: columns, ready for the GPU. */
export interface LineChunkData {
  lineCount: number;
  pathCount: number;
  vertexCount: number;
  originX: number;
  originY: number;
  /** x0, y0, z0, x1, y1, z1 with x, y relative to the origin. */
  box: Float32Array;
  lineClass: Uint16Array;
  /** The line rule of each line (index into the style's `lineRules`). */
  lineRule: Uint16Array;
  lineFeature: Int32Array;
  zStart: Float32Array;
  zEnd: Float32Array;
  /** First polyline of each line; lineCount + 1 entries, the last = pathCount. */
  linePaths: Uint32Array;
  /** First vertex of each polyline; pathCount + 1 entries, the last = vertexCount. */
  pathVertices: Uint32Array;
  /** x, y per vertex, relative to the origin. */
  positions: Float32Array;
  leaveZ: Float32Array;
}


export function lineChunkByteLength(lines: number, paths: number, vertices: number): number {
  return HEADER + 4 * lines + 12 * lines + 4 * (lines + 1) + 4 * (paths + 1) + 12 * vertices;
}

type Columns = Pick<LineChunkData, 'lineClass' | 'lineRule' | 'lineFeature' | 'zStart' | 'zEnd' | 'linePaths' | 'pathVertices' | 'positions' | 'leaveZ'>;

/** The columns, one after the other in this order, as views of `buf` from `base`. */
function columnViews(buf: ArrayBufferLike, base: number, L: number, P: number, V: number): Columns {
  let o = base + HEADER;
  const take = <T>(make: (at: number) => T, bytes: number): T => {
    const at = o;
    o += bytes;
    return make(at);
  };
  return {
    lineClass: take((at) => new Uint16Array(buf, at, L), 2 * L),
    lineRule: take((at) => new Uint16Array(buf, at, L), 2 * L),
    lineFeature: take((at) => new Int32Array(buf, at, L), 4 * L),
    zStart: take((at) => new Float32Array(buf, at, L), 4 * L),
    zEnd: take((at) => new Float32Array(buf, at, L), 4 * L),
    linePaths: take((at) => new Uint32Array(buf, at, L + 1), 4 * (L + 1)),
    pathVertices: take((at) => new Uint32Array(buf, at, P + 1), 4 * (P + 1)),
    positions: take((at) => new Float32Array(buf, at, 2 * V), 8 * V),
    leaveZ: take((at) => new Float32Array(buf, at, V), 4 * V),
  };
}

/** The ground box x0, y0, x1, y1 of polylines given as flat x, y pairs. */
export function groundBox(paths: readonly Float64Array[]): [number, number, number, number] {
  let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  for (const p of paths) {
    for (let i = 0; i < p.length; i += 2) {
      x0 = Math.min(x0, p[i]!);
      x1 = Math.max(x1, p[i]!);
      y0 = Math.min(y0, p[i + 1]!);
      y1 = Math.max(y1, p[i + 1]!);
    }
  }
  return [x0, y0, x1, y1];
}

/** The chunk's bytes and its box in ground units (for the index). */
export function encodeLineChunk(lines: readonly LineRecord[]): { bytes: Uint8Array; bbox: Box3 } {
  if (lines.length === 0) throw new Error('a line chunk needs at least one line');
  let x0 = Infinity, y0 = Infinity, z0 = Infinity, x1 = -Infinity, y1 = -Infinity, z1 = -Infinity;
  let P = 0, V = 0;
  for (const l of lines) {
    z0 = Math.min(z0, l.zStart);
    z1 = Math.max(z1, l.zEnd);
    if (!Number.isInteger(l.rule) || l.rule < 0 || l.rule > 0xffff) throw new Error(`a line of class ${l.classIndex}, feature #${l.feature}: line rule ${l.rule} is not a u16`);
    P += l.paths.length;
    l.paths.forEach((p, k) => {
      if (p.length < 4 || l.leaveZ[k]!.length !== p.length / 2) throw new Error(`a line of class ${l.classIndex}, feature #${l.feature}: polyline ${k} needs two points or more and a leave z per point`);
      V += p.length / 2;
    });
    const g = groundBox(l.paths);
    x0 = Math.min(x0, g[0]);
    y0 = Math.min(y0, g[1]);
    x1 = Math.max(x1, g[2]);
    y1 = Math.max(y1, g[3]);
  }
  const L = lines.length;
  // A whole-unit origin, as surface chunks have: exact in float64, positions within the chunk's size.
  const ox = Math.floor(x0), oy = Math.floor(y0);
  const buf = new ArrayBuffer(lineChunkByteLength(L, P, V));
  const dv = new DataView(buf);
  dv.setUint32(0, LINE_CHUNK_MAGIC, true);
  dv.setUint32(4, LINE_CHUNK_VERSION, true);
  dv.setUint32(8, L, true);
  dv.setUint32(12, P, true);
  dv.setUint32(16, V, true);
  dv.setUint32(20, 0, true);
  dv.setFloat64(24, ox, true);
  dv.setFloat64(32, oy, true);
  [x0 - ox, y0 - oy, z0, x1 - ox, y1 - oy, z1].forEach((b, i) => dv.setFloat32(40 + 4 * i, b, true));
  // Typed arrays are little-endian on every platform we run on; the DataView header is explicit.
  const c = columnViews(buf, 0, L, P, V);
  let path = 0, vertex = 0;
  lines.forEach((l, i) => {
    c.lineClass[i] = l.classIndex;
    c.lineRule[i] = l.rule;
    c.lineFeature[i] = l.feature;
    c.zStart[i] = l.zStart;
    c.zEnd[i] = l.zEnd;
    c.linePaths[i] = path;
    l.paths.forEach((p, k) => {
      c.pathVertices[path++] = vertex;
      const leave = l.leaveZ[k]!;
      for (let j = 0; j < leave.length; j++, vertex++) {
        c.positions[2 * vertex] = p[2 * j]! - ox;
        c.positions[2 * vertex + 1] = p[2 * j + 1]! - oy;
        c.leaveZ[vertex] = leave[j]!;
      }
    });
  });
  c.linePaths[L] = P;
  c.pathVertices[P] = V;
  return { bytes: new Uint8Array(buf), bbox: [x0, y0, z0, x1, y1, z1] };
}

/** Reads a line chunk, checking everything a corrupt or truncated file could break. */
export function decodeLineChunk(input: Uint8Array | ArrayBuffer, name = 'line chunk'): LineChunkData {
  const bytes = input instanceof Uint8Array ? input : new Uint8Array(input);
  const bad = (what: string): never => {
    throw new FormatError(what, name);
  };
  if (bytes.byteLength < HEADER) bad(`truncated (${bytes.byteLength} bytes, the header alone is ${HEADER})`);
  // Aligned copy when the bytes do not start on a 4-byte boundary.
  const b = bytes.byteOffset % 4 === 0 ? bytes : bytes.slice();
  const dv = new DataView(b.buffer, b.byteOffset, b.byteLength);
  if (dv.getUint32(0, true) !== LINE_CHUNK_MAGIC) bad('not a line chunk file (bad magic)');
  const version = dv.getUint32(4, true);
  if (version !== LINE_CHUNK_VERSION) bad(`line chunk version ${version}, this reader knows ${LINE_CHUNK_VERSION}`);
  const L = dv.getUint32(8, true), P = dv.getUint32(12, true), V = dv.getUint32(16, true);
  const expected = lineChunkByteLength(L, P, V);
  if (b.byteLength !== expected) bad(`${b.byteLength} bytes, ${L} lines, ${P} polylines and ${V} vertices need ${expected}`);
  const box = new Float32Array(6);
  for (let i = 0; i < 6; i++) box[i] = dv.getFloat32(40 + 4 * i, true);
  const c = columnViews(b.buffer, b.byteOffset, L, P, V);
  /** Offsets of the parts of each item: from 0 to `last`, at least `min` parts per item. */
  const offsets = (a: Uint32Array, last: number, item: string, parts: string, min: number): void => {
    if (a[0] !== 0 || a[a.length - 1] !== last) bad(`the ${item} offsets do not run from 0 to ${last}`);
    for (let i = 0; i + 1 < a.length; i++) if (a[i + 1]! - a[i]! < min) bad(`${item} ${i} has ${a[i + 1]! - a[i]!} ${parts} (at least ${min})`);
  };
  offsets(c.linePaths, P, 'line', 'polylines', 1);
  offsets(c.pathVertices, V, 'polyline', 'vertices', 2);
  for (let i = 0; i < L; i++) {
    if (!(c.zStart[i]! < c.zEnd[i]!)) bad(`line ${i} has an empty z range [${c.zStart[i]}, ${c.zEnd[i]})`);
  }
  for (let i = 0; i < c.positions.length; i++) if (!Number.isFinite(c.positions[i]!)) bad(`vertex ${i >> 1} has a non-finite coordinate`);
  for (let i = 0; i < V; i++) if (!Number.isFinite(c.leaveZ[i]!)) bad(`vertex ${i} has a non-finite leave z`);
  return { lineCount: L, pathCount: P, vertexCount: V, originX: dv.getFloat64(24, true), originY: dv.getFloat64(32, true), box, ...c };
}

/** Line `i` of a decoded chunk with absolute coordinates (float64 of the stored float32). */
export function lineOfChunk(c: LineChunkData, i: number): LineRecord {
  const paths: Float64Array[] = [], leaveZ: Float64Array[] = [];
  for (let k = c.linePaths[i]!; k < c.linePaths[i + 1]!; k++) {
    const v0 = c.pathVertices[k]!, v1 = c.pathVertices[k + 1]!;
    const p = new Float64Array(2 * (v1 - v0));
    for (let v = v0; v < v1; v++) {
      p[2 * (v - v0)] = c.originX + c.positions[2 * v]!;
      p[2 * (v - v0) + 1] = c.originY + c.positions[2 * v + 1]!;
    }
    paths.push(p);
    leaveZ.push(Float64Array.from(c.leaveZ.subarray(v0, v1)));
  }
  return { classIndex: c.lineClass[i]!, rule: c.lineRule[i]!, feature: c.lineFeature[i]!, zStart: c.zStart[i]!, zEnd: c.zEnd[i]!, paths, leaveZ };
}

/** Whether a line is on the map at z. */
export const lineAliveAt = (l: Pick<LineRecord, 'zStart' | 'zEnd'>, z: number): boolean => l.zStart <= z && z < l.zEnd;

/** A line's polylines at z: the vertices not yet gone (none when the line is not alive at z). */
export function linePathsAtZ(l: LineRecord, z: number): Float64Array[] {
  if (!lineAliveAt(l, z)) return [];
  return l.paths.map((p, k) => {
    const leave = l.leaveZ[k]!;
    const out: number[] = [];
    for (let j = 0; j < leave.length; j++) if (leave[j]! > z) out.push(p[2 * j]!, p[2 * j + 1]!);
    return Float64Array.from(out);
  });
}

/** A segment of a line that is drawn for z0 <= z < z1. */
export interface LineSegment {
  ax: number;
  ay: number;
  bx: number;
  by: number;
  z0: number;
  z1: number;
  /** Its polyline in the line, and the indices of a and b among that polyline's vertices. */
  path: number;
  a: number;
  b: number;
}

/**
 * Every segment a line has at some z, with its z range: (a, b) joins vertices a and b of a
 * polyline from the z where the last vertex between them is gone (the line's zStart for
 * neighbours) until a or b goes. At any z these are exactly the segments of `linePathsAtZ`,
 * so a slicing surface whose z varies over the map is drawn by testing each pixel against its
 * segment's range (the GPU's rule too).
 */
export function lineSegments(l: LineRecord): LineSegment[] {
  const out: LineSegment[] = [];
  l.paths.forEach((p, k) => {
    const leave = l.leaveZ[k]!, n = leave.length;
    for (let a = 0; a + 1 < n; a++) {
      const la = Math.min(leave[a]!, l.zEnd);
      let between = l.zStart;
      for (let b = a + 1; b < n && between < la; b++) {
        const z1 = Math.min(la, leave[b]!, l.zEnd);
        if (between < z1) out.push({ ax: p[2 * a]!, ay: p[2 * a + 1]!, bx: p[2 * b]!, by: p[2 * b + 1]!, z0: between, z1, path: k, a, b });
        between = Math.max(between, leave[b]!);
      }
    }
  });
  return out;
}
