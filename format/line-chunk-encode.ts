// The line chunk file's encoder (docs/FORMAT.md, "Line chunk file", version 4), beside the
// decoder in line-chunk.ts: a file of its own so that the map, which only decodes, does not
// load the encoder's WebAssembly. Used by the build (Node). Same input, same bytes.
import { gridExponentFor, gridSteps } from './chunk.js';
import { encodeRecords } from './chunk-encode.js';
import type { Box3 } from './cube-index.js';
import {
  LINE_CHUNK_MAGIC, LINE_CHUNK_VERSION, LINE_RECORD_BYTES, lineChunkSections, PATH_RECORD_BYTES, VERTEX_RECORD_BYTES,
} from './line-chunk.js';
import { groundBox, type LineRecord } from './line-record.js';

/**
 * The chunk's bytes and its box in ground units (for the index). `gridExponent`: the position
 * grid wanted (the cube's, as the surface chunks'), used unless the box needs a coarser one.
 */
export function encodeLineChunk(lines: readonly LineRecord[], gridExponent?: number): { bytes: Uint8Array; bbox: Box3 } {
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
  const box = Float32Array.of(x0 - ox, y0 - oy, z0, x1 - ox, y1 - oy, z1);
  const e = gridExponentFor(box, gridExponent);

  const lineRecords = new DataView(new ArrayBuffer(L * LINE_RECORD_BYTES));
  const pathRecords = new DataView(new ArrayBuffer(P * PATH_RECORD_BYTES));
  const vertexRecords = new DataView(new ArrayBuffer(V * VERTEX_RECORD_BYTES));
  let path = 0, vertex = 0;
  lines.forEach((l, i) => {
    const o = i * LINE_RECORD_BYTES;
    lineRecords.setUint16(o, l.classIndex, true);
    lineRecords.setUint16(o + 2, l.rule, true);
    lineRecords.setInt32(o + 4, l.feature, true);
    lineRecords.setFloat32(o + 8, l.zStart, true);
    lineRecords.setFloat32(o + 12, l.zEnd, true);
    lineRecords.setUint32(o + 16, l.paths.length, true);
    l.paths.forEach((p, k) => {
      const leave = l.leaveZ[k]!;
      pathRecords.setUint32(PATH_RECORD_BYTES * path++, leave.length, true);
      for (let j = 0; j < leave.length; j++, vertex++) {
        const qx = gridSteps(p[2 * j]! - ox, e), qy = gridSteps(p[2 * j + 1]! - oy, e);
        if (Number.isNaN(qx) || Number.isNaN(qy)) throw new Error(`a line of class ${l.classIndex}, feature #${l.feature}: point ${j} of polyline ${k} lies outside the chunk's box`);
        const v = VERTEX_RECORD_BYTES * vertex;
        vertexRecords.setInt32(v, qx, true);
        vertexRecords.setInt32(v + 4, qy, true);
        vertexRecords.setFloat32(v + 8, leave[j]!, true);
      }
    });
  });
  const lineStream = encodeRecords(lineRecords.buffer, L, LINE_RECORD_BYTES);
  const pathStream = encodeRecords(pathRecords.buffer, P, PATH_RECORD_BYTES);
  const vertexStream = encodeRecords(vertexRecords.buffer, V, VERTEX_RECORD_BYTES);

  const sec = lineChunkSections(lineStream.byteLength, pathStream.byteLength, vertexStream.byteLength);
  const out = new Uint8Array(sec.end);
  const dv = new DataView(out.buffer);
  dv.setUint32(0, LINE_CHUNK_MAGIC, true);
  dv.setUint32(4, LINE_CHUNK_VERSION, true);
  dv.setUint32(8, L, true);
  dv.setUint32(12, P, true);
  dv.setUint32(16, V, true);
  dv.setInt32(20, e, true);
  dv.setFloat64(24, ox, true);
  dv.setFloat64(32, oy, true);
  box.forEach((b, i) => dv.setFloat32(40 + 4 * i, b, true));
  dv.setUint32(64, lineStream.byteLength, true);
  dv.setUint32(68, pathStream.byteLength, true);
  dv.setUint32(72, vertexStream.byteLength, true);
  out.set(lineStream, sec.lines);
  out.set(pathStream, sec.paths);
  out.set(vertexStream, sec.vertices);
  return { bytes: out, bbox: [x0, y0, z0, x1, y1, z1] };
}
