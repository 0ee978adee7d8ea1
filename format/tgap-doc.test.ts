// docs/FORMAT.md's tGAP table is the file: a reader made from the table alone (names, types,
// counts) reads a real tGAP of bgt_otterlo_400m to its last byte, and every field it finds
// equals what format/tgap.ts decodes. A section added, dropped or moved in either fails here.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { createHash } from 'node:crypto';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { repoRoot } from '../testing/paths.js';
import { tempDir } from '../testing/temp-dir.js';
import { generalizedDataset } from '../testing/generalized-dataset.js';
import type { Tgap } from './tgap-model.js';

interface Row {
  field: string;
  type: string;
  count: string;
  meaning: string;
}

/** The rows of the table under "## tGAP file" in docs/FORMAT.md. */
function docTable(): { rows: Row[]; text: string } {
  const md = readFileSync(path.join(repoRoot, 'docs/FORMAT.md'), 'utf8');
  const start = md.indexOf('## tGAP file');
  const text = md.slice(start, md.indexOf('\n## ', start + 1));
  const lines = text.split('\n').filter((l) => l.startsWith('|'));
  const cells = (l: string): string[] => l.slice(1, -1).split(' | ').map((c) => c.trim());
  assert.deepEqual(cells(lines[0]!), ['field', 'type', 'count', 'meaning']);
  const rows = lines.slice(2).map((l) => {
    const [field, type, count, ...meaning] = cells(l);
    return { field: field!, type: type!, count: count!, meaning: meaning.join(' | ') };
  });
  return { rows, text };
}

const ELEMENT: Record<string, { bytes: number; get: (v: DataView, o: number) => number }> = {
  u8: { bytes: 1, get: (v, o) => v.getUint8(o) },
  u16: { bytes: 2, get: (v, o) => v.getUint16(o, true) },
  u32: { bytes: 4, get: (v, o) => v.getUint32(o, true) },
  i32: { bytes: 4, get: (v, o) => v.getInt32(o, true) },
  f64: { bytes: 8, get: (v, o) => v.getFloat64(o, true) },
};

/** Reads a file with nothing but the table and the doc's definition of a section. */
function readByDoc(rows: Row[], buf: Uint8Array): Map<string, number[]> {
  const view = new DataView(buf.buffer, buf.byteOffset, buf.byteLength);
  const out = new Map<string, number[]>();
  const sizes = new Map<string, number>();
  let lastOffset = -1;
  let o = 0;
  const pad8 = (): void => {
    while (o % 8) assert.equal(buf[o++], 0, 'padding is zero');
  };
  for (const r of rows) {
    let values: number[];
    if (r.type === 'u32') {
      values = [view.getUint32(o, true)];
      o += 4;
    } else if (r.type === '32 bytes') {
      values = [...buf.subarray(o, o + 32)];
      assert.deepEqual(values, [...createHash('sha256').update(buf.subarray(0, o)).digest()], 'the checksum is the SHA-256 of everything before it');
      o += 32;
    } else {
      const m = /^section of (\w+)$/.exec(r.type);
      assert.ok(m && ELEMENT[m[1]!], `${r.field}: unknown type ${r.type}`);
      const el = ELEMENT[m[1]!]!;
      const n = view.getUint32(o, true);
      o += 4;
      pad8();
      values = Array.from({ length: n }, (_, i) => el.get(view, o + i * el.bytes));
      o += n * el.bytes;
      pad8();
    }
    // The count column: "1", "any", "<name>", "<name> + 1", "<k> × <name>", "last offset", "3 × last offset".
    const c = /^(?:(\d+) × )?(.+?)(?: \+ (\d+))?$/.exec(r.count)!;
    const k = Number(c[1] ?? 1), plus = Number(c[3] ?? 0), what = c[2]!;
    if (what === 'any') {
      // any length
    } else if (/^\d+$/.test(what)) {
      assert.equal(values.length, Number(what), r.field);
    } else if (what === 'last offset') {
      assert.equal(values.length, k * lastOffset, `${r.field}: ${r.count}`);
    } else {
      assert.equal((values.length - plus) % k, 0, r.field);
      const size = (values.length - plus) / k;
      if (sizes.has(what)) assert.equal(size, sizes.get(what), `${r.field}: ${r.count} disagrees with an earlier section`);
      else sizes.set(what, size);
    }
    if (r.field.endsWith('offsets')) lastOffset = values[values.length - 1]!;
    out.set(r.field, values);
  }
  assert.equal(o, buf.length, 'the table accounts for every byte of the file');
  return out;
}

