// A face's area as triangles, from the edges around it: the edges are joined into rings
// (split where the face touches itself), holes are put in the outer ring that holds them, and
// earcut triangulates. Should earcut's triangles not add up to the face's area (a degenerate
// configuration), a constrained Delaunay triangulation of the boundary is used instead.
import earcut from 'earcut';
import { triangulateRegion } from '../geom/cdt.js';
import { LocalVertices } from '../geom/local-vertices.js';
import { orient } from '../geom/predicates.js';
import { ringArea2 } from '../geom/ring.js';

export interface FaceEdge {
  verts: ArrayLike<number>;
  /** True when the face lies on the edge's left going from its first to its last vertex. */
  forward: boolean;
}

export interface TriangulateStats {
  earcut: number;
  fallback: number;
  failed: number;
}

/** Counterclockwise triangles (3 vertex ids each), appended to `out`; returns how many. */
export function triangulateFace(edges: FaceEdge[], xs: Float64Array, ys: Float64Array, out: number[], stats: TriangulateStats): number {
  if (edges.length === 0) return 0;
  const rings = assembleRings(edges, xs, ys);
  let expected2 = 0;
  for (const r of rings) expected2 += ringArea2(r, xs, ys);
  const before = out.length;
  const got2 = earcutRings(rings, xs, ys, out);
  if (Math.abs(got2 - expected2) <= 1e-9 * Math.abs(expected2) + 1e-12) {
    stats.earcut++;
    return (out.length - before) / 3;
  }
  out.length = before;
  if (cdtEdges(edges, xs, ys, out)) {
    stats.fallback++;
    return (out.length - before) / 3;
  }
  stats.failed++;
  throw new Error(`cannot triangulate a face of ${edges.length} edges (area ${expected2 / 2})`);
}

/** Closed rings of vertex ids (last != first), each simple, outer counterclockwise, holes clockwise. */
export function assembleRings(edges: FaceEdge[], xs: Float64Array, ys: Float64Array): number[][] {
  const chains = edges.map((e) => (e.forward ? Array.from(e.verts) : Array.from(e.verts).reverse()));
  const starting = new Map<number, number[]>();
  chains.forEach((c, i) => {
    let l = starting.get(c[0]!);
    if (!l) starting.set(c[0]!, (l = []));
    l.push(i);
  });
  const used = new Uint8Array(chains.length);
  const walks: number[][] = [];
  for (let i0 = 0; i0 < chains.length; i0++) {
    if (used[i0]) continue;
    const walk: number[] = [];
    let i = i0;
    for (let guard = 0; guard <= chains.length; guard++) {
      used[i] = 1;
      const c = chains[i]!;
      for (let k = 0; k < c.length - 1; k++) walk.push(c[k]!);
      const v = c[c.length - 1]!;
      const cands = (starting.get(v) ?? []).filter((j) => !used[j] || j === i0);
      if (cands.length === 0) break;
      // The face's next boundary piece is the first one clockwise from the way we came in.
      const prev = c[c.length - 2]!;
      const back = Math.atan2(ys[prev]! - ys[v]!, xs[prev]! - xs[v]!);
      let best = cands[0]!, bestTurn = Infinity;
      if (cands.length > 1) {
        for (const j of cands) {
          const n = chains[j]![1]!;
          let turn = back - Math.atan2(ys[n]! - ys[v]!, xs[n]! - xs[v]!);
          while (turn <= 0) turn += 2 * Math.PI;
          if (turn < bestTurn || (turn === bestTurn && j < best)) {
            bestTurn = turn;
            best = j;
          }
        }
      }
      if (best === i0) break;
      i = best;
    }
    walks.push(walk);
  }
  // A walk that passes a vertex twice is two rings touching there.
  const rings: number[][] = [];
  for (const w of walks) {
    const stack: number[] = [];
    const at = new Map<number, number>();
    for (const v of w) {
      const k = at.get(v);
      if (k !== undefined) {
        const loop = stack.splice(k + 1);
        for (const u of loop) at.delete(u);
        if (loop.length >= 2) rings.push([v, ...loop]);
        continue;
      }
      at.set(v, stack.length);
      stack.push(v);
    }
    if (stack.length >= 3) rings.push(stack);
  }
  return rings.filter((r) => r.length >= 3 && ringArea2(r, xs, ys) !== 0);
}

