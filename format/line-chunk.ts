// The line chunk file (docs/FORMAT.md, "Line chunk file", version 4): lines of linear classes
// with their z range in the cube (line-record.ts), compact. Ground positions are whole steps of
// the surface chunks' power-of-two grid (format/chunk.ts, `gridExponentFor`: the cube's grid) relative to the
// chunk's origin, each with its leave z; lines, polylines and vertices are records compressed
// with meshoptimizer's vertex codec. The decoder expands a file to columns (`LineChunkData`).
// Pure: used by the CPU slicer and the map's worker; the encoder is in line-chunk-encode.ts so
// that the map does not load its WebAssembly.
import { MeshoptDecoder } from 'meshoptimizer/decoder';
import { pad4, POSITION_BITS, positionGridProblem } from './chunk.js';
import { FormatError } from './format-error.js';
import type { LineRecord } from './line-record.js';

export const LINE_CHUNK_MAGIC = 0x4c435353; // "SSCL"
export const LINE_CHUNK_VERSION = 4;
/** The older version this reader still reads: the same layout, with the grid always the box's own. */
export const LINE_CHUNK_VERSION_3 = 3;
/** Header bytes (docs/FORMAT.md). */
export const LINE_CHUNK_HEADER_BYTES = 76;
/** Bytes of one line record: u16 class, u16 rule, i32 feature, f32 zStart, f32 zEnd, u32 polyline count. */
export const LINE_RECORD_BYTES = 20;
/** Bytes of one polyline record: u32 vertex count. */
export const PATH_RECORD_BYTES = 4;
/** Bytes of one vertex record: i32 x, i32 y in grid steps, f32 leave z. */
export const VERTEX_RECORD_BYTES = 12;

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
  /** x, y per vertex, relative to the origin: whole steps of the grid, exact in float32. */
  positions: Float32Array;
  leaveZ: Float32Array;
  /** The grid's exponent: positions are whole steps of 2^gridExponent. */
  gridExponent: number;
}

/** Where the streams after the header start (docs/FORMAT.md), from the header's stream lengths. */
export function lineChunkSections(lineStream: number, pathStream: number, vertexStream: number): { lines: number; paths: number; vertices: number; end: number } {
  const lines = LINE_CHUNK_HEADER_BYTES;
  const paths = pad4(lines + lineStream);
  const vertices = pad4(paths + pathStream);
  return { lines, paths, vertices, end: pad4(vertices + vertexStream) };
}

/**
 * The most records of `stride` bytes a vertex-codec stream of `bytes` can hold: the codec
 * writes at least stride / 4 bytes per block of at most 256 records. A bound on the header's
 * counts before anything is allocated.
 */
export const vertexStreamCapacity = (bytes: number, stride: number): number => Math.floor((1024 * bytes) / stride);

/**
 * Reads a line chunk, checking everything a corrupt or truncated file could break, and expands
 * it to columns. Asynchronous only because the codec's WebAssembly is compiled on first use.
 */
