// Line simplification over scale: hand-made lines on a hand-made scale table (vertices go at
// the state their triangle falls under the threshold; vertices of edges and other lines in the
// triangle hold them while they are there), and the 400 m cut of Otterlo, where no simplified
// line touches a line or a face boundary that its full line did not.
import test from 'node:test';
import assert from 'node:assert/strict';
import Flatbush from 'flatbush';
import type { Tgap, TgapEdge } from '../../format/tgap-model.js';
import { segmentsIntersect } from '../geom/predicates.js';
import { generalizeFile } from '../pipeline.js';
import { loadStyle } from '../style.js';
import { dataset, styleFile } from '../../testing/paths.js';
import { collapseLines } from './collapse-lines.js';
import type { PrunedLine } from './prune-lines.js';
import { pruneLines } from './prune-lines.js';
import { areaThresholds, linePathsAt, lineVersions, simplifyLines } from './simplify-lines.js';

/**
 * Steps 0..3 at 1:1,000, 1:2,000, 1:5,000, 1:10,000 (faces 100, 25, 4, 1) with a resolution of
 * 1 mm: tolerances 1, 2, 5, 10 m, Visvalingam thresholds tol²/2 = 0.5, 2, 12.5, 50 m². Edges
 * are given as vertex chains with their step range.
 */
function handTgap(edges: { pts: number[]; from: number; to: number }[]): Tgap {
  const xs: number[] = [], ys: number[] = [];
  const out: TgapEdge[] = edges.map((e) => {
    const verts: number[] = [];
    for (let k = 0; k < e.pts.length; k += 2) {
      verts.push(xs.length);
      xs.push(e.pts[k]!);
      ys.push(e.pts[k + 1]!);
    }
    return { start: verts[0]!, end: verts[verts.length - 1]!, left: 1, right: 2, verts: Int32Array.from(verts), stepLow: e.from, stepHigh: e.to, parents: new Int32Array(0), removed: new Int32Array(0), removedPhase: new Uint8Array(0) };
  });
  return {
    meta: {
      version: 1, crs: 'EPSG:28992', extent: [0, 0, 100, 100], baseScale: 1000, resolutionMm: 1, baseFaces: 100, steps: 3, facesAlive: [100, 25, 4, 1],
      holes: [], repairs: {}, source: 'hand', style: {}, attributes: [], options: {},
    },
    xs: Float64Array.from(xs), ys: Float64Array.from(ys), faces: [], edges: out, events: [],
  };
}

const line = (pts: number[], step: number, prunedStep: number): PrunedLine => ({
  face: 1, feature: -1, classIndex: 0, step, prunedStep, paths: [Float64Array.from(pts)], joins: [], length: 0,
});

test('thresholds follow the scale of every step', () => {
  assert.deepEqual([...areaThresholds(handTgap([]))].map((t) => Math.round(t * 1e9) / 1e9), [0.5, 2, 12.5, 50]);
});

