// A face's area as triangles from the edges around it: the edges joined into rings (split where
// the face touches itself), holes put in the outer ring that holds them, earcut. Shared by the
// build (preprocess/ssc/triangulate-face.ts, which falls back to a constrained Delaunay
// triangulation where earcut fails) and the floor chunk reader (floor-chunk.ts), whose writer
// runs this very code on the file's grid points to find the faces it must give as triangles.
import earcut from 'earcut';
import { orient2d } from 'robust-predicates';

export interface FaceEdge {
  verts: ArrayLike<number>;
  /** True when the face lies on the edge's left going from its first to its last vertex. */
  forward: boolean;
}

/** Twice the signed area of the closed ring through the given vertex ids (last id may repeat the first). */
export function ringArea2(ids: ArrayLike<number>, xs: ArrayLike<number>, ys: ArrayLike<number>): number {
  let n = ids.length;
  if (n > 1 && ids[0] === ids[n - 1]) n--;
  if (n < 3) return 0;
  const x0 = xs[ids[0]!]!, y0 = ys[ids[0]!]!;
  let s = 0;
  for (let i = 1; i < n - 1; i++) {
    const ax = xs[ids[i]!]! - x0, ay = ys[ids[i]!]! - y0;
    const bx = xs[ids[i + 1]!]! - x0, by = ys[ids[i + 1]!]! - y0;
    s += ax * by - bx * ay;
  }
  return s;
}


/**
 * Counterclockwise triangles (vertex ids) of the face bounded by `edges`, appended to `out`;
 * false, with `out` as it was, when earcut's triangles do not add up to the rings' area (a
 * degenerate configuration).
 */
export function earcutFace(edges: FaceEdge[], xs: ArrayLike<number>, ys: ArrayLike<number>, out: number[]): boolean {
  const rings = assembleRings(edges, xs, ys);
  let expected2 = 0;
  for (const r of rings) expected2 += ringArea2(r, xs, ys);
  const before = out.length;
  const got2 = earcutRings(rings, xs, ys, out);
  if (Math.abs(got2 - expected2) <= 1e-9 * Math.abs(expected2) + 1e-12) return true;
  out.length = before;
  return false;
}

/** Twice the area of the face bounded by `edges` (its rings', holes taken off). */
export function faceArea2(edges: FaceEdge[], xs: ArrayLike<number>, ys: ArrayLike<number>): number {
  let a2 = 0;
  for (const r of assembleRings(edges, xs, ys)) a2 += ringArea2(r, xs, ys);
  return a2;
}

/** Closed rings of vertex ids (last != first), each simple, outer counterclockwise, holes clockwise. */
export function assembleRings(edges: FaceEdge[], xs: ArrayLike<number>, ys: ArrayLike<number>): number[][] {
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

/** Triangulates rings with earcut into counterclockwise triangles (vertex ids appended to `out`); returns twice the area of what it produced. */
export function earcutRings(rings: number[][], xs: ArrayLike<number>, ys: ArrayLike<number>, out: number[]): number {
  const outers: { ring: number[]; area2: number; holes: number[][]; bbox: number[]; vertices?: Set<number> }[] = [];
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
    // The smallest outer ring that holds a vertex of the hole that is not on it. Only an outer
    // ring whose box holds the hole's can: a face of many rings tests few.
    const [hx0, hy0, hx1, hy1] = bboxOf(h, xs, ys) as [number, number, number, number];
    let best: (typeof outers)[number] | null = null;
    for (const o of outers) {
      const [x0, y0, x1, y1] = o.bbox as [number, number, number, number];
      if (hx0 < x0 || hx1 > x1 || hy0 < y0 || hy1 > y1) continue;
      const onOuter = (o.vertices ??= new Set(o.ring));
      const v = h.find((u) => !onOuter.has(u));
      if (v === undefined) continue;
      if (pointInRing(o.ring, xs, ys, xs[v]!, ys[v]!) && (!best || o.area2 < best.area2)) best = o;
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
      // robust-predicates: negative for counterclockwise.
      const o2 = -orient2d(xs[a]!, ys[a]!, xs[b]!, ys[b]!, xs[c]!, ys[c]!);
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

function bboxOf(r: number[], xs: ArrayLike<number>, ys: ArrayLike<number>): number[] {
  let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  for (const v of r) {
    x0 = Math.min(x0, xs[v]!); x1 = Math.max(x1, xs[v]!);
    y0 = Math.min(y0, ys[v]!); y1 = Math.max(y1, ys[v]!);
  }
  return [x0, y0, x1, y1];
}

function pointInRing(r: number[], xs: ArrayLike<number>, ys: ArrayLike<number>, x: number, y: number): boolean {
  let inside = false;
  for (let i = 0, j = r.length - 1; i < r.length; j = i++) {
    const xi = xs[r[i]!]!, yi = ys[r[i]!]!, xj = xs[r[j]!]!, yj = ys[r[j]!]!;
    if (yi > y !== yj > y && x < ((xj - xi) * (y - yi)) / (yj - yi) + xi) inside = !inside;
  }
  return inside;
}
