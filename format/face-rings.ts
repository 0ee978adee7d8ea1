// A face's area as triangles from the edges around it: the edges joined into rings (split where
// the face touches itself), holes put in the outer ring that holds them, earcut. Shared by the
// build (preprocess/ssc/triangulate-face.ts, which falls back to a constrained Delaunay
// triangulation where earcut fails), the floor chunk reader (floor-chunk.ts) and the chunk
// file's ring pieces (chunk-rings.ts), whose writers run this very code on the file's grid
// points to find what they must give as triangles.
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
  const { rings, areas } = faceRings(edges, xs, ys);
  let expected2 = 0;
  for (const a of areas) expected2 += a;
  const before = out.length;
  const got2 = earcutRings(rings, xs, ys, out, areas);
  if (Math.abs(got2 - expected2) <= 1e-9 * Math.abs(expected2) + 1e-12) return true;
  out.length = before;
  return false;
}

/** Twice the area of the face bounded by `edges` (its rings', holes taken off). */
export function faceArea2(edges: FaceEdge[], xs: ArrayLike<number>, ys: ArrayLike<number>): number {
  let a2 = 0;
  for (const a of faceRings(edges, xs, ys).areas) a2 += a;
  return a2;
}

/** Closed rings of vertex ids (last != first), each simple, outer counterclockwise, holes clockwise. */
export function assembleRings(edges: FaceEdge[], xs: ArrayLike<number>, ys: ArrayLike<number>): number[][] {
  return faceRings(edges, xs, ys).rings;
}

/** Vertex `k` of an edge, counted in the face's direction. */
const vertexAt = (e: FaceEdge, k: number): number => (e.forward ? e.verts[k]! : e.verts[e.verts.length - 1 - k]!);

/**
 * A face of at most this many edges finds the edge that goes on from a vertex by a scan, not a
 * map: most faces have a few, and the map cost more than the scan (the map reads the floor
 * chunks, whose speed the first map waits for).
 */
const SCAN_EDGES = 16;