/** The same fields from format/tgap.ts's decoder, by the doc's names. */
function fieldsOf(t: Tgap): Map<string, number[]> {
  const F = t.faces, E = t.edges, V = t.events;
  const flat = <T>(items: T[], get: (x: T) => ArrayLike<number> | undefined): number[] => items.flatMap((x) => Array.from(get(x) ?? []));
  const offsets = <T>(items: T[], get: (x: T) => ArrayLike<number> | undefined, per = 1): number[] => {
    const off = [0];
    for (const x of items) off.push(off[off.length - 1]! + (get(x)?.length ?? 0) / per);
    return off;
  };
  return new Map<string, number[]>([
    ['version', [t.meta.version]],
    ['vertices', Array.from(t.xs, (x, i) => [x, t.ys[i]!]).flat()],
    ['face class', F.map((f) => f.classIndex)],
    ['face feature', F.map((f) => f.feature)],
    ['face stepLow', F.map((f) => f.stepLow)],
    ['face stepHigh', F.map((f) => f.stepHigh)],
    ['face mergedInto', F.map((f) => f.mergedInto)],
    ['face endPhase', F.map((f) => f.endPhase)],
    ['face area2', F.map((f) => f.area2)],
    ['edge start', E.map((e) => e.start)],
    ['edge end', E.map((e) => e.end)],
    ['edge left', E.map((e) => e.left)],
    ['edge right', E.map((e) => e.right)],
    ['edge stepLow', E.map((e) => e.stepLow)],
    ['edge stepHigh', E.map((e) => e.stepHigh)],
    ['edge vertex offsets', offsets(E, (e) => e.verts)],
    ['edge vertices', flat(E, (e) => e.verts)],
    ['edge parent offsets', offsets(E, (e) => e.parents)],
    ['edge parents', flat(E, (e) => e.parents)],
    ['edge removed offsets', offsets(E, (e) => e.removed)],
    ['edge removed', flat(E, (e) => e.removed)],
    ['edge removed phases', flat(E, (e) => e.removedPhase)],
    ['event kind', V.map((e) => e.kind)],
    ['event step', V.map((e) => e.step)],
    ['event loser', V.map((e) => e.loser)],
    ['event into', V.map((e) => e.into)],
    ['event triangle offsets', offsets(V, (e) => e.tris, 3)],
    ['event triangles', flat(V, (e) => e.tris)],
    ['event triangle faces', flat(V, (e) => e.triFaces)],
  ]);
}

test("docs/FORMAT.md's tGAP table reads a real tGAP exactly as format/tgap.ts does", async (t) => {
  const { rows, text } = docTable();
  const { tgapFile, tgap } = await generalizedDataset(tempDir(t), 'bgt_otterlo_400m.geojson', 'bgt.json');
  const byDoc = readByDoc(rows, readFileSync(tgapFile));
  const byCode = fieldsOf(tgap);
  // Every documented field is one the decoder knows, and the other way round.
  const documented = rows.map((r) => r.field).filter((f) => !['magic', 'meta', 'checksum'].includes(f));
  assert.deepEqual(documented, [...byCode.keys()]);
  for (const [field, values] of byCode) assert.deepEqual(byDoc.get(field), values, field);
  assert.equal(byDoc.get('magic')![0], Number(/`(0x[0-9a-f]+)`/i.exec(rows[0]!.meaning)![1]));
  assert.equal(byDoc.get('version')![0], Number(rows[1]!.meaning));
  const meta = JSON.parse(new TextDecoder().decode(Uint8Array.from(byDoc.get('meta')!))) as Record<string, unknown>;
  assert.deepEqual(meta, JSON.parse(JSON.stringify(tgap.meta)));

  // The values the meanings promise: event kinds, phases, edge ends and the outside face.
  const meaning = (f: string): string => rows.find((r) => r.field === f)!.meaning;
  const kinds = new Set([...meaning('event kind').matchAll(/(\d+) (merge|split|re-draw)/g)].map((m) => Number(m[1])));
  assert.deepEqual([...new Set(byDoc.get('event kind'))].sort(), [...kinds].sort(), 'the file holds each documented kind of event, and no other');
  const [lo, hi] = /\((\d+)\.\.(\d+)\)/.exec(meaning('edge removed phases'))!.slice(1).map(Number) as [number, number];
  assert.ok(byDoc.get('edge removed phases')!.every((p) => p >= lo && p <= hi));
  const endPhases = new Set([...meaning('face endPhase').matchAll(/(\d+) \(/g)].map((m) => Number(m[1])));
  assert.deepEqual([...new Set(byDoc.get('face endPhase'))].sort(), [...endPhases].sort());
  tgap.edges.forEach((e) => assert.ok(e.verts[0] === e.start && e.verts[e.verts.length - 1] === e.end, 'edge vertices run from start to end'));
  assert.equal(tgap.faces[0]!.feature, -1, 'face 0 is the outside');
  // The metadata paragraph names every key written.
  const para = text.slice(text.indexOf('The metadata JSON holds'));
  for (const key of Object.keys(meta)) assert.ok(para.includes(`\`${key}\``), `meta.${key} is documented`);
});
