// Line simplification that never changes the topology: Visvalingam-Whyatt, removing one vertex
// at a time, and only when the triangle it takes away holds no other vertex (so no line can
// cross the new chord), the edge keeps enough points and no two edges collapse onto each other.
// Every removal is a triangle whose area passes from one face to the other; removals of one
// step whose triangles overlap are put in successive phases so the cube stays unambiguous.
import FlatQueue from 'flatqueue';
import RBush from 'rbush';
import { blocksRemoval, orient } from '../geom/predicates.js';
import { LAST_REMOVAL_PHASE } from '../../format/tgap-model.js';
import type { PlanarState } from './planar-state.js';

interface Tri {
  minX: number;
  minY: number;
  maxX: number;
  maxY: number;
  c: Float64Array; // ax, ay, bx, by, cx, cy, counterclockwise
  phase: number;
}

/** The removal triangles of the current step, to give overlapping ones distinct phases. */
export class StepTriangles {
  private tree = new RBush<Tri>(9);
  private n = 0;

  clear(): void {
    if (this.n) this.tree.clear();
    this.n = 0;
  }

  /** The phase a new removal triangle must take (> every overlapping earlier one); above LAST_REMOVAL_PHASE none is left. */
  phaseFor(c: Float64Array): number {
    if (this.n === 0) return 1;
    let phase = 1;
    const minX = Math.min(c[0]!, c[2]!, c[4]!), maxX = Math.max(c[0]!, c[2]!, c[4]!);
    const minY = Math.min(c[1]!, c[3]!, c[5]!), maxY = Math.max(c[1]!, c[3]!, c[5]!);
    for (const t of this.tree.search({ minX, minY, maxX, maxY })) {
      if (t.phase >= phase && interiorsOverlap(t.c, c)) phase = t.phase + 1;
    }
    return Math.min(phase, LAST_REMOVAL_PHASE + 1);
  }

  add(c: Float64Array, phase: number): void {
    const minX = Math.min(c[0]!, c[2]!, c[4]!), maxX = Math.max(c[0]!, c[2]!, c[4]!);
    const minY = Math.min(c[1]!, c[3]!, c[5]!), maxY = Math.max(c[1]!, c[3]!, c[5]!);
    this.tree.insert({ minX, minY, maxX, maxY, c, phase });
    this.n++;
  }
}

/** Whether the open interiors of two counterclockwise triangles meet (separating axis test). */
function interiorsOverlap(a: Float64Array, b: Float64Array): boolean {
  return !separates(a, b) && !separates(b, a);
}

function separates(a: Float64Array, b: Float64Array): boolean {
  for (let i = 0; i < 3; i++) {
    const j = (i + 1) % 3;
    const px = a[2 * i]!, py = a[2 * i + 1]!, qx = a[2 * j]!, qy = a[2 * j + 1]!;
    if (orient(px, py, qx, qy, b[0]!, b[1]!) <= 0 && orient(px, py, qx, qy, b[2]!, b[3]!) <= 0 && orient(px, py, qx, qy, b[4]!, b[5]!) <= 0) {
      return true;
    }
  }
  return false;
}

const queue = new FlatQueue<number>();

/**
 * Simplifies edge e to tolerance `tol` (ground units). Returns the id of the edge's current
 * version: e itself when nothing could be removed.
 */
