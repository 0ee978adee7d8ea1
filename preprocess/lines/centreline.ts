// The centreline of an area (a road, a watercourse): the chordal axis of its constrained
// Delaunay triangulation. The boundary is first cut into pieces no longer than half the
// area's mean width, so that the triangles span the area from side to side. Then a triangle
// with one inner edge (an end) adds nothing, one with two (a sleeve) joins their midpoints,
// and one with three (a junction) joins them at its centroid, or, when it is obtuse, at the
// midpoint of its longest edge (the centroid of a flat triangle lies off the way through it).
// Between two parallel sides every inner edge's midpoint lies on the mid-axis exactly.
//
// Ports are points the line must reach: on the boundary (where the area meets another area of
// its network) or inside (where an earlier line ends). A port on the boundary gets a piece of
// boundary of its own, a gate, which counts as an open side with the port as its node: the
// axis runs on into it as if the area went on (it does, into the next area). A port beside a
// sleeve's piece (a way coming in from the side) is joined to its foot on that piece, which
// stays on the axis; a port inside is joined to the axis of the triangle that holds it. Then
// short spurs are pruned (prune-spurs.ts), the way into each port straightened
// (port-approach.ts) and the rest traced into polylines (axis-paths.ts).
import { triangulateRegion } from '../geom/cdt.js';
import { orient, segmentsIntersect } from '../geom/predicates.js';
import { pointSegmentDistance, projectOnSegment } from '../../format/point-segment.js';
import { AxisGraph } from './axis-graph.js';
import { simplifyPath, tracePaths } from './axis-paths.js';
import { straightenApproaches } from './port-approach.js';
import { pruneSpurs } from './prune-spurs.js';

/** An area by its boundary: directed segments with the area on their left (holes included). */
export interface Boundary {
  xs: ArrayLike<number>;
  ys: ArrayLike<number>;
  /** Vertex index pairs [a, b, a, b, ...]. */
  segs: ArrayLike<number>;
}

export interface Point {
  x: number;
  y: number;
}

export interface Centreline {
  /** Polylines as flat x, y pairs; a closed one repeats its first point last. */
  paths: Float64Array[];
  /** Per port: whether the line reaches it (false: it lies outside the area, farther than a bridge reaches). */
  reached: boolean[];
  /** Per port: reached by a bridge from the nearest boundary point (it lies just outside the area). */
  bridged: boolean[];
  /** The area's mean width: twice its area over its perimeter. */
  width: number;
  length: number;
}

/** Boundary pieces no longer than this share of the mean width. */
const SPACING = 0.5;
/** A port this close to the boundary (share of the mean width) lies on it. */
const ON_BOUNDARY = 1e-6;
/** How far along the line from a port its approach is straightened, as a share of the mean width. */
const REACH = 2;
/**
 * A port outside the area this close to it (share of the mean width) is reached by a bridge:
 * an earlier line's end that the area's simplified boundary has since passed (seen: up to 0.1 m).
 */
const BRIDGE = 0.25;
/** Simplification tolerance, as a share of the mean width. */
const STRAIGHT = 1e-3;

interface Tri {
  /** Nodes on the open sides: midpoints of inner edges, ports of gates. */
  nodes: number[];
  /** The piece of axis across the triangle, from node a to node b (-1: none). */
  a: number;
  b: number;
  /** Ports joined to the piece at their feet on it. */
  hang: number[];
  /** Where the nodes meet when they do not lie on one piece (-1: none). */
  centre: number;
}

/**
 * The centreline of the area bounded by `b`, reaching every port it can. `name` names the
 * area in errors (e.g. "face 12 (feature #3)").
 */
