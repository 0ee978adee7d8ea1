// npm run bench:bounds [-- <dataset filter>]: issue 13 asks for a session's bytes at half a tile
// map's, and whether the worker could derive the surfaces from a tGAP-like encoding (edges shared
// by two faces, and events) instead of receiving triangles. This sizes that question on
// bench:session's views, without a browser, on bgt_otterlo_1800m and nlcd_zion:
// - the surface chunks the views query, the share some view needs, and of that the share some
//   view's slice cuts (a transition in progress): the rest shows a settled state's partition,
//   which a map could draw from that state's boundaries;
// - those boundaries: every tGAP edge version some view shows (alive at its state, over its
//   ground), each once, its points on the cube's grid, written as the floor chunk file writes its
//   points (meshoptimizer's vertex codec, then gzip), with a record per edge (its faces, its
//   steps, its length); beside it the same written for the input's edges, to set against the
//   floor chunk files, which hold those edges in the project's own encoding.
// An estimate, not a format: it has no cycles, no face table and nothing for the transitions.
import { mkdtempSync, readdirSync, rmSync, statSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { gzipSync } from 'node:zlib';
import { encodeRecords } from '../format/chunk-encode.js';
import { zAtScale } from '../format/scale.js';
import { readTgap } from '../format/tgap.js';
import type { Tgap } from '../format/tgap-model.js';
import { runSsc } from '../testing/run-ssc.js';
import { buildBenchCube } from './bench-cube.js';
import { benchArgs, datasets } from './datasets.js';
import { scriptedSession, SESSION_HEIGHT, SESSION_WIDTH } from './session-script.js';
import { printTable } from './table.js';
import { sessionNeeds, viewBox } from './triangles-in-view.js';

type Box = [number, number, number, number];

/** The edge versions of `t` alive at `state` whose ground box meets `box`, added to `out`. */
function edgesShown(t: Tgap, boxes: Float64Array, state: number, box: Box, out: Set<number>): void {
  t.edges.forEach((e, i) => {
    if (e.stepLow > state || e.stepHigh <= state) return;
    if (boxes[4 * i + 2]! < box[0] || boxes[4 * i]! > box[2] || boxes[4 * i + 3]! < box[1] || boxes[4 * i + 1]! > box[3]) return;
    out.add(i);
  });
}

/**
 * Bytes (gzip) of edges `ids` of `t`: their points on the grid `step` (i32 x, y from the
 * extent's corner, edge after edge, ordered by where they start) and a record per edge (left
 * and right face, first state, states alive, point count), each through the vertex codec.
 */
function edgeBytes(t: Tgap, ids: number[], step: number): { edges: number; points: number; bytes: number } {
  const [x0, y0] = t.meta.extent;
  const q = (v: number, o: number): number => Math.round((v - o) / step);
  const cell = 4 / step;
  const startKey = (i: number): number => {
    const e = t.edges[i]!;
    return Math.floor(q(t.xs[e.start]!, x0) / cell) * 2 ** 26 + Math.floor(q(t.ys[e.start]!, y0) / cell);
  };
  const order = [...ids].sort((a, b) => startKey(a) - startKey(b) || a - b);
  let n = 0;
  for (const i of order) n += t.edges[i]!.verts.length;
  const points = new Int32Array(2 * n), records = new Uint32Array(5 * order.length);
  let k = 0;
  order.forEach((i, r) => {
    const e = t.edges[i]!;
    for (const v of e.verts) {
      points[k++] = q(t.xs[v]!, x0);
      points[k++] = q(t.ys[v]!, y0);
    }
    records.set([e.left, e.right, e.stepLow, e.stepHigh - e.stepLow, e.verts.length], 5 * r);
  });
  const gz = (b: Uint8Array): number => gzipSync(b, { level: 6 }).length;
  return { edges: order.length, points: n, bytes: gz(encodeRecords(points.buffer, n, 8)) + gz(encodeRecords(records.buffer, order.length, 20)) };
}

const { filter } = benchArgs(1);
const mb = (b: number): string => `${(b / 1e6).toFixed(3)} MB`;
const rows = [['dataset', 'queried', 'needed', 'cut (transitions)', 'settled', 'edges shown', 'points', 'their bytes', 'input edges', 'floor chunk files']];
const work = mkdtempSync(path.join(tmpdir(), 'ssc-bench-bounds-'));
try {
  for (const d of datasets(filter, ['bgt_otterlo_1800m', 'nlcd_zion'])) {
    const tgapFile = path.join(work, `${d.name}.tgap`);
    process.stderr.write(`generalizing ${d.name}...\n`);
    const g = runSsc(['generalize', d.file, '--style', d.style, '--out', tgapFile, '--quiet']);
    if (g.code !== 0) throw new Error(`ssc generalize ${d.name} failed (exit ${g.code}): ${g.stderr}`);
    // Built from that tGAP, so that the edges and the chunks are of one generalization.
    const cube = buildBenchCube({ ...d, file: tgapFile }, path.join(work, d.name), { precompress: true });
    const t = await readTgap(tgapFile);
    const meta = cube.index.meta;
    const s = scriptedSession(meta, 120);
    const views = [s.start, ...s.frames.map((f) => f.view)];
    const gzOf = (file: string): number => statSync(path.join(cube.dir, `${file}.gz`)).size;
    const needs = await sessionNeeds(cube.dir, views.map((v) => ({ scale: v.scale, centre: v.center })), (f) => Promise.resolve(gzOf(f)), SESSION_WIDTH, SESSION_HEIGHT);

    const boxes = new Float64Array(4 * t.edges.length);
    t.edges.forEach((e, i) => {
      let a = Infinity, b = Infinity, c = -Infinity, dd = -Infinity;
      for (const v of e.verts) {
        a = Math.min(a, t.xs[v]!);
        b = Math.min(b, t.ys[v]!);
        c = Math.max(c, t.xs[v]!);
        dd = Math.max(dd, t.ys[v]!);
      }
      boxes.set([a, b, c, dd], 4 * i);
    });
    const shown = new Set<number>();
    for (const v of views) {
      const z = zAtScale(meta, v.scale);
      const box = viewBox(v.scale, v.center, SESSION_WIDTH, SESSION_HEIGHT);
      // A slice between two states shows some of each.
      for (const state of new Set([Math.floor(z), Math.ceil(z)])) edgesShown(t, boxes, state, box, shown);
    }
    const step = t.meta.options['precision'] as number;
    const e = edgeBytes(t, [...shown], step);
    const input = edgeBytes(t, t.edges.flatMap((ed, i) => (ed.stepLow === 0 ? [i] : [])), step);
    const floorFiles = readdirSync(cube.dir).filter((f) => /^b-[0-9a-f]{16}\.bin$/.test(f)).reduce((sum, f) => sum + gzOf(f), 0);
    rows.push([
      d.name, mb(needs.queriedBytes), mb(needs.neededBytes), mb(needs.cutBytes), mb(needs.neededBytes - needs.cutBytes),
      String(e.edges), String(e.points), mb(e.bytes), mb(input.bytes), mb(floorFiles),
    ]);
  }
} finally {
  rmSync(work, { recursive: true, force: true });
}
process.stdout.write(`\nbench:session's ${SESSION_WIDTH}x${SESSION_HEIGHT} views, gzip; "settled" lies at or below every slice that needs it, "edges shown" are the tGAP edge versions those views show, written once\n`);
printTable(rows);