/** Triangulates rings with earcut; returns twice the area of what it produced. */
function earcutRings(rings: number[][], xs: Float64Array, ys: Float64Array, out: number[]): number {
  const outers: { ring: number[]; area2: number; holes: number[][]; bbox: number[] }[] = [];
  const holes: number[][] = [];
  for (const r of rings) {
    const a2 = ringArea2(r, xs, ys);
    if (a2 > 0) outers.push({ ring: r, area2: a2, holes: [], bbox: bboxOf(r, xs, ys) });
    else holes.push(r);
  }
  if (outers.length === 0) return 0;
  for (const h of holes) {
    if (outers.length === 1) {
      outers[0]!.holes.push(h);
      continue;
    }
    // The smallest outer ring that holds a vertex of the hole that is not on it.
    let best: (typeof outers)[number] | null = null;
    for (const o of outers) {
      const onOuter = new Set(o.ring);
      const v = h.find((u) => !onOuter.has(u));
      if (v === undefined) continue;
      const [x0, y0, x1, y1] = o.bbox as [number, number, number, number];
      const x = xs[v]!, y = ys[v]!;
      if (x < x0 || x > x1 || y < y0 || y > y1) continue;
      if (pointInRing(o.ring, xs, ys, x, y) && (!best || o.area2 < best.area2)) best = o;
    }
    (best ?? outers[0]!).holes.push(h);
  }
  let total2 = 0;
  for (const o of outers) {
    const ids: number[] = [...o.ring];
    const holeIndex: number[] = [];
    for (const h of o.holes) {
      holeIndex.push(ids.length);
      ids.push(...h);
    }
    const x0 = o.bbox[0]!, y0 = o.bbox[1]!;
    const flat = new Float64Array(ids.length * 2);
    ids.forEach((v, i) => {
      flat[2 * i] = xs[v]! - x0;
      flat[2 * i + 1] = ys[v]! - y0;
    });
    const tri = earcut(flat, holeIndex, 2);
    for (let t = 0; t < tri.length; t += 3) {
      const a = ids[tri[t]!]!, b = ids[tri[t + 1]!]!, c = ids[tri[t + 2]!]!;
      const o2 = orient(xs[a]!, ys[a]!, xs[b]!, ys[b]!, xs[c]!, ys[c]!);
      if (o2 === 0) continue;
      const ax = xs[a]! - x0, ay = ys[a]! - y0;
      const area2 = Math.abs((xs[b]! - x0 - ax) * (ys[c]! - y0 - ay) - (xs[c]! - x0 - ax) * (ys[b]! - y0 - ay));
      total2 += area2;
      if (o2 > 0) out.push(a, b, c);
      else out.push(a, c, b);
    }
  }
  return total2;
}

function cdtEdges(edges: FaceEdge[], xs: Float64Array, ys: Float64Array, out: number[]): boolean {
  const lv = new LocalVertices();
  const segs: number[] = [];
  for (const e of edges) {
    const n = e.verts.length;
    for (let k = 0; k + 1 < n; k++) {
      const a = e.verts[k]!, b = e.verts[k + 1]!;
      if (e.forward) segs.push(lv.of(a), lv.of(b));
      else segs.push(lv.of(b), lv.of(a));
    }
  }
  const r = triangulateRegion(lv.coords(xs, ys), segs);
  if (!r) return false;
  for (const t of r.triangles) out.push(lv.ids[t]!);
  return true;
}

function bboxOf(r: number[], xs: Float64Array, ys: Float64Array): number[] {
  let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  for (const v of r) {
    x0 = Math.min(x0, xs[v]!); x1 = Math.max(x1, xs[v]!);
    y0 = Math.min(y0, ys[v]!); y1 = Math.max(y1, ys[v]!);
  }
  return [x0, y0, x1, y1];
}

function pointInRing(r: number[], xs: Float64Array, ys: Float64Array, x: number, y: number): boolean {
  let inside = false;
  for (let i = 0, j = r.length - 1; i < r.length; j = i++) {
    const xi = xs[r[i]!]!, yi = ys[r[i]!]!, xj = xs[r[j]!]!, yj = ys[r[j]!]!;
    if (yi > y !== yj > y && x < ((xj - xi) * (y - yi)) / (yj - yi) + xi) inside = !inside;
  }
  return inside;
}
