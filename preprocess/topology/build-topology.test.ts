// Hand-made topology cases for the input stage of `ssc generalize`: tiny GeoJSON (and one
// TopoJSON) files run through the real CLI, and where it helps through buildTopology itself.
// Every expected number (counts, repairs, areas, shared boundary lengths) is derived by hand
// from the fixture drawn in the comment above it.
import test, { after, before } from 'node:test';
import assert from 'node:assert/strict';
import { existsSync, readdirSync, writeFileSync } from 'node:fs';
import { gzipSync } from 'node:zlib';
import path from 'node:path';
import { startSscSession, type SscSession } from '../../testing/run-ssc.js';
import { at, collection, CRS, feature, OX, OY, polygon, rect, ring, STYLE, writeCase, type Case, type Json, type XY } from '../../testing/topology-cases.js';
import { resolveCrs } from '../io/crs.js';
import { InputError } from '../io/errors.js';
import { readInput } from '../io/read-input.js';
import { readTgap } from '../../format/tgap.js';
import type { Tgap } from '../../format/tgap-model.js';
import { buildTopology, type Topology, type TopologyRepairs } from './build-topology.js';

interface Run {
  code: number;
  stdout: string;
  stderr: string;
  out: string;
}

// One CLI process for the whole file: the same main() per case, without tsx's start-up each time.
let ssc: SscSession;
before(() => {
  ssc = startSscSession();
});
after(() => ssc.close());

// The cases are drawn in millimetres around a 1 mm grid (the default at their 1:1,000 is
// 2^-7 m, position-grid.ts), unless a case gives its own.
async function generalize(c: Case, out: string, ...extra: string[]): Promise<Run> {
  const file = path.join(c.dir, out);
  const precision = extra.includes('--precision') ? [] : ['--precision', '0.001'];
  const r = await ssc.run(['generalize', c.input, '--style', c.style, '--out', file, '--quiet', ...precision, ...extra]);
  return { ...r, out: file };
}

const NO_REPAIRS: TopologyRepairs = {
  closedRings: 0, duplicatePoints: 0, reorientedRings: 0, tJunctions: 0, snappedPoints: 0, mergedPoints: 0, spikes: 0, slivers: 0,
};

interface Counts {
  faces: number;
  edges: number;
  nodes: number;
  vertices: number;
}

interface Expected {
  counts: Counts;
  repairs?: Partial<TopologyRepairs>;
  /** Area of each feature, in input order. */
  areas: number[];
  /** Shared boundary length of each pair of neighbours ("A|B", features by id; "out" is outside the domain). */
  shared: Record<string, number>;
  extent?: [number, number, number, number];
}

function countsOf(stdout: string): Counts {
  const m = /^topology: (\d+) faces, (\d+) edges, (\d+) nodes, (\d+) vertices$/m.exec(stdout);
  assert.ok(m, `no topology line in:\n${stdout}`);
  return { faces: Number(m[1]), edges: Number(m[2]), nodes: Number(m[3]), vertices: Number(m[4]) };
}

const round = (v: number): number => Math.round(v * 1e6) / 1e6;

/** Name of tGAP face f at step 0: the id of input feature f - 1, or "out". */
function faceName(t: Tgap, f: number): string {
  return f === 0 ? 'out' : String(t.meta.attributes[f - 1]!.id);
}

/** Shared boundary length per pair of faces at step 0, from the tGAP's edges. */
function sharedLengths(t: Tgap): Record<string, number> {
  const out: Record<string, number> = {};
  for (const e of t.edges) {
    if (e.stepLow !== 0) continue;
    assert.notEqual(e.left, e.right, 'an edge has the same face on both sides');
    let len = 0;
    for (let i = 0; i + 1 < e.verts.length; i++) {
      const a = e.verts[i]!, b = e.verts[i + 1]!;
      len += Math.hypot(t.xs[b]! - t.xs[a]!, t.ys[b]! - t.ys[a]!);
    }
    const key = [faceName(t, e.left), faceName(t, e.right)].sort().join('|');
    out[key] = (out[key] ?? 0) + len;
  }
  for (const k of Object.keys(out)) out[k] = round(out[k]!);
  return out;
}

function sortedKeys(o: Record<string, number>): Record<string, number> {
  return Object.fromEntries(Object.entries(o).sort(([a], [b]) => (a < b ? -1 : a > b ? 1 : 0)));
}

/** Runs the CLI on a valid case and checks what it reports and writes against `exp`. */
async function expectPartition(c: Case, exp: Expected, ...extra: string[]): Promise<Tgap> {
  const r = await generalize(c, 'out.tgap', ...extra);
  assert.equal(r.code, 0, r.stderr);
  assert.deepEqual(countsOf(r.stdout), exp.counts, 'faces, edges, nodes, vertices');
  const t = await readTgap(r.out);
  assert.deepEqual(t.meta.repairs, { ...NO_REPAIRS, ...exp.repairs }, 'repairs');
  assert.equal(t.meta.baseFaces, exp.areas.length);
  assert.equal(t.meta.facesAlive[0], exp.areas.length);
  for (let f = 1; f <= exp.areas.length; f++) {
    const a = t.faces[f]!.area2 / 2;
    assert.ok(Math.abs(a - exp.areas[f - 1]!) < 1e-6, `area of ${faceName(t, f)} is ${a}, expected ${exp.areas[f - 1]}`);
  }
  assert.deepEqual(sortedKeys(sharedLengths(t)), sortedKeys(exp.shared), 'neighbours and shared lengths');
  if (exp.extent) assert.deepEqual(t.meta.extent, exp.extent.map((v, i) => v + (i % 2 ? OY : OX)), 'extent');
  return t;
}

/** The topology of an input as the pipeline builds it (read, CRS, topology). */
async function topologyOf(file: string): Promise<Topology> {
  const raw = await readInput(file);
  resolveCrs(raw);
  return buildTopology(raw.features, { precision: 0.001, file: raw.file, inputRepairs: raw.repairs });
}

async function topologyError(file: string): Promise<InputError> {
  try {
    await topologyOf(file);
  } catch (err) {
    assert.ok(err instanceof InputError, `not an InputError: ${String(err)}`);
    return err;
  }
  assert.fail('buildTopology accepted the input');
}

/** True when (px, py) lies on a side of one of the local rings (given shifted). */
function onBoundary(rings: XY[][], px: number, py: number): boolean {
  for (const r of rings) {
    for (let i = 0; i < r.length; i++) {
      const [ax, ay] = at(...r[i]!), [bx, by] = at(...r[(i + 1) % r.length]!);
      const cross = (bx - ax) * (py - ay) - (by - ay) * (px - ax);
      const len = Math.hypot(bx - ax, by - ay);
      const t = ((px - ax) * (bx - ax) + (py - ay) * (by - ay)) / (len * len);
      if (Math.abs(cross) / len < 1e-3 && t >= -1e-9 && t <= 1 + 1e-9) return true;
    }
  }
  return false;
}