export function centreline(b: Boundary, ports: readonly Point[], name: string): Centreline {
  const { area, perimeter } = checkBoundary(b, name);
  const width = (2 * area) / perimeter;
  const pts = new Points(b);
  const g = new AxisGraph();
  const portNode = portNodes(g, ports);
  const placed = placePorts(b, ports, width * ON_BOUNDARY, width * BRIDGE);
  // A bridged port's gate is its foot on the boundary, joined on to the port.
  const gateNode = placed.map((pl, i) => {
    if (!pl?.bridge) return portNode[i]!;
    const s = b.segs[pl.seg]!, e = b.segs[pl.seg + 1]!;
    const foot = g.add(b.xs[s]! + pl.t * (b.xs[e]! - b.xs[s]!), b.ys[s]! + pl.t * (b.ys[e]! - b.ys[s]!));
    g.link(foot, portNode[i]!);
    return foot;
  });
  const { segs, gates } = densify(b, pts, placed, gateNode, width * SPACING);
  const cdt = triangulateRegion(pts.local(), segs);
  if (!cdt) throw new Error(`${name}: cannot be triangulated (its boundary crosses itself or does not close)`);
  const tri = cdt.triangles;
  const tris = axisPieces(tri, pts, gates, g);
  // Ports inside: joined to the axis of the triangle that holds them.
  ports.forEach((p, i) => {
    if (placed[i] || g.degree(portNode[i]!) > 0) return;
    const t = triangleAt(tri, pts, p);
    if (t >= 0) attach(g, tris[t]!, portNode[i]!);
  });
  linkPieces(g, tris);
  const reached = portNode.map((n) => g.degree(n) > 0);
  const bridged = placed.map((pl) => pl?.bridge === true);

  // The width at a point: twice its distance to the boundary, gates (where the area goes on) left out.
  const gateKeys = new Set(gates.keys());
  const closed: number[] = [];
  for (let i = 0; i < segs.length; i += 2) if (!gateKeys.has(segs[i]! * pts.size + segs[i + 1]!)) closed.push(segs[i]!, segs[i + 1]!);
  pruneSpurs(g, (n) => {
    let d = Infinity;
    for (let i = 0; i < closed.length; i += 2) {
      const s = closed[i]!, e = closed[i + 1]!;
      d = Math.min(d, pointSegmentDistance(g.xs[n]!, g.ys[n]!, pts.xs[s]!, pts.ys[s]!, pts.xs[e]!, pts.ys[e]!));
    }
    return 2 * d;
  });

  straightenApproaches(g, (a, c) => {
    const ax = g.xs[a]!, ay = g.ys[a]!, cx = g.xs[c]!, cy = g.ys[c]!;
    for (let i = 0; i < closed.length; i += 2) {
      const s = closed[i]!, e = closed[i + 1]!;
      const sx = pts.xs[s]!, sy = pts.ys[s]!, ex = pts.xs[e]!, ey = pts.ys[e]!;
      // A port on a boundary vertex touches the segments at it.
      if ((sx === ax && sy === ay) || (ex === ax && ey === ay)) continue;
      if (segmentsIntersect(ax, ay, cx, cy, sx, sy, ex, ey)) return false;
    }
    return true;
  }, width * REACH);

  const paths = tracePaths(g).map((p) => simplifyPath(g, p, width * STRAIGHT)).filter((p) => p.length >= 4);
  let length = 0;
  for (const p of paths) for (let i = 2; i < p.length; i += 2) length += Math.hypot(p[i]! - p[i - 2]!, p[i + 1]! - p[i - 1]!);
  return { paths, reached, bridged, width, length };
}
/** Refuses what has no inside: too few segments, bad numbers, pieces of no length, no area. */
function checkBoundary(b: Boundary, name: string): { area: number; perimeter: number } {
  const n = b.segs.length / 2;
  if (n < 3 || !Number.isInteger(n)) throw new Error(`${name}: a boundary needs at least 3 segments, got ${b.segs.length / 2}`);
  const x0 = b.xs[b.segs[0]!]!, y0 = b.ys[b.segs[0]!]!;
  let area2 = 0, perimeter = 0;
  for (let i = 0; i < b.segs.length; i += 2) {
    const s = b.segs[i]!, e = b.segs[i + 1]!;
    const ax = b.xs[s], ay = b.ys[s], bx = b.xs[e], by = b.ys[e];
    if (ax === undefined || ay === undefined || bx === undefined || by === undefined) throw new Error(`${name}: segment ${i / 2} names a vertex that does not exist`);
    if (![ax, ay, bx, by].every(Number.isFinite)) throw new Error(`${name}: segment ${i / 2} has a coordinate that is not a finite number`);
    const len = Math.hypot(bx - ax, by - ay);
    if (len === 0) throw new Error(`${name}: segment ${i / 2} has no length, at (${ax}, ${ay})`);
    perimeter += len;
    area2 += (ax - x0) * (by - y0) - (bx - x0) * (ay - y0);
  }
  if (!(area2 > 0)) throw new Error(`${name}: the boundary encloses no area (signed area ${area2 / 2}; the area must lie left of its segments)`);
  return { area: area2 / 2, perimeter };
}