export function simplifyEdge(st: PlanarState, e: number, tol: number, tris: StepTriangles): number {
  const edge = st.edges[e]!;
  const verts = edge.verts;
  const n = verts.length;
  st.edgeTol[e] = tol;
  const ring = edge.start === edge.end;
  if (n <= 2 || (ring && n <= 4)) return e;
  const xs = st.xs, ys = st.ys;
  const threshold = (tol * tol) / 2;
  const prev = new Int32Array(n), next = new Int32Array(n);
  for (let i = 0; i < n; i++) {
    prev[i] = i - 1;
    next[i] = i + 1;
  }
  const area = new Float64Array(n);
  const triArea = (i: number): number => {
    const a = verts[prev[i]!]!, b = verts[i]!, c = verts[next[i]!]!;
    const ax = xs[a]!, ay = ys[a]!;
    return Math.abs((xs[b]! - ax) * (ys[c]! - ay) - (xs[c]! - ax) * (ys[b]! - ay)) / 2;
  };
  queue.clear();
  for (let i = 1; i < n - 1; i++) {
    area[i] = triArea(i);
    if (area[i]! < threshold) queue.push(i, area[i]!);
  }
  if (queue.length === 0) return e;
  let interior = n - 2;
  const removed: number[] = [];
  const phases: number[] = [];
  const [left, right] = st.sides(e);
  const c = new Float64Array(6);
  while (queue.length > 0) {
    const pr = queue.peekValue()!;
    const i = queue.pop()!;
    if (pr >= threshold) break;
    if (next[i] === -2 || pr !== area[i]) continue; // removed, or a stale entry
    if (ring ? interior <= 2 : false) break;
    const pi = prev[i]!, ni = next[i]!;
    const a = verts[pi]!, v = verts[i]!, b = verts[ni]!;
    if (!ring && pi === 0 && ni === n - 1 && parallelStraightEdge(st, e, edge.start, edge.end)) continue;
    const ax = xs[a]!, ay = ys[a]!, vx = xs[v]!, vy = ys[v]!, bx = xs[b]!, by = ys[b]!;
    const blocked = st.index.some(
      Math.min(ax, vx, bx), Math.min(ay, vy, by), Math.max(ax, vx, bx), Math.max(ay, vy, by),
      (q) => q !== a && q !== v && q !== b && blocksRemoval(ax, ay, vx, vy, bx, by, xs[q]!, ys[q]!),
    );
    if (blocked) continue;
    // Which side gains the triangle, and in which phase it can happen.
    const o = orient(ax, ay, bx, by, vx, vy);
    let phase = 1;
    if (o !== 0) {
      // Counterclockwise: v left of a->b means a, b, v.
      if (o > 0) c.set([ax, ay, bx, by, vx, vy]);
      else c.set([ax, ay, vx, vy, bx, by]);
      phase = tris.phaseFor(c);
      if (phase > LAST_REMOVAL_PHASE) continue;
      tris.add(Float64Array.from(c), phase);
      // v left of the chord: the triangle was the right face's and becomes the left face's.
      const t2 = Math.abs((vx - ax) * (by - ay) - (bx - ax) * (vy - ay));
      const gain = o > 0 ? left : right, lose = o > 0 ? right : left;
      if (gain > 0) {
        st.faceArea2[gain]! += t2;
        st.faceCost[gain]!++;
      }
      if (lose > 0) st.faceArea2[lose]! -= t2;
    }
    removed.push(v);
    phases.push(phase);
    st.kill(v);
    next[pi] = ni;
    prev[ni] = pi;
    next[i] = -2;
    interior--;
    for (const j of [pi, ni]) {
      if (j === 0 || j === n - 1) continue;
      area[j] = triArea(j);
      if (area[j] < threshold) queue.push(j, area[j]);
    }
  }
  if (removed.length === 0) return e;
  const kept: number[] = [];
  for (let i = 0; i !== n; i = next[i]!) {
    kept.push(verts[i]!);
    if (i === n - 1) break;
  }
  st.endEdge(e);
  const id = st.addEdge(edge.start, edge.end, left, right, Int32Array.from(kept), Int32Array.of(e), Int32Array.from(removed), Uint8Array.from(phases));
  st.edgeTol[id] = tol;
  return id;
}

/** Whether another edge already runs straight between the same two nodes (the face between would vanish). */
function parallelStraightEdge(st: PlanarState, e: number, a: number, b: number): boolean {
  const list = st.nodeEdges.get(a);
  if (!list) return false;
  for (const g of list) {
    if (g === e) continue;
    const edge = st.edges[g]!;
    if (edge.verts.length === 2 && ((edge.start === a && edge.end === b) || (edge.start === b && edge.end === a))) return true;
  }
  return false;
}