interface Refusal {
  /**
   * Index and id (null: none) of the feature the message must name; null when the message is
   * about the whole file, or when the caller checks the features named itself.
   */
  feature: [number, string | number | null] | null;
  message: RegExp;
  /** Check on the location named; null when no location is expected. */
  location: ((x: number, y: number) => boolean) | null;
}

/** Runs the CLI on input that must be refused and checks the message, the exit code and that nothing is written. */
async function expectRefusal(c: Case, exp: Refusal, ...extra: string[]): Promise<string> {
  const r = await generalize(c, 'out.tgap', ...extra);
  assert.notEqual(r.code, 0, `accepted:\n${r.stdout}`);
  assert.equal(r.stdout, '', 'nothing on stdout');
  const lines = r.stderr.trimEnd().split('\n');
  assert.equal(lines.length, 1, `one line on stderr:\n${r.stderr}`);
  const msg = lines[0]!;
  assert.ok(msg.startsWith(`ssc generalize: ${path.basename(c.input)}`), `names the file: ${msg}`);
  if (exp.feature) {
    const [index, id] = exp.feature;
    const ref = id === null ? `feature #${index}` : `feature #${index} (id ${JSON.stringify(id)})`;
    assert.ok(msg.includes(`, ${ref}, `) || msg.includes(`, ${ref}: `), `names ${ref}: ${msg}`);
  }
  assert.match(msg, exp.message);
  const loc = /, at \((-?[\d.e+]+), (-?[\d.e+]+)\): /.exec(msg);
  if (exp.location) {
    assert.ok(loc, `names a location: ${msg}`);
    const x = Number(loc[1]), y = Number(loc[2]);
    assert.ok(exp.location(x, y), `location (${x}, ${y}) is not where expected: ${msg}`);
  } else {
    assert.equal(loc, null, `names no location: ${msg}`);
  }
  assert.equal(existsSync(r.out), false, 'no output file');
  assert.deepEqual(readdirSync(c.dir).sort(), c.files, 'no output or temporary file left in the folder');
  return msg;
}

const isAt = (x: number, y: number) => (px: number, py: number): boolean => px === OX + x && py === OY + y;

// ---------------------------------------------------------------------------------------------
// Valid partitions

test('T-junction: a corner of two faces in the middle of a neighbour\'s side is put on that side', async (t) => {
  //  (0,20) +------+------+ (20,20)
  //         |      |  C   |
  //         |  A   +------+ (20,10)     A's right side runs straight from (10,0) to (10,20);
  //         |      |  B   |             B and C have a corner at (10,10) in its middle.
  //  (0,0)  +------+------+ (20,0)
  const A = rect(0, 0, 10, 20), B = rect(10, 0, 20, 10), C = rect(10, 10, 20, 20);
  const c = writeCase(t, 't.geojson', collection([feature('A', polygon(A)), feature('B', polygon(B)), feature('C', polygon(C))]));
  // Vertices: the 4 corners of A, (20,0), (20,10), (10,10), (20,20). Nodes (3 directions):
  // (10,0), (10,10), (10,20), (20,10). Edges: A|B, A|C, B|C and one outside chain per face.
  await expectPartition(c, {
    counts: { faces: 3, edges: 6, nodes: 4, vertices: 8 },
    repairs: { tJunctions: 1 },
    areas: [200, 100, 100],
    shared: { 'A|B': 10, 'A|C': 10, 'B|C': 10, 'A|out': 40, 'B|out': 20, 'C|out': 20 },
  });
  const topo = await topologyOf(c.input);
  const ends = (f: number, g: number): string[] => {
    const e = topo.edges.filter((e) => (e.left === f && e.right === g) || (e.left === g && e.right === f));
    assert.equal(e.length, 1, `one edge between faces ${f} and ${g}`);
    return [...e[0]!.verts].map((v) => `${topo.xs[v]},${topo.ys[v]}`).sort();
  };
  // A's side is cut at the T: (10,0)-(10,10) with B, (10,10)-(10,20) with C, nothing in between.
  assert.deepEqual(ends(1, 2), [at(10, 0), at(10, 10)].map(String).sort());
  assert.deepEqual(ends(1, 3), [at(10, 10), at(10, 20)].map(String).sort());
  assert.deepEqual(ends(2, 3), [at(10, 10), at(20, 10)].map(String).sort());
});

test('a hole filled by two other faces', async (t) => {
  //  +-----------------+ (30,30)
  //  |   A  +--+--+    |       A's hole (10,10)-(20,20), clockwise, with points at (15,10)
  //  |      |B |C |    |       and (15,20); B and C fill it.
  //  |      +--+--+    |
  //  +-----------------+
  const outer = rect(0, 0, 30, 30);
  const hole: XY[] = [[10, 10], [10, 20], [15, 20], [20, 20], [20, 10], [15, 10]];
  const c = writeCase(t, 'hole.geojson', collection([
    feature('A', polygon(outer, hole)),
    feature('B', polygon(rect(10, 10, 15, 20)), 'water'),
    feature('C', polygon(rect(15, 10, 20, 20)), 'water'),
  ]));
  // Vertices: 4 outer + 6 on the hole. Nodes: (15,10) and (15,20), and one on A's outer ring
  // (a ring without any node is a loop). Edges: A|B, A|C, B|C and the outer loop.
  await expectPartition(c, {
    counts: { faces: 3, edges: 4, nodes: 3, vertices: 10 },
    areas: [900 - 100, 50, 50],
    shared: { 'A|B': 5 + 10 + 5, 'A|C': 5 + 10 + 5, 'B|C': 10, 'A|out': 120 },
  });
});

test('an island: a face alone in another face\'s hole, no node on its ring', async (t) => {
  const outer = rect(0, 0, 30, 30);
  const hole: XY[] = [[20, 20], [20, 10], [10, 10], [10, 20]]; // clockwise, starting at another corner
  const c = writeCase(t, 'island.geojson', collection([feature('A', polygon(outer, hole)), feature('B', polygon(rect(10, 10, 20, 20)), 'water')]));
  // Two rings without nodes: two loop edges, one node each.
  await expectPartition(c, {
    counts: { faces: 2, edges: 2, nodes: 2, vertices: 8 },
    areas: [800, 100],
    shared: { 'A|B': 40, 'A|out': 120 },
  });
  const topo = await topologyOf(c.input);
  for (const e of topo.edges) {
    assert.equal(e.start, e.end, 'a loop');
    assert.equal(e.verts.length, 5, 'four corners and back to the first');
  }
});

// A's sloped side and its hole (filled by B), whose vertices come within 0.1 mm of that side.
const NEAR_HOLE_OUTER: XY[] = [[0, 0], [30, 0], [30, 20], [0, 29.123]];
const NEAR_HOLE: XY[] = [[10, 10], [14.005, 24.864], [16.001, 24.257], [20, 10]]; // clockwise

