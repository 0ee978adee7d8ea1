// Collapse on a generalized tGAP: a hand-drawn T of three roads among fields, and the 400 m
// cut of Otterlo, checked against the tGAP's own edges (scanned here, edge by edge).
//
//   +---------------------N (fields)---------------------+ y = 30
//   |                                                    |
//   +------------A (road)-----------+-------B (road)-----+ y = 6
//   +------------------------------++-+------------------+ y = 0
//   |            SW               |C|        SE          |
//   +-----------------------------+-+--------------------+ y = -50
//  x = -50                      -3 0 3                   50
import test from 'node:test';
import assert from 'node:assert/strict';
import { EventKind, resolveFace, type Tgap } from '../../format/tgap-model.js';
import { generalizeFile } from '../pipeline.js';
import { loadStyle } from '../style.js';
import { dataset, styleFile } from '../../testing/paths.js';
import { fixtureStyle, fixtureTgap, rect, ROAD_T } from '../../testing/planar-fixtures.js';
import { collapseLines, type LineObject } from './collapse-lines.js';

const keysOf = (l: LineObject): Set<string> => {
  const out = new Set<string>();
  for (const p of l.paths) for (let i = 0; i < p.length; i += 2) out.add(`${p[i]},${p[i + 1]}`);
  return out;
};
const share = (a: LineObject, b: LineObject): boolean => {
  const ka = keysOf(a);
  return [...keysOf(b)].some((k) => ka.has(k));
};

test('three roads of a T collapse one after another into lines that meet exactly, one network', () => {
  const style = fixtureStyle([{ key: 'road', linear: true }, { key: 'field', weight: 4 }]);
  const tgap = fixtureTgap(ROAD_T, ['road', 'field'], style);
  const { lines, stats } = collapseLines(tgap, style);
  assert.deepEqual(lines.map((l) => l.face).sort(), [1, 2, 3], 'each road became a line');
  assert.equal(stats.linearSplits, 3);
  // The first road to go met the other two as areas: its ports are the middles of the
  // boundaries drawn above (A|B: x = 0, 0..6; A|C: y = 0, -3..0; B|C: y = 0, 0..3).
  const first = lines[0]!;
  const drawn: Record<number, { x: number; y: number }[]> = { 1: [{ x: 0, y: 3 }, { x: -1.5, y: 0 }], 2: [{ x: 0, y: 3 }, { x: 1.5, y: 0 }], 3: [{ x: -1.5, y: 0 }, { x: 1.5, y: 0 }] };
  assert.deepEqual(first.joins.map((j) => ({ x: j.x, y: j.y })).sort((a, b) => a.x - b.x), drawn[first.face]!.sort((a, b) => a.x - b.x));
  // Every pair of roads shares a point of their lines, and every join found its line.
  for (let i = 0; i < 3; i++) for (let k = i + 1; k < 3; k++) assert.ok(share(lines[i]!, lines[k]!), `roads ${lines[i]!.face} and ${lines[k]!.face} meet`);
  for (const l of lines) for (const j of l.joins) assert.ok(j.line >= 0 && keysOf(lines[j.line]!).has(`${j.x},${j.y}`), `face ${l.face}: join (${j.x}, ${j.y}) lies on line ${j.line}`);
  // Each line starts at its face's split.
  for (const l of lines) {
    const ev = tgap.events.find((e) => e.loser === l.face)!;
    assert.deepEqual([ev.kind, ev.step], [EventKind.Split, l.step]);
  }
});

