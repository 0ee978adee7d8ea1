// The chunk file's ring pieces (docs/FORMAT.md, "Chunk file", version 6): a level piece of
// surface (one z, one upper and one lower face) stored as the rings round it, which the reader
// cuts into triangles with earcut. The writer finds the pieces and keeps as rings only those
// whose cut by the reader (cutRingPieces, on the same whole grid steps) covers exactly what the
// triangles covered. Level triangles were 64% of those nlcd_zion's whole-extent view needs; as
// rings, that view's chunks went from 1,447 to 1,218 kB gzip.
import { assembleRings, earcutRings, ringArea2 } from './face-rings.js';

/** A level piece: its z, its faces (as the caller names them) and its rings of point ids. */
export interface RingPiece {
  z: number;
  upper: number;
  lower: number;
  /** Rings of point ids, each starting at its lowest point (x, then y), in that point's order. */
  rings: number[][];
}

/**
 * A chunk's triangles with their vertices' points (ids into xs, ys: whole grid steps, at most
 * 2^24 either way, as gridSteps gives them, so that every product the checks take is exact in
 * float64), z values and faces.
 */
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
 * The level pieces that can go as rings, in the order of their first triangle, and which
 * triangles they take (`ringed[t]` = 1). A piece is the level triangles of one z and two faces
 * (all three corners alike); it goes as rings when its triangles are all counterclockwise, no
 * side is used twice the same way, and the reader's cut of the rings round them has the same
 * sides along every line (sameLines), so each point is covered as often.
 */
export function findRingPieces(c: PieceInput): { pieces: RingPiece[]; ringed: Uint8Array } {
  const T = c.indices.length / 3;
  // Sides are keyed by their two point ids: a * P + b stays exact in float64.
  if (c.xs.length ** 2 > Number.MAX_SAFE_INTEGER) throw new Error(`chunk encoder: ${c.xs.length} points are too many for a chunk`);
  const groups = new Map<string, number[]>();
  for (let t = 0; t < T; t++) {
    const [a, b, d] = [c.indices[3 * t]!, c.indices[3 * t + 1]!, c.indices[3 * t + 2]!];
    const z = c.zOf[a]!, up = c.upper[a]!, low = c.lower[a]!;
    if (c.zOf[b] !== z || c.zOf[d] !== z || c.upper[b] !== up || c.upper[d] !== up || c.lower[b] !== low || c.lower[d] !== low) continue;
    const key = `${z}|${up}|${low}`;
    let g = groups.get(key);
    if (!g) groups.set(key, (g = []));
    g.push(t);
  }
  const ringed = new Uint8Array(T);
  const pieces: RingPiece[] = [];
  for (const tris of groups.values()) {
    const corners = tris.flatMap((t) => [0, 1, 2].map((k) => c.pointOf[c.indices[3 * t + k]!]!));
    const rings = ringsRound(corners, c.xs, c.ys);
    if (!rings) continue;
    for (const t of tris) ringed[t] = 1;
    const v = c.indices[3 * tris[0]!]!;
    pieces.push({ z: c.zOf[v]!, upper: c.upper[v]!, lower: c.lower[v]!, rings });
  }
  return { pieces, ringed };
}

/**
 * The canonical rings round triangles (`corners`: 3 point ids each) when the reader's cut of them
 * covers exactly what the triangles cover; else null.
 */
function ringsRound(corners: number[], xs: ArrayLike<number>, ys: ArrayLike<number>): number[][] | null {
  const within = sidesRound(corners, xs, ys);
  if (!within) return null;
  const rings = assembleRings([...within.round].map((k) => ({ verts: within.sideOf(k), forward: true })), xs, ys).map((r) => startAtLowest(r, xs, ys));
  rings.sort((r, s) => compareRings(r, s, xs, ys));
  const cut: number[] = [];
  earcutRings(rings, xs, ys, cut);
  // The cut's triangles are counterclockwise (earcutRings turns them so, and leaves out those
  // of no area); with the same sides as the triangles', as lines, each point is covered as often.
  return sameLines(corners, cut, xs, ys) ? rings : null;
}

/**
 * Whether two sets of triangles (3 point ids each) have the same sides, counted along each
 * line: on every straight line, the sides going one way less those going the other cover each
 * stretch of it as often. Sides shared inside cancel; a side that earcut leaves a point of, or
 * splits elsewhere, counts as the same line. Counterclockwise triangles with the same sides cover
 * each point as often (the winding number of their sides).
 */