test('an outer ring passing 0.09 mm from vertices of its own hole builds: snapping does not fold it onto the hole', async (t) => {
  //  (0,29.123) +._
  //             |  '-._           A's sloped side runs from (30,20) to (0,29.123); two vertices of
  //             |   /\ '-+ (30,20) its hole (filled by B) lie 0.076 and 0.092 mm below it, within
  //             |  / B \ |         the precision (1 mm). Put into A's side as T-junctions they
  //             |  +---+ |         folded A's outer ring onto its hole, and the input was refused
  //      (0,0)  +--------+ (30,0)  as an overlap of A and B.
  const outer = NEAR_HOLE_OUTER, hole = NEAR_HOLE;
  const side = (x: number): number => 29.123 - (9.123 * x) / 30;
  const gap = (p: XY): number => (side(p[0]) - p[1]) * Math.cos(Math.atan(9.123 / 30));
  assert.ok(gap(hole[1]!) > 0 && gap(hole[1]!) < 1e-4 && gap(hole[2]!) > 0 && gap(hole[2]!) < 1e-4, 'the hole comes within 0.1 mm of the side');
  const c = writeCase(t, 'near-hole.geojson', collection([feature('A', polygon(outer, hole)), feature('B', polygon([...hole].reverse()), 'water')]));
  const area = (r: XY[]): number => Math.abs(r.reduce((s, [x, y], i) => s + x * r[(i + 1) % r.length]![1] - r[(i + 1) % r.length]![0] * y, 0)) / 2;
  const perimeter = (r: XY[]): number => r.reduce((s, [x, y], i) => s + Math.hypot(r[(i + 1) % r.length]![0] - x, r[(i + 1) % r.length]![1] - y), 0);
  // Two rings without nodes, as for an island: nothing inserted, nothing merged.
  await expectPartition(c, {
    counts: { faces: 2, edges: 2, nodes: 2, vertices: 8 },
    areas: [area(outer) - area(hole), area(hole)],
    shared: { 'A|B': round(perimeter(hole)), 'A|out': round(perimeter(outer)) },
  });
});