test('a bridge deck joins the road network its style names: its line meets the roads\' lines, and without that it does not', () => {
  // The T's stem C is a bridge deck, of a linear class of its own.
  const faces = ROAD_T.map((f, i) => (i === 2 ? { ...f, cls: 'bridge' } : f));
  const lineOfBridge = (network?: string): { bridge: LineObject; roads: LineObject[] } => {
    const style = fixtureStyle([{ key: 'road', linear: true }, { key: 'field', weight: 4 }, { key: 'bridge', linear: true, ...(network ? { network } : {}) }]);
    const { lines } = collapseLines(fixtureTgap(faces, ['road', 'field', 'bridge'], style), style);
    return { bridge: lines.find((l) => l.face === 3)!, roads: lines.filter((l) => l.face !== 3) };
  };
  const apart = lineOfBridge();
  assert.equal(apart.roads.length, 2);
  for (const r of apart.roads) assert.ok(!share(apart.bridge, r), `road ${r.face}: a bridge of its own network does not meet it`);
  const joined = lineOfBridge('road');
  for (const r of joined.roads) assert.ok(share(joined.bridge, r), `road ${r.face} meets the bridge deck of its network`);
  assert.ok(joined.bridge.joins.length >= 2 && joined.bridge.joins.every((j) => j.line >= 0), 'the bridge\'s joins found the roads\' lines');
});

test('a road piece merged whole into the field around it becomes a line that meets the road it continues', () => {
  // A = [-20,0] x [0,4] goes first and is split between B and the field; B = [0,30] x [0,4],
  // then held only by the field (one neighbour), is merged whole into it.
  const faces = [
    { cls: 'road', rings: [rect(-20, 0, 0, 4)] },
    { cls: 'road', rings: [rect(0, 0, 30, 4)] },
    { cls: 'field', rings: [rect(-40, -20, 50, 20), rect(-20, 0, 30, 4)] },
  ];
  const style = fixtureStyle([{ key: 'road', linear: true }, { key: 'field', weight: 4 }]);
  const tgap = fixtureTgap(faces, ['road', 'field'], style);
  const ends = tgap.events.map((e) => [e.loser, e.kind]);
  assert.deepEqual(ends.slice(0, 2), [[1, EventKind.Split], [2, EventKind.Merge]], 'A is split, then B merged whole');
  const { lines, stats } = collapseLines(tgap, style);
  assert.deepEqual([stats.linearSplits, stats.linearMerges, stats.anchorsLeft], [1, 1, 0]);
  const [a, b] = [lines.find((l) => l.face === 1)!, lines.find((l) => l.face === 2)!];
  assert.ok(b, 'B became a line');
  assert.equal(b.step, tgap.events[1]!.step, 'from its merge on');
  assert.ok(share(a, b), 'A\'s line meets B\'s');
  // B's line runs along its mid-axis, y = 2, away from the part of A it took.
  const far = b.paths.flatMap((p) => [...p].flatMap((v, i) => (i % 2 === 0 && v >= 5 ? [[v, p[i + 1]!]] : [])));
  assert.ok(far.some(([x]) => x! >= 25) && far.every(([, y]) => Math.abs(y! - 2) < 0.05), `B's line on y = 2 from x = 5 to within 5 m of its end: ${far.join(' ')}`);
  assert.ok(b.length > 20, `B's line is ${b.length} m long`);
  // Merged into a road of its own network instead, B leaves no line: the road takes its area on.
  const merged = fixtureTgap([...faces.slice(0, 2), { cls: 'road', rings: faces[2]!.rings }], ['road'], fixtureStyle([{ key: 'road', linear: true }]));
  const own = collapseLines(merged, fixtureStyle([{ key: 'road', linear: true }]));
  assert.equal(own.stats.linearMerges, 0);
});

/** Face f's boundary segments at state s, straight from the tGAP's edges. */
function segmentsAt(tgap: Tgap, f: number, s: number): number[][] {
  const out: number[][] = [];
  for (const e of tgap.edges) {
    if (e.stepLow > s || e.stepHigh <= s) continue;
    const l = resolveFace(tgap.faces, e.left, s), r = resolveFace(tgap.faces, e.right, s);
    if ((l === f) === (r === f)) continue;
    for (let i = 0; i + 1 < e.verts.length; i++) out.push([tgap.xs[e.verts[i]!]!, tgap.ys[e.verts[i]!]!, tgap.xs[e.verts[i + 1]!]!, tgap.ys[e.verts[i + 1]!]!]);
  }
  return out;
}