/** The triangulation's points: the boundary's, then ports and boundary cuts (global coordinates). */
class Points {
  readonly xs: number[];
  readonly ys: number[];

  constructor(b: Boundary) {
    this.xs = Array.from(b.xs);
    this.ys = Array.from(b.ys);
  }

  add(x: number, y: number): number {
    this.xs.push(x);
    this.ys.push(y);
    return this.xs.length - 1;
  }

  get size(): number {
    return this.xs.length;
  }

  /** Coordinates near the origin, as the triangulator wants them. */
  local(): Float64Array {
    let x0 = Infinity, y0 = Infinity;
    for (let i = 0; i < this.xs.length; i++) {
      x0 = Math.min(x0, this.xs[i]!);
      y0 = Math.min(y0, this.ys[i]!);
    }
    const out = new Float64Array(this.xs.length * 2);
    for (let i = 0; i < this.xs.length; i++) {
      out[2 * i] = this.xs[i]! - x0;
      out[2 * i + 1] = this.ys[i]! - y0;
    }
    return out;
  }
}

/** A node per distinct port point (ports given twice share it). */
function portNodes(g: AxisGraph, ports: readonly Point[]): number[] {
  const seen = new Map<string, number>();
  return ports.map((p) => {
    const key = `${p.x},${p.y}`;
    let n = seen.get(key);
    if (n === undefined) seen.set(key, (n = g.add(p.x, p.y, true)));
    return n;
  });
}

/**
 * Where a port lies on the boundary: segment (index of its first vertex in `segs`) and position;
 * for a bridge, where its foot does.
 */
interface OnBoundary {
  seg: number;
  t: number;
  bridge: boolean;
}

/**
 * Per port, the boundary segment it lies on (null: it lies off the boundary, inside or too far
 * outside). A port outside within `bridge` of the boundary is reached from its foot.
 */
function placePorts(b: Boundary, ports: readonly Point[], tol: number, bridge: number): (OnBoundary | null)[] {
  return ports.map((p) => {
    let best = -1, bestD = Infinity;
    for (let i = 0; i < b.segs.length; i += 2) {
      const s = b.segs[i]!, e = b.segs[i + 1]!;
      const d = pointSegmentDistance(p.x, p.y, b.xs[s]!, b.ys[s]!, b.xs[e]!, b.ys[e]!);
      if (d < bestD) {
        bestD = d;
        best = i;
      }
    }
    const s = b.segs[best]!, e = b.segs[best + 1]!;
    if (bestD > tol) {
      if (bestD > bridge || insideBoundary(b, p)) return null;
      return { seg: best, t: projectOnSegment(p.x, p.y, b.xs[s]!, b.ys[s]!, b.xs[e]!, b.ys[e]!), bridge: true };
    }
    // On a vertex: at the start of a segment leaving it.
    for (const v of [s, e]) {
      if (Math.hypot(p.x - b.xs[v]!, p.y - b.ys[v]!) > tol) continue;
      for (let i = 0; i < b.segs.length; i += 2) if (b.segs[i] === v) return { seg: i, t: 0, bridge: false };
    }
    return { seg: best, t: projectOnSegment(p.x, p.y, b.xs[s]!, b.ys[s]!, b.xs[e]!, b.ys[e]!), bridge: false };
  });
}

/** Even-odd: whether p lies inside the area (p is not on the boundary). */
function insideBoundary(b: Boundary, p: Point): boolean {
  let inside = false;
  for (let i = 0; i < b.segs.length; i += 2) {
    const ax = b.xs[b.segs[i]!]!, ay = b.ys[b.segs[i]!]!, bx = b.xs[b.segs[i + 1]!]!, by = b.ys[b.segs[i + 1]!]!;
    if (ay > p.y !== by > p.y && p.x < ax + ((p.y - ay) * (bx - ax)) / (by - ay)) inside = !inside;
  }
  return inside;
}

/**
 * The boundary's segments cut into pieces no longer than `spacing`. A port on the boundary gets
 * a piece of its own around it (a gate: the area goes on there, into the next area of its
 * network), centred on it where there is room. Returns the segments and, by directed key
 * a * points + b, the port node of each gate.
 */
