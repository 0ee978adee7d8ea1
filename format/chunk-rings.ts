// The chunk file's ring pieces (docs/FORMAT.md, "Chunk file", version 6): a horizontal piece of
// surface (one z, one upper and one lower face) stored as the rings round it, which the reader
// cuts into triangles with earcut. The writer finds the pieces and keeps as rings only those
// that the reader's very cut (cutRingPiece, on the same whole grid steps) gives back exactly:
// the triangles' area, to the unit, with none turned over. Horizontal triangles were 64% of
// those nlcd_zion's whole-extent view needs, and as rings their share of the bytes fell by half.
import { assembleRings, earcutRings, ringArea2 } from './face-rings.js';

/** A horizontal piece: its z, its faces (as the caller names them) and its rings of point ids. */
export interface RingPiece {
  z: number;
  upper: number;
  lower: number;
  /** Rings of point ids, each starting at its lowest point (x, then y), in that point's order. */
  rings: number[][];
}

/** A chunk's triangles with their vertices' points (ids into xs, ys: whole grid steps), z values and faces. */
export interface PieceInput {
  indices: ArrayLike<number>;
  pointOf: ArrayLike<number>;
  /** z of each vertex (float32 values). */
  zOf: ArrayLike<number>;
  upper: ArrayLike<number>;
  lower: ArrayLike<number>;
  xs: ArrayLike<number>;
  ys: ArrayLike<number>;
}

/**
 * The reader's triangles of a ring piece: counterclockwise triangles of point ids appended to
 * `out`; returns twice their area. The same call on the same steps gives the same triangles.
 */
export function cutRingPiece(rings: number[][], xs: ArrayLike<number>, ys: ArrayLike<number>, out: number[]): number {
  return earcutRings(rings, xs, ys, out);
}

/**
 * The horizontal pieces that can go as rings, in the order of their first triangle, and which
 * triangles they take (`ringed[t]` = 1). A piece is the horizontal triangles of one z and two
 * faces; it stays as triangles unless they are all counterclockwise, no side is used twice the
 * same way, and the rings round them and earcut's cut of those rings have exactly their area.
 */
export function findRingPieces(c: PieceInput): { pieces: RingPiece[]; ringed: Uint8Array } {
  const T = c.indices.length / 3;
  const groups = new Map<string, number[]>();
  for (let t = 0; t < T; t++) {
    const a = c.indices[3 * t]!, b = c.indices[3 * t + 1]!, d = c.indices[3 * t + 2]!;
    const z = c.zOf[a]!;
    if (c.zOf[b] !== z || c.zOf[d] !== z) continue;
    const key = `${z}|${c.upper[a]}|${c.lower[a]}`;
    let g = groups.get(key);
    if (!g) groups.set(key, (g = []));
    g.push(t);
  }
  const ringed = new Uint8Array(T);
  const pieces: RingPiece[] = [];
  for (const tris of groups.values()) {
    const rings = piecesRings(c, tris);
    if (!rings) continue;
    for (const t of tris) ringed[t] = 1;
    const v = c.indices[3 * tris[0]!]!;
    pieces.push({ z: c.zOf[v]!, upper: c.upper[v]!, lower: c.lower[v]!, rings });
  }
  return { pieces, ringed };
}

/** The canonical rings round triangles `tris` when the reader's cut of them gives their area back exactly; else null. */
function piecesRings(c: PieceInput, tris: number[]): number[][] | null {
  const { xs, ys } = c;
  const p = (t: number, k: number): number => c.pointOf[c.indices[3 * t + k]!]!;
  // Directed sides by their two points (ids are below 2^26: a chunk's points are far fewer).
  const sides = new Map<number, number>();
  const key = (a: number, b: number): number => a * 67108864 + b;
  let area2 = 0;
  for (const t of tris) {
    const a = p(t, 0), b = p(t, 1), d = p(t, 2);
    // Whole steps: exact.
    const t2 = (xs[b]! - xs[a]!) * (ys[d]! - ys[a]!) - (xs[d]! - xs[a]!) * (ys[b]! - ys[a]!);
    if (!(t2 > 0)) return null;
    area2 += t2;
    for (const [u, w] of [[a, b], [b, d], [d, a]] as const) {
      const k = key(u, w);
      if (sides.has(k)) return null;
      sides.set(k, 1);
    }
  }
  const edges: { verts: number[]; forward: boolean }[] = [];
  for (const t of tris) {
    for (let k = 0; k < 3; k++) {
      const u = p(t, k), w = p(t, (k + 1) % 3);
      if (!sides.has(key(w, u))) edges.push({ verts: [u, w], forward: true });
    }
  }
  const rings = assembleRings(edges, xs, ys).map((r) => startAtLowest(r, xs, ys));
  rings.sort((r, s) => compareRings(r, s, xs, ys));
  let ringSum = 0;
  for (const r of rings) ringSum += ringArea2(r, xs, ys);
  if (ringSum !== area2) return null;
  return cutRingPiece(rings, xs, ys, []) === area2 ? rings : null;
}

/** The ring rotated to start at its lowest point (smallest x, then y): the same rings give the same file. */
function startAtLowest(r: number[], xs: ArrayLike<number>, ys: ArrayLike<number>): number[] {
  let best = 0;
  for (let i = 1; i < r.length; i++) {
    const dx = xs[r[i]!]! - xs[r[best]!]!;
    if (dx < 0 || (dx === 0 && ys[r[i]!]! < ys[r[best]!]!)) best = i;
  }
  return best === 0 ? r : [...r.slice(best), ...r.slice(0, best)];
}

function compareRings(r: number[], s: number[], xs: ArrayLike<number>, ys: ArrayLike<number>): number {
  for (let i = 0; i < Math.min(r.length, s.length); i++) {
    const d = xs[r[i]!]! - xs[s[i]!]! || ys[r[i]!]! - ys[s[i]!]!;
    if (d !== 0) return d;
  }
  return r.length - s.length;
}