/** Inside (even-odd) or within `tol` of a segment. */
function insideOrOn(segs: number[][], x: number, y: number, tol: number): boolean {
  let inside = false;
  for (const [ax, ay, bx, by] of segs as [number, number, number, number][]) {
    const dx = bx - ax, dy = by - ay;
    const t = Math.max(0, Math.min(1, ((x - ax) * dx + (y - ay) * dy) / (dx * dx + dy * dy)));
    if (Math.hypot(x - ax - t * dx, y - ay - t * dy) <= tol) return true;
    if (ay > y !== by > y && x < ax + ((y - ay) * dx) / dy) inside = !inside;
  }
  return inside;
}

test('bgt_otterlo_400m: every line lies in its face, and faces that touched at a split get lines that meet', async () => {
  const styleName = styleFile('bgt.json');
  const { tgap } = await generalizeFile(dataset('bgt_otterlo_400m.geojson'), { style: styleName });
  const style = await loadStyle(styleName);
  const { lines, stats } = collapseLines(tgap, style);
  const linear = (f: number): boolean => f > 0 && style.classes[tgap.faces[f]!.classIndex]!.linear;
  const linearSplits = tgap.events.filter((e) => e.kind === EventKind.Split && linear(e.loser));
  // Merged whole into a face of another class (each linear class is its own network here,
  // but for the bridge deck, which joins the roads).
  const network = (f: number): string => { const k = style.classes[tgap.faces[f]!.classIndex]!; return k.network ?? k.key; };
  const linearMerges = tgap.events.filter((e) => e.kind === EventKind.Merge && linear(e.loser) && !(linear(e.into) && network(e.into) === network(e.loser)));
  assert.equal(stats.linearSplits, linearSplits.length);
  assert.equal(stats.linearMerges, linearMerges.length);
  assert.ok(linearMerges.length > 0, 'linear faces merged whole into other classes');
  assert.equal(lines.length + stats.empty, linearSplits.length + linearMerges.length);
  assert.equal(stats.anchorsLeft, 0, 'every line\'s end at a face of its network still an area is met by that area\'s line');
  assert.ok(lines.length > 100, `${lines.length} lines`);

  let outside = 0;
  for (const l of lines) {
    const segs = segmentsAt(tgap, l.face, l.step - 1);
    const bridged = new Set(l.joins.filter((j) => j.bridge).map((j) => `${j.x},${j.y}`));
    for (const p of l.paths) {
      for (let i = 0; i < p.length; i += 2) if (!insideOrOn(segs, p[i]!, p[i + 1]!, 1e-6) && !bridged.has(`${p[i]},${p[i + 1]}`)) outside++;
    }
  }
  assert.equal(outside, 0, 'line vertices outside their face');

  // Pairs of faces of one class sharing a boundary when the first splits; the second's area
  // is held, when it collapses in turn, by the face of a later line.
  let pairs = 0, apart = 0;
  lines.forEach((l) => {
    const s = l.step - 1;
    const across = new Set<number>();
    for (const e of tgap.edges) {
      if (e.stepLow > s || e.stepHigh <= s) continue;
      const a = resolveFace(tgap.faces, e.left, s), b = resolveFace(tgap.faces, e.right, s);
      const g = a === l.face ? b : b === l.face ? a : -1;
      if (g > 0 && g !== l.face && tgap.faces[g]!.classIndex === l.classIndex) across.add(g);
    }
    for (const g of across) {
      const later = lines.find((m) => m.step > l.step && m.classIndex === l.classIndex && resolveFace(tgap.faces, g, m.step - 1) === m.face);
      if (!later) continue;
      pairs++;
      if (!share(l, later)) apart++;
    }
  });
  assert.ok(pairs > 100, `${pairs} pairs`);
  assert.equal(apart, 0, `of ${pairs} pairs of touching faces, lines apart`);

  assert.deepEqual(collapseLines(tgap, style), { lines, stats }, 'the same tGAP gives the same lines');
});