function densify(
  b: Boundary, pts: Points, placed: (OnBoundary | null)[], gateNode: number[], spacing: number,
): { segs: Int32Array; gates: Map<number, number> } {
  const bySeg = new Map<number, { t: number; node: number }[]>();
  placed.forEach((on, i) => {
    if (!on) return;
    let list = bySeg.get(on.seg);
    if (!list) bySeg.set(on.seg, (list = []));
    if (!list.some((c) => c.node === gateNode[i])) list.push({ t: on.t, node: gateNode[i]! });
  });
  const out: number[] = [];
  const gateList: [number, number, number][] = [];
  for (let i = 0; i < b.segs.length; i += 2) {
    const a = b.segs[i]!, c = b.segs[i + 1]!;
    const ax = pts.xs[a]!, ay = pts.ys[a]!, cx = pts.xs[c]!, cy = pts.ys[c]!;
    const len = Math.hypot(cx - ax, cy - ay);
    const at = (t: number): number => (t <= 0 ? a : t >= 1 ? c : pts.add(ax + (cx - ax) * t, ay + (cy - ay) * t));
    // Breakpoints along the segment: [t, point, port node of the piece that starts here or -1].
    const marks: { t: number; node: number }[] = [{ t: 0, node: -1 }];
    const ports = (bySeg.get(i) ?? []).sort((p, q) => p.t - q.t || p.node - q.node);
    const half = spacing / 2 / len;
    ports.forEach((p, k) => {
      const lo = Math.max(p.t - half, k > 0 ? (ports[k - 1]!.t + p.t) / 2 : 0, marks[marks.length - 1]!.t);
      const hi = Math.min(p.t + half, k + 1 < ports.length ? (p.t + ports[k + 1]!.t) / 2 : 1);
      if (lo > marks[marks.length - 1]!.t) marks.push({ t: lo, node: -1 });
      marks[marks.length - 1]!.node = p.node;
      marks.push({ t: hi, node: -1 });
    });
    if (marks[marks.length - 1]!.t < 1) marks.push({ t: 1, node: -1 });
    let prev = a;
    for (let k = 0; k + 1 < marks.length; k++) {
      const m = marks[k]!, t1 = marks[k + 1]!.t;
      const end = at(t1);
      if (m.node >= 0) {
        gateList.push([prev, end, m.node]);
        out.push(prev, end);
      } else {
        const n = Math.ceil(((t1 - m.t) * len) / spacing);
        let p = prev;
        for (let j = 1; j < n; j++) {
          const v = at(m.t + ((t1 - m.t) * j) / n);
          out.push(p, v);
          p = v;
        }
        out.push(p, end);
      }
      prev = end;
    }
  }
  const gates = new Map<number, number>();
  for (const [s, e, node] of gateList) gates.set(s * pts.size + e, node);
  return { segs: Int32Array.from(out), gates };
}

/**
 * Each triangle's piece of axis. Its open sides are inner edges (a node at the midpoint) and
 * gates (the port's node): one open side ends the axis, two are joined, three meet at a
 * centre; but a port beside two inner edges (a road coming in from the side) is joined to its
 * foot on the piece between them, which stays on the axis.
 */