test('a vertex goes at the first state its triangle is under the threshold, after its neighbour\'s removal grew it', () => {
  // P1's triangle: 20 x 0.1 / 2 = 1 m² (state 1); P2's: 10.5 m² (state 2) until P1 goes, then
  // (P0, P2, P3) = 20 x 2.5 / 2 = 25 m² (state 3); P3's: 30 x 2.5 / 2 = 37.5 m² (state 3, after
  // P2 as 37.5 / 50 > 25 / 50); then (P0, P3, P4) = 62.5 m², over every threshold.
  const pts = [0, 0, 10, 0.1, 20, 0, 30, 2.5, 50, 0];
  const { lines, stats } = simplifyLines([line(pts, 1, 4)], handTgap([]));
  assert.deepEqual([...lines[0]!.vertexEnd[0]!], [4, 1, 3, 4, 4]);
  assert.deepEqual(stats, { removed: 2, blocked: 0, given: 0 });
  assert.deepEqual(lineVersions(lines[0]!).map((v) => [v.step, [...v.paths[0]!]]), [
    [1, [0, 0, 20, 0, 30, 2.5, 50, 0]],
    [3, [0, 0, 30, 2.5, 50, 0]],
  ]);
  assert.throws(() => simplifyLines([line(pts, 1, 4), line(pts, 2, 9)], handTgap([])), /line 1 \(face 1, feature #-1\): its range \[2, 9\) is not a range of states of the tGAP \(0\.\.4\)/);
  // A line pruned at state 3 keeps P2: the removal would come when it is gone.
  assert.deepEqual([...simplifyLines([line(pts, 1, 3)], handTgap([])).lines[0]!.vertexEnd[0]!], [3, 1, 3, 3, 3]);
});

test('a vertex of an edge or another line inside the triangle holds the vertex while it is there', () => {
  // The bump's triangle is 20 x 1 / 2 = 10 m² (state 2); (10, 0.5) lies inside it.
  const bump = line([0, 0, 10, 1, 20, 0], 1, 4);
  const endOfBump = (tgap: Tgap, others: PrunedLine[] = []): number => simplifyLines([bump, ...others], tgap).lines[0]!.vertexEnd[0]![1]!;
  const edge = (to: number): { pts: number[]; from: number; to: number } => ({ pts: [10, 0.5, 10, 30], from: 0, to });
  assert.equal(endOfBump(handTgap([])), 2, 'nothing in the way');
  assert.equal(endOfBump(handTgap([edge(2)])), 2, 'an edge gone by state 2 does not hold it');
  assert.equal(endOfBump(handTgap([edge(3)])), 3, 'an edge there until state 3 holds it until then');
  assert.equal(endOfBump(handTgap([edge(10)])), 4, 'an edge there for the line\'s life holds it for good');
  assert.equal(endOfBump(handTgap([{ pts: [10, 0.5, 10, 30], from: 4, to: 9 }])), 2, 'an edge after the line\'s end does not');
  const other = (step: number, prunedStep: number): PrunedLine => line([10, 0.5, 10, 30, 40, 30], step, prunedStep);
  assert.equal(endOfBump(handTgap([]), [other(3, 4)]), 4, 'a line born at state 3 holds it: it will be there with the bump');
  assert.equal(endOfBump(handTgap([]), [other(1, 2)]), 2, 'a line pruned by state 2 does not');
  assert.equal(endOfBump(handTgap([]), [other(1, 3)]), 3, 'a line pruned at state 3 holds it until then');
  // A vertex on the chord itself blocks too: the new segment would touch it.
  assert.equal(endOfBump(handTgap([{ pts: [10, 0, 10, -30], from: 0, to: 10 }])), 4, 'a vertex on the chord');
});

/** Pairs "a b" of owners whose closed segments meet (a from `as`, b from `bs`, a !== b when `same`). */
function contacts(as: { segs: number[]; owner: number[] }, bs: { segs: number[]; owner: number[] }, same: boolean): Set<string> {
  const out = new Set<string>();
  const nb = bs.owner.length;
  if (nb === 0) return out;
  const index = new Flatbush(nb);
  for (let i = 0; i < nb; i++) {
    const [x0, y0, x1, y1] = bs.segs.slice(4 * i, 4 * i + 4) as [number, number, number, number];
    index.add(Math.min(x0, x1), Math.min(y0, y1), Math.max(x0, x1), Math.max(y0, y1));
  }
  index.finish();
  as.owner.forEach((a, i) => {
    const [ax, ay, bx, by] = as.segs.slice(4 * i, 4 * i + 4) as [number, number, number, number];
    for (const j of index.search(Math.min(ax, bx), Math.min(ay, by), Math.max(ax, bx), Math.max(ay, by))) {
      const b = bs.owner[j]!;
      if (same && a === b) continue;
      const [cx, cy, dx, dy] = bs.segs.slice(4 * j, 4 * j + 4) as [number, number, number, number];
      if (segmentsIntersect(ax, ay, bx, by, cx, cy, dx, dy)) out.add(`${a} ${b}`);
    }
  });
  return out;
}

function segmentsOf(polylines: { owner: number; paths: ArrayLike<number>[] }[]): { segs: number[]; owner: number[] } {
  const segs: number[] = [], owner: number[] = [];
  for (const { owner: o, paths } of polylines) {
    for (const p of paths) {
      for (let k = 2; k < p.length; k += 2) {
        segs.push(p[k - 2]!, p[k - 1]!, p[k]!, p[k + 1]!);
        owner.push(o);
      }
    }
  }
  return { segs, owner };
}

test('bgt_otterlo_400m: simplified lines touch no line or face boundary their full lines do not, and lose vertices', async () => {
  const styleName = styleFile('bgt.json');
  const { tgap } = await generalizeFile(dataset('bgt_otterlo_400m.geojson'), { style: styleName });
  const style = await loadStyle(styleName);
  const pruned = pruneLines(collapseLines(tgap, style).lines, tgap, style).lines;
  const { lines, stats } = simplifyLines(pruned, tgap);
  assert.ok(stats.removed > 1000, `${stats.removed} vertices removed`);

  // The states at which the lines change, and eight in between.
  const changes = [...new Set(lines.flatMap((l) => l.vertexEnd.flatMap((e) => [...e])))].filter((s) => s <= tgap.meta.steps).sort((a, b) => a - b);
  const states = [...new Set(Array.from({ length: 8 }, (_, k) => changes[Math.floor((k * (changes.length - 1)) / 7)]!))];
  let full = 0, kept = 0;
  for (const s of states) {
    const shown = lines.map((l, i) => ({ l, i })).filter(({ l }) => l.step <= s && l.prunedStep > s);
    const before = segmentsOf(shown.map(({ l, i }) => ({ owner: i, paths: l.paths })));
    const after = segmentsOf(shown.map(({ l, i }) => ({ owner: i, paths: linePathsAt(l, s) })));
    // Lines still meet: every join is a point of the simplified line.
    for (const { l } of shown) {
      const points = new Set(linePathsAt(l, s).flatMap((p) => Array.from({ length: p.length / 2 }, (_, k) => `${p[2 * k]},${p[2 * k + 1]}`)));
      for (const j of l.joins) assert.ok(points.has(`${j.x},${j.y}`), `state ${s}, face ${l.face}: join (${j.x}, ${j.y}) lost`);
    }
    full += before.owner.length;
    kept += after.owner.length;
    const edges = segmentsOf(tgap.edges.flatMap((e, i) => (e.stepLow <= s && e.stepHigh > s ? [{ owner: i, paths: [Array.from(e.verts, (v) => [tgap.xs[v]!, tgap.ys[v]!]).flat()] }] : [])));
    const newOf = (was: Set<string>, is: Set<string>): string[] => [...is].filter((p) => !was.has(p));
    assert.deepEqual(newOf(contacts(before, before, true), contacts(after, after, true)), [], `state ${s}: lines that now touch`);
    assert.deepEqual(newOf(contacts(before, edges, false), contacts(after, edges, false)), [], `state ${s}: lines that now touch a face boundary`);
  }
  assert.ok(kept < full / 2, `${kept} of ${full} segments kept at the states checked`);

  assert.deepEqual(simplifyLines(pruned, tgap), { lines, stats }, 'the same lines give the same simplification');
});
