// The floor's faces as boundaries (the floor chunk file, docs/FORMAT.md): from each face's floor
// triangles, the sides no other triangle of the face shares, each piece of boundary between two
// faces once (with the face on its left and the one on its right), joined into runs of points.
// Taken from the triangles rather than the tGAP's edges, so that the floor chunks bound exactly
// the area the floor triangles cover, with the same points.
import { orient2d } from 'robust-predicates';
import type { Surfaces } from './surfaces.js';

export interface FloorBoundary {
  /** Vertex ids (into the surfaces' xs, ys), in order with `left` on the left. */
  verts: number[];
  /** The faces on either side; 0: none among the triangles given (another chunk's, or the edge of the data). */
  left: number;
  right: number;
}

export interface FloorFaces {
  /** The floor's faces, in order of their first triangle. */
  faces: number[];
  /** Each face's triangles. */
  trianglesOf: Map<number, number[]>;
  edges: FloorBoundary[];
}

/** Vertex ids below this make one exact key for a directed side. */
const VERTEX_KEY = 2 ** 26;

/** `xs`, `ys`: the ground position of each vertex id. */
export function floorBoundaries(s: Surfaces, floor: ArrayLike<number>, xs: ArrayLike<number>, ys: ArrayLike<number>): FloorFaces {
  const trianglesOf = new Map<number, number[]>();
  // Each directed side of a floor triangle, and the face of the triangle.
  const sideFace = new Map<number, number>();
  for (let k = 0; k < floor.length; k++) {
    const i = floor[k]!, f = s.upper[i]!;
    // A floor triangle is flat at z = 0 over face 0: what the floor chunk file can say.
    if (s.lower[i] !== 0 || s.zMin[i] !== 0 || [0, 1, 2].some((j) => s.z[3 * i + j] !== 0)) throw new Error(`floor boundaries: triangle ${i} (face ${f}) is not at z = 0 over face 0`);
    let tris = trianglesOf.get(f);
    if (!tris) trianglesOf.set(f, (tris = []));
    tris.push(i);
    for (let j = 0; j < 3; j++) {
      if (s.v[3 * i + j]! >= VERTEX_KEY) throw new Error(`floor boundaries: vertex ${s.v[3 * i + j]}, at most ${VERTEX_KEY - 1}`);
      sideFace.set(s.v[3 * i + j]! * VERTEX_KEY + s.v[3 * i + ((j + 1) % 3)]!, f);
    }
  }

  splitAtTJunctions(xs, ys, sideFace);

  // The boundary sides, each once: a side whose reverse is another face's is kept by the lower face id.
  const groups = new Map<string, { left: number; right: number; from: number[]; to: number[] }>();
  for (const [key, f] of sideFace) {
    const a = Math.floor(key / VERTEX_KEY), b = key % VERTEX_KEY;
    const other = sideFace.get(b * VERTEX_KEY + a) ?? 0;
    if (other === f || (other !== 0 && other < f)) continue;
    const g = `${f} ${other}`;
    let group = groups.get(g);
    if (!group) groups.set(g, (group = { left: f, right: other, from: [], to: [] }));
    group.from.push(a);
    group.to.push(b);
  }

  // Sides of one pair of faces joined into runs, broken where the run would branch.
  const runs: FloorBoundary[] = [];
  for (const g of groups.values()) {
    const next = new Map<number, number[]>(), into = new Map<number, number>();
    g.from.forEach((a, k) => {
      const l = next.get(a);
      if (l) l.push(k);
      else next.set(a, [k]);
      into.set(g.to[k]!, (into.get(g.to[k]!) ?? 0) + 1);
    });
    const through = (v: number): boolean => next.get(v)?.length === 1 && into.get(v) === 1;
    const used = new Uint8Array(g.from.length);
    const run = (k0: number): void => {
      const verts = [g.from[k0]!];
      let k = k0;
      for (;;) {
        used[k] = 1;
        const v = g.to[k]!;
        verts.push(v);
        if (v === verts[0] || !through(v)) break;
        k = next.get(v)![0]!;
        if (used[k]) break;
      }
      runs.push({ verts, left: g.left, right: g.right });
    };
    // Open runs first (from a point that is not passed through), then the closed loops.
    g.from.forEach((a, k) => { if (!used[k] && !through(a)) run(k); });
    g.from.forEach((_, k) => { if (!used[k]) run(k); });
  }

  return { faces: [...trianglesOf.keys()], trianglesOf, edges: chained(runs) };
}

