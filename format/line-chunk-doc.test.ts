// docs/FORMAT.md's line chunk tables are the file: a reader made from the tables alone (offsets,
// types, record sizes) reads an encoded file to its last byte, and every field it finds equals
// what format/line-chunk.ts decodes. A field added, dropped or moved in either fails here.
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { test } from 'node:test';
import { MeshoptDecoder } from 'meshoptimizer/decoder';
import { repoRoot } from '../testing/paths.js';
import { roadAndBrook } from '../testing/road-and-brook.js';
import { decodeLineChunk, LINE_CHUNK_HEADER_BYTES, LINE_RECORD_BYTES, PATH_RECORD_BYTES, VERTEX_RECORD_BYTES } from './line-chunk.js';
import { encodeLineChunk } from './line-chunk-encode.js';

interface Row {
  offset: string;
  type: string;
  field: string;
}

/** The tables of the section "Line chunk file" of docs/FORMAT.md: header, line, polyline and vertex record. */
function docTables(): Row[][] {
  const md = readFileSync(path.join(repoRoot, 'docs/FORMAT.md'), 'utf8');
  const start = md.indexOf('### Line chunk file');
  const text = md.slice(start, md.indexOf('\n### ', start + 1));
  const cells = (l: string): string[] => l.slice(1, -1).split(' | ').map((c) => c.trim());
  const tables: Row[][] = [];
  let last = false;
  for (const l of text.split('\n')) {
    const row = l.startsWith('|');
    if (row && !last) tables.push([]);
    last = row;
    if (!row) continue;
    const [offset, type, ...field] = cells(l);
    if (offset === 'offset' || offset!.startsWith('---')) continue;
    tables.at(-1)!.push({ offset: offset!, type: type!, field: field.join(' | ') });
  }
  return tables;
}

const SIZE: Record<string, number> = { u16: 2, u32: 4, i32: 4, f32: 4, f64: 8, 'f32 x 6': 24 };
const READ: Record<string, (v: DataView, o: number) => number> = {
  u16: (v, o) => v.getUint16(o, true),
  u32: (v, o) => v.getUint32(o, true),
  i32: (v, o) => v.getInt32(o, true),
  f32: (v, o) => v.getFloat32(o, true),
  f64: (v, o) => v.getFloat64(o, true),
};
const read = (v: DataView, o: number, type: string): number => READ[type]!(v, o);

/** Fixed-size rows: each at the offset the sizes before it give; returns the bytes they take. */
function checkOffsets(rows: Row[]): number {
  let o = 0;
  for (const r of rows) {
    assert.equal(Number(r.offset), o, `${r.field}: offset`);
    assert.ok(SIZE[r.type], `${r.field}: type ${r.type}`);
    o += SIZE[r.type]!;
  }
  return o;
}

test("docs/FORMAT.md's line chunk tables lay out the header and records the code uses", () => {
  const [header, line, polyline, vertex] = docTables() as [Row[], Row[], Row[], Row[]];
  const fixed = header.filter((r) => r.type in SIZE);
  assert.equal(checkOffsets(fixed), LINE_CHUNK_HEADER_BYTES);
  assert.equal(header[fixed.length]!.offset, String(LINE_CHUNK_HEADER_BYTES), 'the first stream right after the header');
  assert.deepEqual(header.slice(fixed.length).map((r) => r.type), ['`Ll` bytes', '`Lp` bytes', '`Lv` bytes']);
  assert.deepEqual([line, polyline, vertex].map(checkOffsets), [LINE_RECORD_BYTES, PATH_RECORD_BYTES, VERTEX_RECORD_BYTES]);
});

test("a reader made from docs/FORMAT.md's tables reads what decodeLineChunk reads", async () => {
  await MeshoptDecoder.ready;
  const [header, ...recordTables] = docTables() as [Row[], Row[], Row[], Row[]];
  const bytes = encodeLineChunk(roadAndBrook()).bytes;
  const dv = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const h = new Map(header.filter((r) => r.type in SIZE && r.type !== 'f32 x 6').map((r) => [r.field.split(' (')[0]!, read(dv, Number(r.offset), r.type)]));
  const count = (name: string): number => h.get(name)!;
  const streams = [['line count `L`', 'line stream length `Ll` in bytes'], ['polyline count `P`', 'polyline stream length `Lp` in bytes'], ['vertex count `V`', 'vertex stream length `Lv` in bytes']] as const;
  let at = LINE_CHUNK_HEADER_BYTES;
  const fields = streams.map(([n, len], s) => {
    const rows = recordTables[s]!, stride = rows.reduce((b, r) => b + SIZE[r.type]!, 0);
    const out = new Uint8Array(count(n) * stride);
    MeshoptDecoder.decodeVertexBuffer(out, count(n), stride, bytes.subarray(at, at + count(len)));
    at += count(len);
    while (at % 4) assert.equal(bytes[at++], 0, 'zero bytes to a multiple of 4');
    const v = new DataView(out.buffer);
    return rows.map((r) => Array.from({ length: count(n) }, (_, i) => read(v, i * stride + Number(r.offset), r.type)));
  });
  assert.equal(at, bytes.byteLength, 'the file ends with the vertex stream');

  const c = await decodeLineChunk(bytes);
  assert.equal(h.get('magic `0x4C435353`'), 0x4c435353);
  assert.equal(h.get('version 4'), 4);
  assert.deepEqual([count('line count `L`'), count('polyline count `P`'), count('vertex count `V`')], [c.lineCount, c.pathCount, c.vertexCount]);
  assert.deepEqual([h.get('origin x'), h.get('origin y')], [c.originX, c.originY]);
  const [lines, polylines, vertices] = fields as [number[][], number[][], number[][]];
  const diffs = (a: Uint32Array): number[] => Array.from({ length: a.length - 1 }, (_, i) => a[i + 1]! - a[i]!);
  assert.deepEqual(lines, [[...c.lineClass], [...c.lineRule], [...c.lineFeature], [...c.zStart], [...c.zEnd], diffs(c.linePaths)]);
  assert.deepEqual(polylines, [diffs(c.pathVertices)]);
  const step = 2 ** count('position step exponent `e`');
  assert.deepEqual(vertices, [
    Array.from({ length: c.vertexCount }, (_, v) => c.positions[2 * v]! / step),
    Array.from({ length: c.vertexCount }, (_, v) => c.positions[2 * v + 1]! / step),
    [...c.leaveZ],
  ]);
});