function axisPieces(tri: Int32Array, pts: Points, gates: Map<number, number>, g: AxisGraph): Tri[] {
  const n = pts.size, nt = tri.length / 3;
  const directed = new Set<number>();
  for (let t = 0; t < nt; t++) for (let k = 0; k < 3; k++) directed.add(tri[3 * t + k]! * n + tri[3 * t + ((k + 1) % 3)]!);
  const mid = new Map<number, number>();
  const midNode = (a: number, c: number): number => {
    const key = Math.min(a, c) * n + Math.max(a, c);
    let m = mid.get(key);
    if (m === undefined) {
      m = g.add((pts.xs[a]! + pts.xs[c]!) / 2, (pts.ys[a]! + pts.ys[c]!) / 2);
      mid.set(key, m);
    }
    return m;
  };
  const out: Tri[] = [];
  for (let t = 0; t < nt; t++) {
    const v = [tri[3 * t]!, tri[3 * t + 1]!, tri[3 * t + 2]!];
    const nodes: number[] = [];
    const portAt: boolean[] = [];
    let longest = -1, longest2 = -1, sum2 = 0;
    for (let k = 0; k < 3; k++) {
      const a = v[k]!, c = v[(k + 1) % 3]!;
      const len2 = (pts.xs[c]! - pts.xs[a]!) ** 2 + (pts.ys[c]! - pts.ys[a]!) ** 2;
      sum2 += len2;
      const gate = gates.get(a * n + c);
      let node = -1;
      if (directed.has(c * n + a)) node = midNode(a, c);
      else if (gate !== undefined) node = gate;
      if (len2 > longest2) {
        longest2 = len2;
        longest = node >= 0 && gate === undefined ? node : -1;
      }
      if (node >= 0) {
        nodes.push(node);
        portAt.push(gate !== undefined && node === gate);
      }
    }
    const tr: Tri = { nodes, a: -1, b: -1, hang: [], centre: -1 };
    const ports = portAt.filter(Boolean).length;
    if (nodes.length === 2) {
      [tr.a, tr.b] = nodes as [number, number];
    } else if (nodes.length === 3 && ports === 1) {
      const k = portAt.indexOf(true);
      tr.a = nodes[(k + 1) % 3]!;
      tr.b = nodes[(k + 2) % 3]!;
      tr.hang.push(nodes[k]!);
    } else if (nodes.length === 3 || (nodes.length <= 1 && (nodes.length === 0 || portAt[0]))) {
      // Obtuse: the centroid lies off the way through; the longest (inner) edge's midpoint is on it.
      const obtuse = 2 * longest2 > sum2;
      tr.centre = obtuse && longest >= 0 ? longest : g.add((pts.xs[v[0]!]! + pts.xs[v[1]!]! + pts.xs[v[2]!]!) / 3, (pts.ys[v[0]!]! + pts.ys[v[1]!]! + pts.ys[v[2]!]!) / 3);
    }
    out.push(tr);
  }
  return out;
}

/** The triangle holding point p (its closed area), -1: none. */
function triangleAt(tri: Int32Array, pts: Points, p: Point): number {
  for (let t = 0; t < tri.length / 3; t++) {
    const a = tri[3 * t]!, b = tri[3 * t + 1]!, c = tri[3 * t + 2]!;
    const ax = pts.xs[a]!, ay = pts.ys[a]!, bx = pts.xs[b]!, by = pts.ys[b]!, cx = pts.xs[c]!, cy = pts.ys[c]!;
    if (orient(ax, ay, bx, by, p.x, p.y) >= 0 && orient(bx, by, cx, cy, p.x, p.y) >= 0 && orient(cx, cy, ax, ay, p.x, p.y) >= 0) return t;
  }
  return -1;
}

/** Joins a port inside triangle `tr` to its axis: at its foot on the piece, the centre, or the end. */
function attach(g: AxisGraph, tr: Tri, p: number): void {
  if (tr.a >= 0) tr.hang.push(p);
  else g.link(p, tr.centre >= 0 ? tr.centre : tr.nodes[0]!);
}

/**
 * Joins each triangle's nodes: a piece from a to b (through the feet of the ports hanging off
 * it, each joined to its foot), or every node to the centre.
 */
function linkPieces(g: AxisGraph, tris: Tri[]): void {
  for (const tr of tris) {
    if (tr.a >= 0) {
      const ax = g.xs[tr.a]!, ay = g.ys[tr.a]!, bx = g.xs[tr.b]!, by = g.ys[tr.b]!;
      const feet: { u: number; node: number }[] = [];
      for (const p of tr.hang) {
        const u = projectOnSegment(g.xs[p]!, g.ys[p]!, ax, ay, bx, by);
        if (u <= 0) g.link(p, tr.a);
        else if (u >= 1) g.link(p, tr.b);
        else {
          const x = ax + u * (bx - ax), y = ay + u * (by - ay);
          // A port on the piece itself is its own foot.
          const foot = x === g.xs[p] && y === g.ys[p] ? p : g.add(x, y);
          g.link(p, foot);
          feet.push({ u, node: foot });
        }
      }
      feet.sort((p, q) => p.u - q.u || p.node - q.node);
      const chain = [tr.a, ...feet.map((f) => f.node), tr.b];
      for (let i = 0; i + 1 < chain.length; i++) g.link(chain[i]!, chain[i + 1]!);
    } else if (tr.centre >= 0) {
      for (const m of tr.nodes) g.link(m, tr.centre);
    }
  }
}