/** assembleRings, with each ring's twice signed area (ringArea2), worked out once. */
function faceRings(edges: FaceEdge[], xs: ArrayLike<number>, ys: ArrayLike<number>): { rings: number[][]; areas: number[] } {
  const n = edges.length;
  const firstOf: number[] = [];
  for (const e of edges) firstOf.push(vertexAt(e, 0));
  let starting: Map<number, number[]> | null = null;
  if (n > SCAN_EDGES) {
    starting = new Map();
    for (let i = 0; i < n; i++) {
      let l = starting.get(firstOf[i]!);
      if (!l) starting.set(firstOf[i]!, (l = []));
      l.push(i);
    }
  }
  const used = new Uint8Array(n);
  const rings: number[][] = [], areas: number[] = [];
  const cands: number[] = [];
  for (let i0 = 0; i0 < n; i0++) {
    if (used[i0]) continue;
    const walk: number[] = [];
    let i = i0;
    for (let guard = 0; guard <= n; guard++) {
      used[i] = 1;
      const e = edges[i]!, len = e.verts.length;
      for (let k = 0; k < len - 1; k++) walk.push(vertexAt(e, k));
      const v = vertexAt(e, len - 1);
      cands.length = 0;
      if (starting) {
        for (const j of starting.get(v) ?? []) if (!used[j] || j === i0) cands.push(j);
      } else {
        for (let j = 0; j < n; j++) if (firstOf[j] === v && (!used[j] || j === i0)) cands.push(j);
      }
      if (cands.length === 0) break;
      // The face's next boundary piece is the first one clockwise from the way we came in.
      let best = cands[0]!;
      if (cands.length > 1) {
        const prev = vertexAt(e, len - 2);
        const back = Math.atan2(ys[prev]! - ys[v]!, xs[prev]! - xs[v]!);
        let bestTurn = Infinity;
        for (const j of cands) {
          const nx = vertexAt(edges[j]!, 1);
          let turn = back - Math.atan2(ys[nx]! - ys[v]!, xs[nx]! - xs[v]!);
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
    splitWalk(walk, xs, ys, rings, areas);
  }
  return { rings, areas };
}

/** Marks for `repeats`: a vertex is marked when `mark[v] === markGen` (no clearing between calls). */
let mark = new Uint32Array(0);
let markGen = 0;

/** Whether a vertex id occurs twice in `w`. */
function repeats(w: number[]): boolean {
  let top = 0;
  for (const v of w) if (v >= top) top = v + 1;
  if (top > mark.length) {
    mark = new Uint32Array(Math.max(top, 2 * mark.length));
    markGen = 0;
  }
  if (++markGen === 0xffffffff) {
    mark.fill(0);
    markGen = 1;
  }
  for (const v of w) {
    if (mark[v] === markGen) return true;
    mark[v] = markGen;
  }
  return false;
}

/** Keeps a ring of 3 vertices or more and some area, with that area. */
function keepRing(r: number[], xs: ArrayLike<number>, ys: ArrayLike<number>, rings: number[][], areas: number[]): void {
  if (r.length < 3) return;
  const a2 = ringArea2(r, xs, ys);
  if (a2 === 0) return;
  rings.push(r);
  areas.push(a2);
}

/** The rings of a walk: one that passes a vertex twice is two rings touching there. */
function splitWalk(w: number[], xs: ArrayLike<number>, ys: ArrayLike<number>, rings: number[][], areas: number[]): void {
  if (!repeats(w)) {
    keepRing(w, xs, ys, rings, areas);
    return;
  }
  const stack: number[] = [];
  const at = new Map<number, number>();
  for (const v of w) {
    const k = at.get(v);
    if (k !== undefined) {
      const loop = stack.splice(k + 1);
      for (const u of loop) at.delete(u);
      if (loop.length >= 2) keepRing([v, ...loop], xs, ys, rings, areas);
      continue;
    }
    at.set(v, stack.length);
    stack.push(v);
  }
  keepRing(stack, xs, ys, rings, areas);
}

/**
 * Triangulates rings with earcut into counterclockwise triangles (vertex ids appended to `out`);
 * returns twice the area of what it produced. `areas`: each ring's ringArea2, when known.
 */
export function earcutRings(rings: number[][], xs: ArrayLike<number>, ys: ArrayLike<number>, out: number[], areas?: ArrayLike<number>): number {
  // Most faces are one ring.
  if (rings.length === 1) return (areas ? areas[0]! : ringArea2(rings[0]!, xs, ys)) > 0 ? cutRings(rings[0]!, [], xs, ys, out) : 0;
  const outers: { ring: number[]; area2: number; holes: number[][]; bbox: number[]; vertices?: Set<number> }[] = [];
  const holes: number[][] = [];
  for (let r = 0; r < rings.length; r++) {
    const ring = rings[r]!;
    const a2 = areas ? areas[r]! : ringArea2(ring, xs, ys);
    if (a2 > 0) outers.push({ ring, area2: a2, holes: [], bbox: bboxOf(ring, xs, ys) });
    else holes.push(ring);
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
  for (const o of outers) total2 += cutRings(o.ring, o.holes, xs, ys, out);
  return total2;
}

/** earcut's triangles of one outer ring with its holes, counterclockwise (appended to `out`); twice their area. */
function cutRings(ring: number[], holes: number[][], xs: ArrayLike<number>, ys: ArrayLike<number>, out: number[]): number {
  let ids = ring;
  const holeIndex: number[] = [];
  if (holes.length > 0) {
    ids = ring.slice();
    for (const h of holes) {
      holeIndex.push(ids.length);
      for (const v of h) ids.push(v);
    }
  }
  // Relative to the ring's lowest corner, so that earcut works on small numbers.
  let x0 = Infinity, y0 = Infinity;
  for (const v of ring) {
    if (xs[v]! < x0) x0 = xs[v]!;
    if (ys[v]! < y0) y0 = ys[v]!;
  }
  const flat = new Float64Array(ids.length * 2);
  for (let i = 0; i < ids.length; i++) {
    flat[2 * i] = xs[ids[i]!]! - x0;
    flat[2 * i + 1] = ys[ids[i]!]! - y0;
  }
  const tri = earcut(flat, holeIndex, 2);
  let total2 = 0;
  for (let t = 0; t < tri.length; t += 3) {
    const a = ids[tri[t]!]!, b = ids[tri[t + 1]!]!, c = ids[tri[t + 2]!]!;
    // robust-predicates: negative for counterclockwise.
    const o2 = -orient2d(xs[a]!, ys[a]!, xs[b]!, ys[b]!, xs[c]!, ys[c]!);
    if (o2 === 0) continue;
    const ax = xs[a]! - x0, ay = ys[a]! - y0;
    total2 += Math.abs((xs[b]! - x0 - ax) * (ys[c]! - y0 - ay) - (xs[c]! - x0 - ax) * (ys[b]! - y0 - ay));
    if (o2 > 0) out.push(a, b, c);
    else out.push(a, c, b);
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
    if (crossesRightOf(xs[r[i]!]!, ys[r[i]!]!, xs[r[j]!]!, ys[r[j]!]!, x, y)) inside = !inside;
  }
  return inside;
}

/** Whether the segment (xi, yi)-(xj, yj) crosses the ray from (x, y) towards +x: even-odd point in polygon, one side at a time. */
export function crossesRightOf(xi: number, yi: number, xj: number, yj: number, x: number, y: number): boolean {
  return yi > y !== yj > y && x < ((xj - xi) * (y - yi)) / (yj - yi) + xi;
}