function sameLines(a: ArrayLike<number>, b: ArrayLike<number>, xs: ArrayLike<number>, ys: ArrayLike<number>): boolean {
  const flow = new Map<string, number>();
  const add = (tris: ArrayLike<number>, sign: number): void => {
    for (let i = 0; i < tris.length; i += 3) {
      for (let k = 0; k < 3; k++) {
        const p = tris[i + k]!, q = tris[i + ((k + 1) % 3)]!;
        let dx = xs[q]! - xs[p]!, dy = ys[q]! - ys[p]!;
        const g = gcd(Math.abs(dx), Math.abs(dy));
        dx /= g;
        dy /= g;
        // The line's direction, one way round; the side goes along it (+1) or against it (-1).
        let s = sign;
        if (dx < 0 || (dx === 0 && dy < 0)) {
          dx = -dx;
          dy = -dy;
          s = -s;
        }
        // Whole steps: the line's offset and the ends' places along it are exact.
        const line = `${dx},${dy},${dx * ys[p]! - dy * xs[p]!}`;
        const tp = dx * xs[p]! + dy * ys[p]!, tq = dx * xs[q]! + dy * ys[q]!;
        const at = (t: number, d: number): void => {
          const key = `${line},${t}`;
          const v = (flow.get(key) ?? 0) + d;
          if (v === 0) flow.delete(key);
          else flow.set(key, v);
        };
        at(Math.min(tp, tq), s);
        at(Math.max(tp, tq), -s);
      }
    }
  };
  add(a, 1);
  add(b, -1);
  return flow.size === 0;
}

function gcd(a: number, b: number): number {
  while (b) [a, b] = [b, a % b];
  return a;
}

/**
 * The sides round counterclockwise triangles (3 point ids each): those no triangle has the other
 * way round, as keys; null when a triangle is not counterclockwise or a side is used twice the
 * same way.
 */
function sidesRound(corners: ArrayLike<number>, xs: ArrayLike<number>, ys: ArrayLike<number>): { round: Set<number>; sideOf: (k: number) => [number, number] } | null {
  const P = xs.length;
  const sides = new Set<number>();
  for (let i = 0; i < corners.length; i += 3) {
    const tri = [corners[i]!, corners[i + 1]!, corners[i + 2]!];
    // Whole steps: exact.
    if (!(ringArea2(tri, xs, ys) > 0)) return null;
    for (let k = 0; k < 3; k++) {
      const key = tri[k]! * P + tri[(k + 1) % 3]!;
      if (sides.has(key)) return null;
      sides.add(key);
    }
  }
  const round = new Set<number>();
  const sideOf = (k: number): [number, number] => [Math.floor(k / P), k % P];
  for (const k of sides) {
    const [a, b] = sideOf(k);
    if (!sides.has(b * P + a)) round.add(k);
  }
  return { round, sideOf };
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

/** The reader's side: ring pieces cut into vertices (a point once per piece) and triangles. */
export interface CutPieces {
  /** Each vertex's point and its piece. */
  vertexPoints: number[];
  vertexPiece: number[];
  /** Counterclockwise triangles as indices into those vertices. */
  triangles: number[];
}

/**
 * The pieces of a file cut as the writer checked them (earcutRings on the points' whole steps
 * `xs`, `ys`): `ringCounts[g]` rings for piece g, taken in turn from `lengths`, whose points are
 * taken in turn from `ringPoints`. `fail` names what does not add up.
 */
export function cutRingPieces(
  ringCounts: ArrayLike<number>, lengths: ArrayLike<number>, ringPoints: Uint32Array, xs: ArrayLike<number>, ys: ArrayLike<number>, fail: (why: string) => Error,
): CutPieces {
  const P = xs.length;
  for (const p of ringPoints) if (p >= P) throw fail(`a ring names point ${p} of ${P}`);
  const out: CutPieces = { vertexPoints: [], vertexPiece: [], triangles: [] };
  // The vertex of each point in the current piece: vertexOf[p], valid where seenIn[p] is the piece + 1.
  const seenIn = new Uint32Array(P), vertexOf = new Uint32Array(P);
  const cut: number[] = [];
  let r = 0, q = 0;
  for (let g = 0; g < ringCounts.length; g++) {
    const n = ringCounts[g]!;
    if (n === 0 || r + n > lengths.length) throw fail(`ring piece ${g} has ${n} rings, ${lengths.length - r} are left`);
    const rings: number[][] = [];
    for (let i = 0; i < n; i++, r++) {
      const len = lengths[r]!;
      if (len < 3 || q + len > ringPoints.length) throw fail(`ring ${r} has ${len} points, ${ringPoints.length - q} are left`);
      rings.push(Array.from(ringPoints.subarray(q, q + len)));
      q += len;
    }
    cut.length = 0;
    earcutRings(rings, xs, ys, cut);
    for (const p of cut) {
      if (seenIn[p] !== g + 1) {
        seenIn[p] = g + 1;
        vertexOf[p] = out.vertexPoints.length;
        out.vertexPoints.push(p);
        out.vertexPiece.push(g);
      }
      out.triangles.push(vertexOf[p]!);
    }
  }
  if (r !== lengths.length || q !== ringPoints.length) throw fail(`${lengths.length - r} rings and ${ringPoints.length - q} ring points belong to no piece`);
  return out;
}