export async function decodeLineChunk(input: Uint8Array | ArrayBuffer, name = 'line chunk'): Promise<LineChunkData> {
  const b = input instanceof Uint8Array ? input : new Uint8Array(input);
  const bad = (what: string): FormatError => new FormatError(what, name);
  if (b.byteLength < 8) throw bad(`truncated (${b.byteLength} bytes, the header alone is ${LINE_CHUNK_HEADER_BYTES})`);
  const dv = new DataView(b.buffer, b.byteOffset, b.byteLength);
  if (dv.getUint32(0, true) !== LINE_CHUNK_MAGIC) throw bad('not a line chunk file (bad magic)');
  const version = dv.getUint32(4, true);
  if (version !== LINE_CHUNK_VERSION && version !== LINE_CHUNK_VERSION_3) throw bad(`line chunk version ${version}, this reader knows only versions ${LINE_CHUNK_VERSION_3} and ${LINE_CHUNK_VERSION} (rebuild the cube with ssc build)`);
  if (b.byteLength < LINE_CHUNK_HEADER_BYTES) throw bad(`truncated (${b.byteLength} bytes, the header alone is ${LINE_CHUNK_HEADER_BYTES})`);
  const L = dv.getUint32(8, true), P = dv.getUint32(12, true), V = dv.getUint32(16, true);
  const e = dv.getInt32(20, true);
  const box = new Float32Array(6);
  for (let i = 0; i < 6; i++) box[i] = dv.getFloat32(40 + 4 * i, true);
  if (!box.every(Number.isFinite)) throw bad('its box is not finite');
  // Version 3 always used the box's own grid.
  const gridProblem = positionGridProblem(e, box, version === LINE_CHUNK_VERSION_3);
  if (gridProblem) throw bad(gridProblem);
  const lineStream = dv.getUint32(64, true), pathStream = dv.getUint32(68, true), vertexStream = dv.getUint32(72, true);
  // Every line has a polyline and every polyline two vertices; the codec's smallest stream
  // bounds each count: a damaged count is refused before anything is allocated.
  if (L < 1 || P < L || V < 2 * P) throw bad(`counts out of bounds (${L} lines, ${P} polylines, ${V} vertices: at least one line, a polyline per line, two vertices per polyline)`);
  const fits = (n: number, what: string, bytes: number, stride: number): void => {
    if (n > vertexStreamCapacity(bytes, stride)) throw bad(`${n} ${what} cannot fit a stream of ${bytes} bytes`);
  };
  fits(L, 'lines', lineStream, LINE_RECORD_BYTES);
  fits(P, 'polylines', pathStream, PATH_RECORD_BYTES);
  fits(V, 'vertices', vertexStream, VERTEX_RECORD_BYTES);
  const sec = lineChunkSections(lineStream, pathStream, vertexStream);
  if (b.byteLength !== sec.end) throw bad(`${b.byteLength} bytes, its header (${lineStream} + ${pathStream} + ${vertexStream} bytes of streams) needs ${sec.end}`);
  await MeshoptDecoder.ready;

  const lineBytes = new Uint8Array(L * LINE_RECORD_BYTES), pathBytes = new Uint8Array(P * PATH_RECORD_BYTES), vertexBytes = new Uint8Array(V * VERTEX_RECORD_BYTES);
  try {
    MeshoptDecoder.decodeVertexBuffer(lineBytes, L, LINE_RECORD_BYTES, b.subarray(sec.lines, sec.lines + lineStream));
    MeshoptDecoder.decodeVertexBuffer(pathBytes, P, PATH_RECORD_BYTES, b.subarray(sec.paths, sec.paths + pathStream));
    MeshoptDecoder.decodeVertexBuffer(vertexBytes, V, VERTEX_RECORD_BYTES, b.subarray(sec.vertices, sec.vertices + vertexStream));
  } catch (err) {
    throw bad(`its compressed lines, polylines or vertices do not decode (${(err as Error).message})`);
  }

  const lv = new DataView(lineBytes.buffer), pv = new DataView(pathBytes.buffer);
  const lineClass = new Uint16Array(L), lineRule = new Uint16Array(L), lineFeature = new Int32Array(L);
  const zStart = new Float32Array(L), zEnd = new Float32Array(L);
  const linePaths = new Uint32Array(L + 1), pathVertices = new Uint32Array(P + 1);
  for (let i = 0, paths = 0; i < L; i++) {
    const o = i * LINE_RECORD_BYTES;
    lineClass[i] = lv.getUint16(o, true);
    lineRule[i] = lv.getUint16(o + 2, true);
    lineFeature[i] = lv.getInt32(o + 4, true);
    zStart[i] = lv.getFloat32(o + 8, true);
    zEnd[i] = lv.getFloat32(o + 12, true);
    if (!(zStart[i]! < zEnd[i]!)) throw bad(`line ${i} has an empty z range [${zStart[i]}, ${zEnd[i]})`);
    const n = lv.getUint32(o + 16, true);
    if (n < 1) throw bad(`line ${i} has no polyline`);
    paths += n;
    if (paths > P) throw bad(`line ${i} ends at polyline ${paths}, beyond the header's ${P}`);
    linePaths[i + 1] = paths;
  }
  if (linePaths[L] !== P) throw bad(`the lines hold ${linePaths[L]} polylines, the header says ${P}`);
  for (let k = 0, vertices = 0; k < P; k++) {
    const n = pv.getUint32(k * PATH_RECORD_BYTES, true);
    if (n < 2) throw bad(`polyline ${k} has ${n} vertices (at least 2)`);
    vertices += n;
    if (vertices > V) throw bad(`polyline ${k} ends at vertex ${vertices}, beyond the header's ${V}`);
    pathVertices[k + 1] = vertices;
  }
  if (pathVertices[P] !== V) throw bad(`the polylines hold ${pathVertices[P]} vertices, the header says ${V}`);
  const positions = new Float32Array(2 * V), leaveZ = new Float32Array(V);
  const step = 2 ** e, limit = 2 ** POSITION_BITS;
  // The vertex records as i32 and f32 words (typed arrays are little-endian wherever the map runs, as chunk.ts assumes).
  const steps = new Int32Array(vertexBytes.buffer), words = new Float32Array(vertexBytes.buffer);
  const w = VERTEX_RECORD_BYTES / 4;
  for (let v = 0; v < V; v++) {
    const qx = steps[w * v]!, qy = steps[w * v + 1]!, z = words[w * v + 2]!;
    // Within the grid, a position is exact in float32.
    if (Math.abs(qx) > limit || Math.abs(qy) > limit) throw bad(`vertex ${v} lies outside the grid of its box (${qx}, ${qy} steps)`);
    if (!Number.isFinite(z)) throw bad(`vertex ${v} has a non-finite leave z`);
    positions[2 * v] = qx * step;
    positions[2 * v + 1] = qy * step;
    leaveZ[v] = z;
  }
  return {
    lineCount: L, pathCount: P, vertexCount: V, originX: dv.getFloat64(24, true), originY: dv.getFloat64(32, true), box,
    lineClass, lineRule, lineFeature, zStart, zEnd, linePaths, pathVertices, positions, leaveZ, gridExponent: e,
  };
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
