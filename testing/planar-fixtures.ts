// Small planar partitions drawn by hand, for unit tests of the topology and tGAP steps. Faces
// are given as rings of local coordinates; face f (1, 2, ...) is the f-th face given, 0 the
// outside. Tests work out what they expect from the drawing, not from the code under test.
import assert from 'node:assert/strict';
import type { InputFeature } from '../preprocess/io/read-input.js';
import type { ClassStyle, Style } from '../preprocess/style.js';
import { lineRules, type LineStyleJson } from '../format/line-style.js';
import { TGAP_VERSION } from '../format/tgap.js';
import type { Tgap } from '../format/tgap-model.js';
import { generalize } from '../preprocess/tgap/generalize.js';
import { PlanarState } from '../preprocess/tgap/planar-state.js';
import { buildTopology, type Topology } from '../preprocess/topology/build-topology.js';

export type XY = [number, number];

export interface FixtureFace {
  cls: string;
  /** Outer ring first, then holes; open (no closing point), either orientation. */
  rings: XY[][];
}

/** Counterclockwise rectangle, open. */
export const rect = (x0: number, y0: number, x1: number, y1: number): XY[] => [[x0, y0], [x1, y0], [x1, y1], [x0, y1]];

/**
 * Three faces in [0,10] x [0,4] (drawn in preprocess/tgap/merge.test.ts): X = [0,6] x [0,4]
 * (face 1, class x), S = [6,7] x [0,1] (face 2, class s) and Y, the L-shaped rest (face 3,
 * class y).
 */
export const SMALL_BETWEEN_TWO: FixtureFace[] = [
  { cls: 'x', rings: [rect(0, 0, 6, 4)] },
  { cls: 's', rings: [rect(6, 0, 7, 1)] },
  { cls: 'y', rings: [[[6, 1], [7, 1], [7, 0], [10, 0], [10, 4], [6, 4]]] },
];

/**
 * A T of three roads among fields (drawn in preprocess/lines/collapse-lines.test.ts): road A =
 * [-50,0] x [0,6], road B = [0,50] x [0,6], road C = [-3,3] x [-50,0] (faces 1-3, class road),
 * fields above and on either side of C (faces 4-6, class field).
 */
export const ROAD_T: FixtureFace[] = [
  { cls: 'road', rings: [rect(-50, 0, 0, 6)] },
  { cls: 'road', rings: [rect(0, 0, 50, 6)] },
  { cls: 'road', rings: [[[-3, -50], [3, -50], [3, 0], [0, 0], [-3, 0]]] },
  { cls: 'field', rings: [rect(-50, 6, 50, 30)] },
  { cls: 'field', rings: [[[-50, -50], [-3, -50], [-3, 0], [-50, 0]]] },
  { cls: 'field', rings: [[[3, -50], [50, -50], [50, 0], [3, 0]]] },
];

export function topologyOf(faces: FixtureFace[]): Topology {
  const features: InputFeature[] = faces.map((f, index) => ({
    ref: { index, id: null },
    properties: { cls: f.cls },
    polygons: [f.rings.map((r) => Float64Array.from(r.flat()))],
  }));
  return buildTopology(features, { precision: 0.001 });
}

/** Face f's class as its index in `classes`. */
export function classIndexOf(faces: FixtureFace[], classes: string[]): (f: number) => number {
  return (f) => {
    const i = classes.indexOf(faces[f - 1]?.cls ?? '');
    if (i < 0) throw new Error(`face ${f}: class not in ${classes.join(', ')}`);
    return i;
  };
}

/** The faces as a PlanarState, classes numbered in the order of `classes`. */
export function planarStateOf(faces: FixtureFace[], classes: string[]): PlanarState {
  return new PlanarState(topologyOf(faces), classIndexOf(faces, classes));
}

/** The id of the vertex at (x, y) exactly. */
export function vertexAt(st: { xs: Float64Array; ys: Float64Array; size: number }, x: number, y: number): number {
  for (let v = 0; v < st.size; v++) if (st.xs[v] === x && st.ys[v] === y) return v;
  throw new Error(`no vertex at ${x}, ${y}`);
}

/** The alive edges with faces f and g on their two sides. */
export function edgesBetween(st: PlanarState, f: number, g: number): number[] {
  const out: number[] = [];
  for (let e = 0; e < st.edges.length; e++) {
    if (!st.edgeAlive[e]) continue;
    const [l, r] = st.sides(e);
    if ((l === f && r === g) || (l === g && r === f)) out.push(e);
  }
  return out;
}

/** The coordinates of an edge's vertices, in its order. */
export function edgePoints(st: PlanarState, e: number): XY[] {
  return [...st.edges[e]!.verts].map((v): XY => [st.xs[v]!, st.ys[v]!]);
}

/**
 * A style for the fixtures: classes with their weights and linearity (a linear class draws its
 * lines 0.5 mm wide unless `line` says otherwise); compatibility 1 within a class and
 * `compat[a][b]` (default 1) between classes a and b.
 */
export function fixtureStyle(classes: { key: string; weight?: number; linear?: boolean; line?: LineStyleJson; network?: string }[], compat: Record<string, Record<string, number>> = {}): Style {
  const cs: ClassStyle[] = classes.map((c) => {
    const out: ClassStyle = { key: c.key, label: c.key, color: '#808080', weight: c.weight ?? 1, linear: c.linear ?? false };
    if (c.line ?? c.linear) out.line = c.line ?? { width: 0.5 };
    if (c.network !== undefined) out.network = c.network;
    return out;
  });
  const matrix = cs.map((a) => Float64Array.from(cs.map((b) => (a.key === b.key ? 1 : compat[a.key]?.[b.key] ?? 1))));
  return { name: 'fixture', classProperty: 'cls', idProperty: null, baseScale: 1000, resolutionMm: 0.28, allowHoles: false, background: '#ffffff', classes: cs, lineRules: lineRules(cs), compat: matrix, attribution: '' };
}

/** Equal up to rounding (areas summed from float coordinates). */
export function assertNear(actual: number, expected: number, what: string): void {
  assert.ok(Math.abs(actual - expected) < 1e-9, `${what}: ${actual}, expected ${expected}`);
}

/** The fixture generalized (equal weights unless `style` says otherwise) into a whole tGAP. */
export function fixtureTgap(faces: FixtureFace[], classes: string[], style: Style = fixtureStyle(classes.map((key) => ({ key })))): Tgap {
  const topo = topologyOf(faces);
  let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  for (let v = 0; v < topo.vertexCount; v++) {
    x0 = Math.min(x0, topo.xs[v]!); x1 = Math.max(x1, topo.xs[v]!);
    y0 = Math.min(y0, topo.ys[v]!); y1 = Math.max(y1, topo.ys[v]!);
  }
  const g = generalize(topo, classIndexOf(faces, classes), style, { baseScale: style.baseScale, resolutionMm: style.resolutionMm });
  const steps = g.events.length === 0 ? 0 : g.events[g.events.length - 1]!.step;
  return {
    meta: {
      version: TGAP_VERSION, crs: 'EPSG:28992', extent: [x0, y0, x1, y1], baseScale: style.baseScale, resolutionMm: style.resolutionMm,
      baseFaces: topo.faceCount - 1, steps, facesAlive: g.facesAlive, holes: [], repairs: {}, source: 'fixture', style: {}, attributes: [], options: {},
    },
    xs: g.xs, ys: g.ys, faces: g.faces, edges: g.edges, events: g.events,
  };
}