/**
 * A side of one face that passes through a corner of another face's triangles (a T-junction: the
 * build's triangles need not meet corner to corner, e.g. at a point only one face's triangles
 * use, or where two faces split between chunks have sides on one line) is split there. Both
 * faces' boundaries then have the same points and make one edge. Otherwise the two would be two
 * edges over one line, and the floor chunk file's version 2, which finds the faces from the
 * cycles the edges go round, could not be written. Only sides with no reverse side (another
 * face's, or none) and their ends are concerned; a point splits a side when it lies exactly on it
 * (robust-predicates' orient2d) strictly between its ends.
 */
function splitAtTJunctions(xs: ArrayLike<number>, ys: ArrayLike<number>, sideFace: Map<number, number>): void {
  const key = (a: number, b: number): number => a * VERTEX_KEY + b;
  const lone: number[] = [];
  const ends = new Set<number>();
  let sum = 0;
  for (const k of sideFace.keys()) {
    const a = Math.floor(k / VERTEX_KEY), b = k % VERTEX_KEY;
    if (sideFace.has(key(b, a))) continue;
    lone.push(k);
    ends.add(a);
    ends.add(b);
    sum += Math.hypot(xs[b]! - xs[a]!, ys[b]! - ys[a]!);
  }
  if (lone.length === 0) return;
  // The ends in cells about a side long.
  const cell = Math.max(sum / lone.length, 1e-9);
  const cellKey = (cx: number, cy: number): string => `${cx} ${cy}`;
  const cells = new Map<string, number[]>();
  for (const v of ends) {
    const c = cellKey(Math.floor(xs[v]! / cell), Math.floor(ys[v]! / cell));
    const l = cells.get(c);
    if (l) l.push(v);
    else cells.set(c, [v]);
  }
  for (const k of lone) {
    const a = Math.floor(k / VERTEX_KEY), b = k % VERTEX_KEY;
    const ax = xs[a]!, ay = ys[a]!, dx = xs[b]! - ax, dy = ys[b]! - ay, len2 = dx * dx + dy * dy;
    const inside: { v: number; t: number }[] = [];
    const cx0 = Math.floor(Math.min(ax, xs[b]!) / cell), cx1 = Math.floor(Math.max(ax, xs[b]!) / cell);
    const cy0 = Math.floor(Math.min(ay, ys[b]!) / cell), cy1 = Math.floor(Math.max(ay, ys[b]!) / cell);
    for (let cx = cx0; cx <= cx1; cx++) {
      for (let cy = cy0; cy <= cy1; cy++) {
        for (const v of cells.get(cellKey(cx, cy)) ?? []) {
          if (v === a || v === b || orient2d(ax, ay, xs[b]!, ys[b]!, xs[v]!, ys[v]!) !== 0) continue;
          const px = xs[v]! - ax, py = ys[v]! - ay;
          const t = (px * dx + py * dy) / len2;
          if (t > 0 && t < 1) inside.push({ v, t });
        }
      }
    }
    if (inside.length === 0) continue;
    inside.sort((p, q) => p.t - q.t || p.v - q.v);
    const f = sideFace.get(k)!;
    sideFace.delete(k);
    let from = a;
    for (const { v } of inside) {
      // Two vertices at one point make one split.
      if (xs[v] === xs[from] && ys[v] === ys[from]) continue;
      sideFace.set(key(from, v), f);
      from = v;
    }
    sideFace.set(key(from, b), f);
  }
}

/**
 * The edges in an order where each starts, as far as it can, where the one before it ended
 * (turned around where that helps): the floor chunk file then stores that point once.
 */
function chained(edges: FloorBoundary[]): FloorBoundary[] {
  const touching = new Map<number, number[]>();
  edges.forEach((ed, k) => {
    for (const v of new Set([ed.verts[0]!, ed.verts[ed.verts.length - 1]!])) {
      const l = touching.get(v);
      if (l) l.push(k);
      else touching.set(v, [k]);
    }
  });
  const used = new Uint8Array(edges.length);
  const out: FloorBoundary[] = [];
  let next = 0, end = -1, left = -1;
  while (out.length < edges.length) {
    // Going on around the same face where one can: the faces then change little from edge to edge.
    const free = (touching.get(end) ?? []).filter((j) => !used[j]);
    const leftAfter = (j: number): number => (edges[j]!.verts[0] === end ? edges[j]!.left : edges[j]!.right);
    let k = free.find((j) => leftAfter(j) === left) ?? free[0] ?? -1;
    if (k < 0) {
      while (used[next]) next++;
      k = next;
    }
    used[k] = 1;
    const ed = edges[k]!;
    const turned = ed.verts[0] !== end && ed.verts[ed.verts.length - 1] === end;
    out.push(turned ? { verts: [...ed.verts].reverse(), left: ed.right, right: ed.left } : ed);
    const last = out[out.length - 1]!;
    end = last.verts[last.verts.length - 1]!;
    left = last.left;
  }
  return out;
}
