// Half-edges: every ring segment, directed with its face on the left, paired with its twin
// (the same segment the other way, the neighbour's or the outside's), and grouped by the
// vertex they start at. Two faces on the same side of a segment are an overlap: refused.
import type { Refusal } from './refusal.js';
import type { Ring } from './topology-types.js';

export interface Outgoing {
  /** Half-edges leaving vertex v: list[start[v] .. start[v + 1]). */
  start: Int32Array;
  list: Int32Array;
}

export interface HalfEdges {
  from: Int32Array;
  to: Int32Array;
  /** Face on the left (0: outside the domain). */
  face: Int32Array;
  twin: Int32Array;
  count: number;
  /** Outgoing half-edges of each vertex, counterclockwise by direction. */
  out: Outgoing;
}

/**
 * The half-edges of the rings, each with its twin, and with face 0 where no ring is across.
 * The first ones are the rings' segments, ring after ring in order (slivers.ts relies on it).
 */
export function buildHalfEdges(rings: Ring[], xs: Float64Array, ys: Float64Array, refusal: Refusal): HalfEdges {
  const nv = xs.length;
  const { from, to, face, count: nh0 } = ringHalfEdges(rings);
  const twin = pairTwins(from, to, face, nh0, nv, xs, ys, refusal);
  // Unmatched half-edges border the outside: give each a twin with face 0.
  let nh = nh0;
  const fromAll = new Int32Array(nh0 * 2), toAll = new Int32Array(nh0 * 2), faceAll = new Int32Array(nh0 * 2);
  fromAll.set(from);
  toAll.set(to);
  faceAll.set(face);
  for (let h = 0; h < nh0; h++) {
    if (twin[h]! >= 0) continue;
    fromAll[nh] = to[h]!;
    toAll[nh] = from[h]!;
    faceAll[nh] = 0;
    twin[h] = nh;
    twin[nh] = h;
    nh++;
  }
  const out = outgoing(fromAll, nv, nh);
  sortByAngle(out, fromAll, toAll, xs, ys);
  return { from: fromAll, to: toAll, face: faceAll, twin, count: nh, out };
}

/**
 * The twin of each half-edge among the rings' own (-1: none, the outside is across), room
 * left for twice as many. Notes two half-edges the same way (an overlap or a repeated ring)
 * and a face on both sides of a segment.
 */
function pairTwins(
  from: Int32Array, to: Int32Array, face: Int32Array, nh0: number, nv: number,
  xs: Float64Array, ys: Float64Array, refusal: Refusal,
): Int32Array {
  const out = outgoing(from, nv, nh0);
  const twin = new Int32Array(nh0 * 2).fill(-1);
  // Each pair of faces is named once, at the first segment found.
  const named = new Set<string>();
  const once = (f: number, g: number): boolean => {
    const key = f < g ? `${f}|${g}` : `${g}|${f}`;
    if (named.has(key)) return false;
    named.add(key);
    return true;
  };
  for (let h = 0; h < nh0; h++) {
    const u = from[h]!, v = to[h]!;
    for (let k = out.start[u]!; k < out.start[u + 1]!; k++) {
      const g = out.list[k]!;
      if (g !== h && to[g] === v) {
        const mx = (xs[u]! + xs[v]!) / 2, my = (ys[u]! + ys[v]!) / 2;
        if (g > h || !once(face[g]!, face[h]!)) continue;
        if (face[g] === face[h]) refusal.note('overlap', 'has a boundary segment twice in the same direction (a repeated ring or part)', face[h], mx, my);
        else refusal.note('overlap', `overlaps ${refusal.describe(face[g]!)}: both lie on the same side of the segment`, face[h], mx, my);
      }
    }
    for (let k = out.start[v]!; k < out.start[v + 1]!; k++) {
      const g = out.list[k]!;
      if (to[g] === u) {
        if (face[g] === face[h]) {
          if (g > h && once(face[h]!, face[h]!)) refusal.note('selfIntersection', 'touches itself along a segment (a ring or hole that is not a simple boundary)', face[h], (xs[u]! + xs[v]!) / 2, (ys[u]! + ys[v]!) / 2);
          continue;
        }
        twin[h] = g;
        break;
      }
    }
  }
  return twin;
}