test('at the default precision (2^-7 m at 1:1,000) that ring crosses its hole, and the refusal says how to snap less', async (t) => {
  // The case above: the hole's vertices 0.08 and 0.09 mm below A's side. Snapped to 7.8 mm they
  // land on either side of it.
  const c = writeCase(t, 'near-hole.geojson', collection([feature('A', polygon(NEAR_HOLE_OUTER, NEAR_HOLE)), feature('B', polygon([...NEAR_HOLE].reverse()), 'water')]));
  const out = path.join(c.dir, 'out.tgap');
  const r = await ssc.run(['generalize', c.input, '--style', c.style, '--out', out, '--quiet']);
  assert.notEqual(r.code, 0);
  assert.match(r.stderr, /crosses feature #\d \(id "[AB]"\) \(overlap\) \(the snapping to a grid of 0\.0078125 moved points; a finer --precision may keep them apart\)/);
  assert.equal(existsSync(out), false, 'no output file');
});

test('a MultiPolygon feature with two parts', async (t) => {
  //  +----+----+----+
  //  | A1 | B  | A2 |      A is one feature of two parts on either side of B.
  //  +----+----+----+
  const c = writeCase(t, 'multi.geojson', collection([
    feature('A', { type: 'MultiPolygon', coordinates: [[ring(rect(0, 0, 10, 10))], [ring(rect(20, 0, 30, 10))]] }),
    feature('B', polygon(rect(10, 0, 20, 10)), 'water'),
  ]));
  // Nodes: (10,0), (10,10), (20,0), (20,10). Edges: two A|B, two A|out (3 sides each), two B|out.
  const tg = await expectPartition(c, {
    counts: { faces: 2, edges: 6, nodes: 4, vertices: 8 },
    areas: [200, 100],
    shared: { 'A|B': 20, 'A|out': 60, 'B|out': 20 },
  });
  assert.equal(tg.edges.filter((e) => e.stepLow === 0 && e.left * e.right === 2).length, 2, 'B borders each part of A on its own edge');
});

test('faces touching at a single point are not neighbours', async (t) => {
  await t.test('four squares around a point: the diagonal pairs', async (t) => {
    //  +---+---+
    //  | D | B |    A and B touch only at (10,10), and so do C and D.
    //  +---+---+
    //  | A | C |
    //  +---+---+
    const c = writeCase(t, 'checker.geojson', collection([
      feature('A', polygon(rect(0, 0, 10, 10))),
      feature('B', polygon(rect(10, 10, 20, 20))),
      feature('C', polygon(rect(10, 0, 20, 10)), 'water'),
      feature('D', polygon(rect(0, 10, 10, 20)), 'water'),
    ]));
    // Nodes: the centre (4 directions) and the middle of each outer side (3).
    await expectPartition(c, {
      counts: { faces: 4, edges: 8, nodes: 5, vertices: 9 },
      areas: [100, 100, 100, 100],
      shared: { 'A|C': 10, 'A|D': 10, 'B|C': 10, 'B|D': 10, 'A|out': 20, 'B|out': 20, 'C|out': 20, 'D|out': 20 },
    });
  });
  await t.test('two squares touching at a corner: never merged with each other', async (t) => {
    const c = writeCase(t, 'pinch.geojson', collection([feature('A', polygon(rect(0, 0, 10, 10))), feature('B', polygon(rect(10, 10, 20, 20)))]));
    // One node where they touch (4 directions), each square one loop edge from it.
    const tg = await expectPartition(c, {
      counts: { faces: 2, edges: 2, nodes: 1, vertices: 7 },
      areas: [100, 100],
      shared: { 'A|out': 40, 'B|out': 40 },
    });
    // Each has no neighbour but the outside: the first to come up leaves the map (merges into
    // the outside); the last one stays.
    assert.equal(tg.meta.steps, 1);
    assert.deepEqual(tg.meta.facesAlive, [2, 1]);
    assert.deepEqual(tg.events.map((e) => e.into), [0], 'faces that are not neighbours are not merged with each other');
  });
});

test('rings given clockwise (holes counterclockwise) are reoriented and counted', async (t) => {
  // The island case with every ring turned the other way: 3 rings reoriented, the same result.
  const rev = (r: XY[]): XY[] => [...r].reverse();
  const c = writeCase(t, 'cw.geojson', collection([
    feature('A', polygon(rev(rect(0, 0, 30, 30)), rect(10, 10, 20, 20))),
    feature('B', polygon(rev(rect(10, 10, 20, 20))), 'water'),
  ]));
  await expectPartition(c, {
    counts: { faces: 2, edges: 2, nodes: 2, vertices: 8 },
    repairs: { reorientedRings: 3 },
    areas: [800, 100],
    shared: { 'A|B': 40, 'A|out': 120 },
  });
});

test('open rings are closed and counted', async (t) => {
  const open = (r: XY[]): Json => ({ type: 'Polygon', coordinates: [ring(r, true)] });
  const c = writeCase(t, 'open.geojson', collection([feature('A', open(rect(0, 0, 10, 10))), feature('B', open(rect(10, 0, 20, 10)))]));
  await expectPartition(c, {
    counts: { faces: 2, edges: 3, nodes: 2, vertices: 6 },
    repairs: { closedRings: 2 },
    areas: [100, 100],
    shared: { 'A|B': 10, 'A|out': 30, 'B|out': 30 },
  });
});

test('repeated consecutive points are dropped and counted', async (t) => {
  // A: (10,0) twice, (10,10) three times, the closing (0,0) twice: 1 + 2 + 1 repeats.
  // B: (20,0) twice: 1 repeat.
  const a: XY[] = [[0, 0], [10, 0], [10, 0], [10, 10], [10, 10], [10, 10], [0, 10], [0, 0], [0, 0]];
  const b: XY[] = [[10, 0], [20, 0], [20, 0], [20, 10], [10, 10], [10, 0]];
  const c = writeCase(t, 'dup.geojson', collection([
    feature('A', { type: 'Polygon', coordinates: [ring(a, true)] }),
    feature('B', { type: 'Polygon', coordinates: [ring(b, true)] }),
  ]));
  await expectPartition(c, {
    counts: { faces: 2, edges: 3, nodes: 2, vertices: 6 },
    repairs: { duplicatePoints: 5 },
    areas: [100, 100],
    shared: { 'A|B': 10, 'A|out': 30, 'B|out': 30 },
  });
});

test('points closer than the precision are merged and counted', async (t) => {
  // B's left side is at x = 10.001, one grid step (the default precision, 0.001) from A's
  // right side at x = 10: its two points there become A's. (20, 0.0004) is snapped to (20, 0).
  const b: XY[] = [[10.001, 0], [20, 0.0004], [20, 10], [10.001, 10]];
  const c = writeCase(t, 'near.geojson', collection([feature('A', polygon(rect(0, 0, 10, 10))), feature('B', polygon(b))]));
  await expectPartition(c, {
    // The merged-away points are no vertices of the topology.
    counts: { faces: 2, edges: 3, nodes: 2, vertices: 6 },
    repairs: { snappedPoints: 1, mergedPoints: 2 },
    areas: [100, 100], // B is 10 x 10 once on A's side, not 9.999 x 10
    shared: { 'A|B': 10, 'A|out': 30, 'B|out': 30 },
    extent: [0, 0, 20, 10],
  });
});

test('zero-width spikes are removed and counted', async (t) => {
  await t.test('a spike out of the domain', async (t) => {
    // A goes out along y = 5 to (30,5) and straight back; B sits on top of A.
    const a: XY[] = [[0, 0], [10, 0], [10, 5], [30, 5], [10, 5], [10, 10], [0, 10]];
    const c = writeCase(t, 'spike-out.geojson', collection([feature('A', polygon(a)), feature('B', polygon(rect(0, 10, 10, 20)))]));
    await expectPartition(c, {
      // (30,5) is gone: 5 points of A and 2 of B; the map's extent ends at x = 10.
      counts: { faces: 2, edges: 3, nodes: 2, vertices: 7 },
      repairs: { spikes: 1 },
      areas: [100, 100],
      shared: { 'A|B': 10, 'A|out': 30, 'B|out': 30 },
      extent: [0, 0, 10, 20],
    });
  });
  await t.test('a spike into the neighbour', async (t) => {
    // A's spike (10,5)-(14,5)-(10,5) pokes into B; (10,5) is then a T-junction on B's side.
    const a: XY[] = [[0, 0], [10, 0], [10, 5], [14, 5], [10, 5], [10, 10], [0, 10]];
    const c = writeCase(t, 'spike-in.geojson', collection([feature('A', polygon(a)), feature('B', polygon(rect(10, 0, 20, 10)))]));
    await expectPartition(c, {
      counts: { faces: 2, edges: 3, nodes: 2, vertices: 7 },
      repairs: { spikes: 1, tJunctions: 1 },
      areas: [100, 100],
      shared: { 'A|B': 10, 'A|out': 30, 'B|out': 30 },
      extent: [0, 0, 20, 10],
    });
  });
});

// ---------------------------------------------------------------------------------------------
// Slivers: the style's base scale is 1:1,000, so the sliver width is 0.05 x 0.28 mm x 1,000 = 1.4 cm.

//  (0,10) +--------++-----------------+ (20,10)
//         |        ||        C        |        S: x 10..10.005, 5 mm wide, between A (10 along it),
//         |   A    |S      +----------+ 6.004  B (6) and C (4).
//         |        ||      | S2  (4 mm)  6     S2: x 15..20, y 6..6.004, between B (5 along it)
//         |        ||  B              |        and C (5 and its 4 mm end at x = 15).
//  (0,0)  +--------++-----------------+ (20,0)
function slivers(): Json {
  return collection([
    feature('A', polygon(rect(0, 0, 10, 10))),
    feature('S', polygon([[10, 0], [10.005, 0], [10.005, 6], [10.005, 10], [10, 10]])),
    feature('B', polygon([[10.005, 0], [20, 0], [20, 6], [15, 6], [10.005, 6]])),
    feature('S2', polygon([[15, 6], [20, 6], [20, 6.004], [15, 6.004]])),
    feature('C', polygon([[10.005, 6], [15, 6], [15, 6.004], [20, 6.004], [20, 10], [10.005, 10]])),
  ]);
}

test('slivers thinner than the sliver width are dissolved into the neighbour with the longest shared boundary, and counted', async (t) => {
  const c = writeCase(t, 'slivers.geojson', slivers());
  // S goes to A, S2 to C: three faces. A now reaches x = 10.005; C has S2's strip.
  // Vertices: A's four corners, (10,0) and (10,10) now on its outside boundary; (10.005, 0 / 6 /
  // 10); (20, 0 / 6 / 6.004 / 10); (15,6), where B meets C. (15,6.004) bounded only S2. Nodes:
  // the four points where three of A, B, C and the outside meet.
  const tg = await expectPartition(c, {
    counts: { faces: 3, edges: 6, nodes: 4, vertices: 12 },
    repairs: { slivers: 2 },
    areas: [10.005 * 10, 9.995 * 6, 9.995 * 4],
    shared: { 'A|B': 6, 'A|C': 4, 'B|C': 9.995, 'A|out': round(10.005 * 2 + 10), 'B|out': 15.995, 'C|out': 13.995 },
  });
  assert.deepEqual(tg.meta.attributes.map((a) => a.id), ['A', 'B', 'C'], 'the slivers\' features are gone, the others keep their attributes');
  const r = await generalize(c, 'again.tgap');
  assert.match(r.stdout, /^repairs: slivers 2$/m, 'the report counts them');
});

test('--refuse-slivers names every sliver in one run, and nothing is written', async (t) => {
  const c = writeCase(t, 'slivers.geojson', slivers());
  const r = await generalize(c, 'out.tgap', '--refuse-slivers');
  assert.equal(r.code, 1);
  assert.equal(r.stdout, '');
  // The thinnest first: S2 is 2 x 0.02 / 10.008 = 0.0039968 wide, S 2 x 0.05 / 20.01 = 0.0049975.
  assert.deepEqual(r.stderr.trimEnd().split('\n').slice(0, 4), [
    'ssc generalize: slivers.geojson: 2 problems; the input is refused:',
    '  sliver (2):',
    '    feature #3 (id "S2"), at (1015, 2006): has a part 0.00400 wide (2 x area / perimeter), under the sliver width 0.0140 (without --refuse-slivers it is dissolved into feature #4 (id "C"))',
    '    feature #1 (id "S"), at (1010, 2000): has a part 0.00500 wide (2 x area / perimeter), under the sliver width 0.0140 (without --refuse-slivers it is dissolved into feature #0 (id "A"))',
  ]);
  assert.deepEqual(readdirSync(c.dir).sort(), c.files, 'nothing written');
  // A sliver width under theirs: no slivers, the input is taken as it is.
  await expectPartition(c, {
    counts: { faces: 5, edges: 12, nodes: 8, vertices: 13 },
    areas: [100, 0.05, 9.995 * 6, 0.02, 9.995 * 4 - 0.02],
    shared: {
      'A|S': 10, 'B|S': 6, 'C|S': 4, 'B|C': 4.995, 'B|S2': 5, 'C|S2': 5.004,
      'A|out': 30, 'S|out': 0.01, 'B|out': 15.995, 'S2|out': 0.004, 'C|out': 13.991,
    },
  }, '--sliver-width', '0.003');
});

test('a sliver narrower than the precision is left out before the snapping, and counted', async (t) => {
  // S is 0.4 mm wide between A and B: snapped to the millimetre it has two distinct points.
  const doc = collection([
    feature('A', polygon(rect(0, 0, 10, 10))),
    feature('S', polygon(rect(10, 0, 10.0004, 10))),
    feature('B', polygon(rect(10.0004, 0, 20, 10))),
  ]);
  const c = writeCase(t, 'collapsed.geojson', doc);
  // S is 2 x 0.004 / 20.0008 = 0.0004 wide, under the precision: left out. B's 2 points at
  // x = 10.0004 are snapped to x = 10, where A's side is.
  await expectPartition(c, {
    counts: { faces: 2, edges: 3, nodes: 2, vertices: 6 },
    repairs: { snappedPoints: 2, slivers: 1 },
    areas: [100, 100],
    shared: { 'A|B': 10, 'A|out': 30, 'B|out': 30 },
  });
  // Without slivers (--sliver-width 0) it is refused as before.
  await expectRefusal(writeCase(t, 'collapsed.geojson', doc), { feature: [1, 'S'], message: /has a ring with fewer than 3 distinct points/, location: isAt(10, 0) }, '--sliver-width', '0');
});

test('a noisy sliver under a millimetre along a sloped boundary is dissolved, and the area kept', async (t) => {
  // A boundary 30 long at 40 degrees between A (left of it) and B; S runs along it, 0.4 to
  // 0.8 mm wide, with 26 points a side that wobble by up to 0.2 mm and are spaced unevenly,
  // as coordinate noise leaves them. Snapped to the millimetre its sides cross each other.
  const [dx, dy] = [Math.cos(0.7), Math.sin(0.7)], [nx, ny] = [-dy, dx];
  const along = (i: number, k: number, side: number): XY => {
    const t = i === 0 || i === 25 ? 1.2 * i : 1.2 * i + 0.3 * Math.sin(i * k);
    const off = side * (0.0003 + 0.0001 * Math.sin(i * 1.7) + (i === 0 || i === 25 ? 0 : 0.0001 * Math.cos(i * k)));
    return [10 + dx * t + nx * off, 10 + dy * t + ny * off];
  };
  const left = Array.from({ length: 26 }, (_, i) => along(i, 2.3, 1));
  const right = Array.from({ length: 26 }, (_, i) => along(i, 3.1, -1));
  const far = (p: XY, s: number): XY => [p[0] + s * 20 * nx, p[1] + s * 20 * ny];
  const A: XY[] = [...left, far(left[25]!, 1), far(left[0]!, 1)];
  const B: XY[] = [...[...right].reverse(), far(right[0]!, -1), far(right[25]!, -1)];
  const S: XY[] = [...left, ...[...right].reverse()];
  // Apart from them, X | T | Y: T is 5 mm wide, more than the precision, and goes to X (10
  // along each; the lower feature on a tie) once the partition is built.
  const doc = collection([
    feature('A', polygon(A)), feature('S', polygon(S)), feature('B', polygon(B), 'water'),
    feature('X', polygon(rect(100, 0, 110, 10))), feature('T', polygon(rect(110, 0, 110.005, 10))), feature('Y', polygon(rect(110.005, 0, 120, 10))),
  ]);
  // --refuse-slivers names both, each the way it would be dissolved, and writes nothing.
  const refused = writeCase(t, 'noisy.geojson', doc);
  const no = await generalize(refused, 'out.tgap', '--refuse-slivers');
  assert.equal(no.code, 1);
  const lines = no.stderr.trimEnd().split('\n');
  assert.deepEqual(lines.slice(0, 2), ['ssc generalize: noisy.geojson: 2 problems; the input is refused:', '  sliver (2):']);
  assert.match(lines[2]!, /^ {4}feature #4 \(id "T"\), at \(1110, 2000\): has a part 0\.00500 wide .* dissolved into feature #3 \(id "X"\)\)$/);
  assert.match(lines[3]!, /^ {4}feature #1 \(id "S"\), at \([\d., ]+\): has a part 0\.000[5-7]\d+ wide .*narrower than the precision 0\.001.* left out, and its neighbours meet\)$/);
  assert.deepEqual(readdirSync(refused.dir).sort(), refused.files, 'nothing written');
  const c = writeCase(t, 'noisy.geojson', doc);
  // Without slivers (--sliver-width 0) the snapping makes S cross itself: refused.
  const kept = await generalize(c, 'kept.tgap', '--sliver-width', '0');
  assert.match(kept.stderr, /feature #1 \(id "S"\), at \([\d., ]+\): is self-intersecting/);
  const r = await generalize(c, 'out.tgap');
  assert.equal(r.code, 0, r.stderr);
  const tg = await readTgap(r.out);
  assert.equal(tg.meta.repairs.slivers, 2);
  assert.deepEqual(tg.meta.attributes.map((a) => a.id), ['A', 'B', 'X', 'Y']);
  assert.ok(Math.abs(tg.faces[3]!.area2 / 2 - 100.05) < 1e-6 && Math.abs(tg.faces[4]!.area2 / 2 - 9.995 * 10) < 1e-6, 'X took T');
  // A and B now cover what A, S and B covered, up to the snapping: half a millimetre along
  // the 4 x 20 + 2 x 30 of outside boundary at most.
  const area = (r: XY[]): number => Math.abs(r.reduce((s, [x, y], i) => s + x * r[(i + 1) % r.length]![1] - r[(i + 1) % r.length]![0] * y, 0)) / 2;
  const input = area(A) + area(S) + area(B);
  const output = (tg.faces[1]!.area2 + tg.faces[2]!.area2) / 2;
  assert.ok(Math.abs(output - input) < 0.0005 * 140, `area ${output}, input ${input}`);
});

// ---------------------------------------------------------------------------------------------
// Refusals: exit code 1, the feature and the place named, nothing written.

test('overlapping faces whose sides cross are refused', async (t) => {
  // A (0,0)-(10,10) and B (5,5)-(15,15): the sides cross at (10,5) and (5,10).
  const c = writeCase(t, 'cross.geojson', collection([feature('a', polygon(rect(0, 0, 10, 10))), feature('b', polygon(rect(5, 5, 15, 15)))]));
  const crossing = (x: number, y: number): boolean => isAt(10, 5)(x, y) || isAt(5, 10)(x, y);
  const msg = await expectRefusal(c, { feature: null, message: /crosses feature #\d \(id "[ab]"\) \(overlap\)/, location: crossing });
  assert.match(msg, /feature #0 \(id "a"\)/);
  assert.match(msg, /feature #1 \(id "b"\)/);
  const err = await topologyError(c.input);
  assert.ok(err.location && crossing(...err.location));
});

test('a face inside another face without a hole for it is refused', async (t) => {
  const inner = rect(10, 10, 20, 20);
  const c = writeCase(t, 'nested.geojson', collection([feature('outer', polygon(rect(0, 0, 30, 30))), feature('inner', polygon(inner))]));
  await expectRefusal(c, {
    feature: [1, 'inner'],
    message: /lies inside the area of other features without a hole for it \(overlap\)/,
    location: (x, y) => onBoundary([inner], x, y),
  });
  const err = await topologyError(c.input);
  assert.deepEqual(err.feature, { index: 1, id: 'inner' });
});

test('a duplicated polygon is refused', async (t) => {
  await t.test('the same square as two features: both named', async (t) => {
    const b = rect(10, 0, 20, 10);
    // The copy starts at another corner and runs the other way: the same polygon all the same.
    const c = writeCase(t, 'dup-feature.geojson', collection([
      feature('a', polygon(rect(0, 0, 10, 10))),
      feature('b', polygon(b)),
      feature('copy of b', polygon([[20, 10], [20, 0], [10, 0], [10, 10]])),
    ]));
    const msg = await expectRefusal(c, {
      feature: [2, 'copy of b'],
      message: /is an exact duplicate of feature #1 \(id "b"\) \(--drop-duplicates drops the later one\)$/,
      location: isAt(20, 10),
    });
    assert.doesNotMatch(msg, /feature #0/);
    // With --drop-duplicates the copy is dropped and counted: a and b are left.
    const tg = await expectPartition(c, {
      counts: { faces: 2, edges: 3, nodes: 2, vertices: 6 },
      areas: [100, 100],
      shared: { 'a|b': 10, 'a|out': 30, 'b|out': 30 },
    }, '--drop-duplicates');
    assert.deepEqual(tg.meta.attributes.map((p) => p.id), ['a', 'b']);
    const r = await generalize(c, 'again.tgap', '--drop-duplicates');
    assert.match(r.stdout, /^dropped duplicate polygons: 1$/m);
  });
  await t.test('the same part twice in one MultiPolygon', async (t) => {
    const part = [ring(rect(10, 0, 20, 10))];
    const c = writeCase(t, 'dup-part.geojson', collection([
      feature('a', polygon(rect(0, 0, 10, 10))),
      feature('b', { type: 'MultiPolygon', coordinates: [part, part] }),
    ]));
    await expectRefusal(c, {
      feature: [1, 'b'],
      message: /has a boundary segment twice in the same direction \(a repeated ring or part\)/,
      location: (x, y) => onBoundary([rect(10, 0, 20, 10)], x, y),
    });
  });
});

test('a gap inside the domain is refused, and taken as an enclave with --allow-holes', async (t) => {
  await t.test('a hole that no feature fills', async (t) => {
    const hole = rect(10, 10, 20, 20);
    const doc = collection([feature('frame', polygon(rect(0, 0, 30, 30), [...hole].reverse()))]);
    const c = writeCase(t, 'hole.geojson', doc);
    await expectRefusal(c, {
      feature: [0, 'frame'],
      message: /borders a gap inside the domain \(an area no feature covers, 100\.0 square units, bounding box 1010, 2010, 1020, 2020\).*--allow-holes/,
      location: (x, y) => onBoundary([hole], x, y),
    });
    const exp: Expected = {
      counts: { faces: 1, edges: 2, nodes: 2, vertices: 8 },
      areas: [800],
      shared: { 'frame|out': 120 + 40 },
    };
    const tg = await expectPartition(c, exp, '--allow-holes');
    assert.equal(tg.meta.holes.length, 1);
    assert.equal(tg.meta.holes[0]!.area, 100);
    assert.ok(onBoundary([hole], tg.meta.holes[0]!.x, tg.meta.holes[0]!.y), 'the hole is named by a point on it');
    assert.equal(tg.meta.options.allowHoles, true);
    // The same through the style.
    const c2 = writeCase(t, 'hole.geojson', doc, { ...STYLE, allowHoles: true });
    const tg2 = await expectPartition(c2, exp);
    assert.equal(tg2.meta.holes.length, 1);
  });
  await t.test('a gap between four features', async (t) => {
    //  +-----------+ (30,30)
    //  |     B     |
    //  +---+---+---+ (30,20)      The middle square (10,10)-(20,20) is in no feature.
    //  | C |   | D |
    //  +---+---+---+ (30,10)
    //  |     A     |
    //  +-----------+
    const gap = rect(10, 10, 20, 20);
    const c = writeCase(t, 'gap.geojson', collection([
      feature('A', polygon(rect(0, 0, 30, 10))),
      feature('B', polygon(rect(0, 20, 30, 30))),
      feature('C', polygon(rect(0, 10, 10, 20)), 'water'),
      feature('D', polygon(rect(20, 10, 30, 20)), 'water'),
    ]));
    const msg = await expectRefusal(c, {
      feature: null,
      message: /borders a gap inside the domain \(an area no feature covers, 100\.0 square units, bounding box 1010, 2010, 1020, 2020\)/,
      location: (x, y) => onBoundary([gap], x, y),
    });
    assert.match(msg, /feature #(0 \(id "A"\)|1 \(id "B"\)|2 \(id "C"\)|3 \(id "D"\))/, 'names a feature along the gap');
    // With --allow-holes: C's and D's corners are T-junctions on A's top and B's bottom side.
    // Nodes: every corner of the gap and (0,10), (30,10), (0,20), (30,20); edges: A and B
    // have 4 each (outside, C, gap, D), C and D 2 each (outside, gap).
    const tg = await expectPartition(c, {
      counts: { faces: 4, edges: 12, nodes: 8, vertices: 12 },
      repairs: { tJunctions: 4 },
      areas: [300, 300, 100, 100],
      shared: { 'A|C': 10, 'A|D': 10, 'B|C': 10, 'B|D': 10, 'A|out': 50 + 10, 'B|out': 50 + 10, 'C|out': 10 + 10, 'D|out': 10 + 10 },
    }, '--allow-holes');
    assert.equal(tg.meta.holes.length, 1);
    assert.equal(tg.meta.holes[0]!.area, 100);
    assert.ok(onBoundary([gap], tg.meta.holes[0]!.x, tg.meta.holes[0]!.y));
  });
});

test('a self-intersecting ring (bow-tie) is refused', async (t) => {
  // (0,0)-(30,30) crosses (30,20)-(0,5) at (10,10); the two loops (100 and 25 square units)
  // do not cancel out. Feature #0 is a good square elsewhere.
  const bow: XY[] = [[0, 0], [30, 30], [30, 20], [0, 5]];
  const c = writeCase(t, 'bow.geojson', collection([feature('square', polygon(rect(40, 0, 50, 10))), feature('bow', polygon(bow))]));
  await expectRefusal(c, { feature: [1, 'bow'], message: /is self-intersecting: its outer ring crosses itself$/, location: isAt(10, 10) });
});

test('a bow-tie beside a neighbour is a self-intersection, not an overlap with the neighbour', async (t) => {
  // B = (10,0) (30,14) (30,-4) (10,10) crosses itself at (10 + 50/7, 5): its small loop along A's
  // side runs the way A's does, once the larger loop sets the ring's direction.
  const c = writeCase(t, 'bow-beside.geojson', collection([
    feature('A', polygon(rect(0, 0, 10, 10))),
    feature('B', polygon([[10, 0], [30, 14], [30, -4], [10, 10]])),
  ]));
  const msg = await expectRefusal(c, { feature: [1, 'B'], message: /is self-intersecting: its outer ring crosses itself$/, location: (x, y) => Math.abs(x - OX - (10 + 50 / 7)) < 1e-3 && y === OY + 5 });
  assert.doesNotMatch(msg, /overlap|feature #0/);
});

test('a coordinate far out of range is named as such, not as an overlap', async (t) => {
  const pts: Json[] = [at(10, 0), [1e300, OY], at(20, 10), at(10, 10), at(10, 0)];
  const c = writeCase(t, 'far.geojson', collection([
    feature('ok', polygon(rect(0, 0, 10, 10))),
    feature('far', { type: 'Polygon', coordinates: [pts] }),
  ]));
  const msg = await expectRefusal(c, { feature: [1, 'far'], message: /has a coordinate out of range: \[1e\+300, 2000\]/, location: isAt(10, 0) });
  assert.doesNotMatch(msg, /overlap/);
});

test('a class property present but null is named as null', async (t) => {
  const doc = collection([feature('f0', polygon(rect(0, 0, 10, 10))), feature('f1', polygon(rect(10, 0, 20, 10)))]);
  (((doc as { features: Json[] }).features[1] as { properties: Record<string, Json> }).properties).cls = null;
  const c = writeCase(t, 'null-class.geojson', doc);
  await expectRefusal(c, { feature: [1, 'f1'], message: /has the class property "cls" set to null$/, location: isAt(10, 0) });
});

test('a .gz file that is not gzip is named a broken gzip, not broken JSON', async (t) => {
  const good = JSON.stringify(collection([feature('f0', polygon(rect(0, 0, 10, 10)))]));
  const expectBrokenGzip = async (c: Case, reason: RegExp): Promise<void> => {
    const r = await generalize(c, 'out.tgap');
    assert.equal(r.code, 1);
    assert.equal(r.stderr, `ssc generalize: ${c.input}: broken gzip: ${r.stderr.split('broken gzip: ')[1]}`);
    assert.match(r.stderr, reason);
    assert.doesNotMatch(r.stderr, /JSON/);
    assert.deepEqual(readdirSync(c.dir).sort(), c.files, 'nothing written');
  };
  await t.test('plain JSON named .gz', async (t) => {
    await expectBrokenGzip(writeCase(t, 'plain.geojson.gz', good), /the file is named \.gz but does not start with the gzip signature \(1f 8b\)\n$/);
  });
  await t.test('a gzip stream cut short', async (t) => {
    const c = writeCase(t, 'cut.geojson.gz', '');
    writeFileSync(c.input, gzipSync(good).subarray(0, 20));
    await expectBrokenGzip(c, /broken gzip: unexpected end of file\n$/);
  });
});

test('coordinates that are not finite numbers are refused', async (t) => {
  // Feature #1's ring is (10,0), (20,0), (20,10), (10,10); one value is replaced by `bad`.
  const cases: { name: string; bad: string; pos: number; axis: 0 | 1; shown: string; near: XY }[] = [
    { name: 'NaN', bad: 'NaN', pos: 2, axis: 0, shown: '[NaN, 2010]', near: [20, 0] },
    { name: 'Infinity', bad: '-Infinity', pos: 2, axis: 1, shown: '[1020, -Infinity]', near: [20, 0] },
    { name: 'a number too large (1e999)', bad: '1e999', pos: 2, axis: 0, shown: '[Infinity, 2010]', near: [20, 0] },
    // The first point of the ring: the place is the first good point after it.
    { name: 'a string', bad: '"1010"', pos: 0, axis: 0, shown: '["1010", 2000]', near: [20, 0] },
    { name: 'null', bad: 'null', pos: 3, axis: 1, shown: '[1010, null]', near: [20, 10] },
  ];
  for (const k of cases) {
    await t.test(k.name, async (t) => {
      const pts: XY[] = [...rect(10, 0, 20, 10), [10, 0] as XY].map(([x, y]) => at(x, y));
      const coords: Json[] = pts.map((p, i) => (i === k.pos ? p.map((v, j) => (j === k.axis ? '@BAD@' : v)) : p));
      const doc = collection([
        feature('ok', polygon(rect(0, 0, 10, 10))),
        feature('bad', { type: 'Polygon', coordinates: [coords] }),
      ]);
      const c = writeCase(t, 'coords.geojson', JSON.stringify(doc).replace('"@BAD@"', k.bad));
      const msg = await expectRefusal(c, { feature: [1, 'bad'], message: /has a coordinate that is not a finite number: /, location: isAt(...k.near) });
      assert.ok(msg.endsWith(`not a finite number: ${k.shown}`), msg);
    });
  }
});

test('geometry that is not a polygon is refused', async (t) => {
  const cases: { name: string; geometry: Json; id: string | null; message: RegExp; location: ((x: number, y: number) => boolean) | null }[] = [
    { name: 'Point', geometry: { type: 'Point', coordinates: at(5, 5) }, id: 'pt', message: /has geometry type "Point"; only Polygon and MultiPolygon are accepted/, location: isAt(5, 5) },
    { name: 'LineString', geometry: { type: 'LineString', coordinates: [at(0, 0), at(10, 10)] }, id: 'line', message: /has geometry type "LineString"/, location: isAt(0, 0) },
    // Nothing to place: the feature's index (it has no id) is all there is.
    { name: 'null geometry', geometry: null, id: null, message: /has no geometry \(polygon expected\)/, location: null },
  ];
  for (const k of cases) {
    await t.test(k.name, async (t) => {
      const c = writeCase(t, 'geom.geojson', collection([feature('ok', polygon(rect(0, 0, 10, 10))), feature(k.id, k.geometry)]));
      await expectRefusal(c, { feature: [1, k.id], message: k.message, location: k.location });
    });
  }
});

test('a class value the style does not define is refused', async (t) => {
  const c = writeCase(t, 'class.geojson', collection([
    feature('f0', polygon(rect(0, 0, 10, 10))),
    feature('f1', polygon(rect(10, 0, 20, 10)), 'forest'),
  ]));
  // The feature is named, and found on the map by its first point.
  await expectRefusal(c, { feature: [1, 'f1'], message: /has class "forest" \(property "cls"\), which the style style\.json does not define/, location: isAt(10, 0) });
});

// Two cells of 0.001 degrees near Otterlo (lon 5.85, lat 52.05).
const lonLat = (x0: number, y0: number, x1: number, y1: number): Json => ({
  type: 'Polygon',
  coordinates: [[[x0, y0], [x1, y0], [x1, y1], [x0, y1], [x0, y0]]],
});
const lonLatDoc = (crs: string | null): Json => ({
  type: 'FeatureCollection',
  ...(crs ? { crs: { type: 'name', properties: { name: crs } } } : {}),
  features: [
    { type: 'Feature', properties: { id: 'A', cls: 'field' }, geometry: lonLat(5.85, 52.05, 5.851, 52.051) },
    { type: 'Feature', properties: { id: 'B', cls: 'field' }, geometry: lonLat(5.851, 52.05, 5.852, 52.051) },
  ],
});

test('longitude/latitude declared as a projected CRS is refused', async (t) => {
  const c = writeCase(t, 'degrees.geojson', lonLatDoc('urn:ogc:def:crs:EPSG::28992'));
  // A property of the whole file: the extent is the place, no feature is named.
  await expectRefusal(c, {
    feature: null,
    message: /declares EPSG:28992 \(projected, metres\) but its coordinates look like degrees \(5\.8500, 52\.0500, 5\.8520, 52\.0510\)/,
    location: null,
  });
});

test('longitude/latitude without a crs member is projected to its UTM zone', async (t) => {
  const c = writeCase(t, 'lonlat.geojson', lonLatDoc(null));
  const r = await generalize(c, 'out.tgap');
  assert.equal(r.code, 0, r.stderr);
  // Zone: floor((5.85 + 180) / 6) + 1 = 31, north.
  assert.match(r.stdout, /^input: lonlat\.geojson \(EPSG:32631, projected from OGC:CRS84\)$/m);
  assert.deepEqual(countsOf(r.stdout), { faces: 2, edges: 3, nodes: 2, vertices: 6 });
  const tg = await readTgap(r.out);
  assert.equal(tg.meta.crs, 'EPSG:32631');
  assert.equal(tg.meta.projectedFrom, 'OGC:CRS84');
  assert.match(tg.meta.proj4 ?? '', /\+proj=utm \+zone=31 /);
  // Metres on the WGS 84 ellipsoid at 52.0505 N: a cell is N cos(lat) dLon wide and M dLat
  // high (N, M the radii of curvature); UTM's scale there is within 0.1% of 1.
  const a = 6378137, e2 = 0.00669437999014, lat = (52.0505 * Math.PI) / 180, d = (0.001 * Math.PI) / 180;
  const w = 1 - e2 * Math.sin(lat) ** 2;
  const width = (a / Math.sqrt(w)) * Math.cos(lat) * d, height = (a * (1 - e2)) / w ** 1.5 * d;
  const near = (v: number, want: number, what: string): void => assert.ok(Math.abs(v / want - 1) < 0.003, `${what}: ${v}, expected about ${want}`);
  near(tg.faces[1]!.area2 / 2, width * height, 'area of A');
  near(tg.faces[2]!.area2 / 2, width * height, 'area of B');
  const shared = sharedLengths(tg);
  near(shared['A|B']!, height, 'shared side');
  near(shared['A|out']!, 2 * width + height, 'A along the outside');
  // East of the zone's central meridian (3 E), about 52 degrees north of the equator.
  const [x0, y0] = tg.meta.extent;
  near(x0 - 500000, 0.9996 * (a / Math.sqrt(w)) * Math.cos(lat) * ((2.85 * Math.PI) / 180), 'easting from the central meridian');
  assert.ok(y0 > 5.7e6 && y0 < 5.8e6, `northing ${y0}`);
  const { snappedPoints, ...rest } = tg.meta.repairs;
  assert.deepEqual(rest, { closedRings: 0, duplicatePoints: 0, reorientedRings: 0, tJunctions: 0, mergedPoints: 0, spikes: 0, slivers: 0 });
  assert.ok(snappedPoints !== undefined && snappedPoints <= 8, 'at most the 8 ring points were snapped to the millimetre grid');
});

test('TopoJSON gives the same topology as the equivalent GeoJSON', async (t) => {
  // The four squares around (10,10) (A bottom left, B top right, C bottom right, D top left),
  // as arcs: 0-3 the spokes from the centre down, right, up, left; 4-7 the outer sides of A,
  // C, B, D counterclockwise.
  const arcs: XY[][] = [
    [[10, 10], [10, 0]], [[10, 10], [20, 10]], [[10, 10], [10, 20]], [[10, 10], [0, 10]],
    [[0, 10], [0, 0], [10, 0]], [[10, 0], [20, 0], [20, 10]], [[20, 10], [20, 20], [10, 20]], [[10, 20], [0, 20], [0, 10]],
  ];
  const cell = (id: string, rings: number[], cls = 'field'): Json => ({ type: 'Polygon', arcs: [rings], properties: { id, cls } });
  const topojson: Json = {
    type: 'Topology',
    crs: { type: 'name', properties: { name: CRS } },
    arcs: arcs.map((a) => a.map(([x, y]) => at(x, y))),
    objects: {
      cells: {
        type: 'GeometryCollection',
        geometries: [cell('A', [4, ~0, 3]), cell('B', [6, ~2, 1]), cell('C', [5, ~1, 0], 'water'), cell('D', [7, ~3, 2], 'water')],
      },
    },
  };
  const geojson = collection([
    feature('A', polygon(rect(0, 0, 10, 10))),
    feature('B', polygon(rect(10, 10, 20, 20))),
    feature('C', polygon(rect(10, 0, 20, 10)), 'water'),
    feature('D', polygon(rect(0, 10, 10, 20)), 'water'),
  ]);
  const exp: Expected = {
    counts: { faces: 4, edges: 8, nodes: 5, vertices: 9 },
    areas: [100, 100, 100, 100],
    shared: { 'A|C': 10, 'A|D': 10, 'B|C': 10, 'B|D': 10, 'A|out': 20, 'B|out': 20, 'C|out': 20, 'D|out': 20 },
  };
  const fromTopo = await expectPartition(writeCase(t, 'cells.topojson', topojson), exp);
  const fromGeo = await expectPartition(writeCase(t, 'cells.geojson', geojson), exp);
  assert.deepEqual(fromTopo.meta.attributes, fromGeo.meta.attributes, 'the same features in the same order');
});