/**
 * The same half-edges with the faces given (one per half-edge, e.g. after a sliver's side was
 * handed to its neighbour), without the segments that now have one face on both sides.
 */
export function withFaces(he: HalfEdges, faces: Int32Array, xs: Float64Array, ys: Float64Array): HalfEdges {
  const newId = new Int32Array(he.count).fill(-1);
  let n = 0;
  for (let h = 0; h < he.count; h++) if (faces[h] !== faces[he.twin[h]!]) newId[h] = n++;
  const from = new Int32Array(n), to = new Int32Array(n), face = new Int32Array(n), twin = new Int32Array(n);
  for (let h = 0; h < he.count; h++) {
    const k = newId[h]!;
    if (k < 0) continue;
    from[k] = he.from[h]!;
    to[k] = he.to[h]!;
    face[k] = faces[h]!;
    twin[k] = newId[he.twin[h]!]!;
  }
  const out = outgoing(from, xs.length, n);
  sortByAngle(out, from, to, xs, ys);
  return { from, to, face, twin, count: n, out };
}

/** One half-edge per ring segment, the ring's face on its left. */
function ringHalfEdges(rings: Ring[]): { from: Int32Array; to: Int32Array; face: Int32Array; count: number } {
  let n = 0;
  for (const r of rings) n += r.ids.length;
  const from = new Int32Array(n), to = new Int32Array(n), face = new Int32Array(n);
  let h = 0;
  for (const r of rings) {
    const m = r.ids.length;
    for (let i = 0; i < m; i++) {
      from[h] = r.ids[i]!;
      to[h] = r.ids[(i + 1) % m]!;
      face[h] = r.face;
      h++;
    }
  }
  return { from, to, face, count: n };
}

/** Half-edges grouped by their start vertex (compressed rows). */
function outgoing(from: Int32Array, nv: number, nh: number): Outgoing {
  const start = new Int32Array(nv + 1);
  for (let h = 0; h < nh; h++) start[from[h]! + 1]!++;
  for (let v = 0; v < nv; v++) start[v + 1]! += start[v]!;
  const fill = start.slice(0, nv);
  const list = new Int32Array(nh);
  for (let h = 0; h < nh; h++) list[fill[from[h]!]!++] = h;
  return { start, list };
}

/** Sorts each vertex's outgoing half-edges counterclockwise by direction. */
function sortByAngle(out: Outgoing, from: Int32Array, to: Int32Array, xs: Float64Array, ys: Float64Array): void {
  const nv = out.start.length - 1;
  for (let v = 0; v < nv; v++) {
    const s = out.start[v]!, e = out.start[v + 1]!;
    if (e - s <= 2) continue; // two directions are in order either way for our use
    const hs = Array.from(out.list.subarray(s, e));
    const ang = (h: number): number => Math.atan2(ys[to[h]!]! - ys[from[h]!]!, xs[to[h]!]! - xs[from[h]!]!);
    hs.sort((a, b) => ang(a) - ang(b));
    out.list.set(hs, s);
  }
}

/** The next half-edge around the face on the left of h: clockwise-next after h's twin at h's end. */
export function nextInFace(h: number, twin: Int32Array, to: Int32Array, out: Outgoing): number {
  const v = to[h]!;
  const s = out.start[v]!, e = out.start[v + 1]!;
  const t = twin[h]!;
  for (let k = s; k < e; k++) {
    if (out.list[k] === t) return out.list[k === s ? e - 1 : k - 1]!;
  }
  throw new Error('half-edge structure is inconsistent');
}
