// The checks that the half-edges form a planar partition: no segments crossing, no gap
// inside the domain, no part of it lying inside another. Each problem is noted and the
// check goes on.
import { orient } from '../geom/predicates.js';
import { ringArea2 } from '../geom/ring.js';
import { nextInFace, type HalfEdges } from './half-edges.js';
import type { Refusal } from './refusal.js';
import { crossingPoint, forEachNearPair, segmentsConflict } from './segment-conflict.js';

/**
 * Notes two segments that cross or touch other than at a shared vertex (an overlap), each pair of
 * features once; `snapNote` (when the snapping moved points) is added to each.
 */
export function checkCrossings(he: HalfEdges, xs: Float64Array, ys: Float64Array, refusal: Refusal, snapNote: string | null = null): void {
  const { from, to, face, twin, count: nh } = he;
  const segs: number[] = [];
  for (let h = 0; h < nh; h++) if (h < twin[h]!) segs.push(h);
  const named = new Set<string>();
  forEachNearPair(segs.map((h) => from[h]!), segs.map((h) => to[h]!), xs, ys, (i, j) => {
    const h = segs[i]!, g = segs[j]!;
    const a = from[h]!, b = to[h]!, c = from[g]!, d = to[g]!;
    if (!segmentsConflict(a, b, c, d, xs, ys)) return;
    const faces1 = [face[h]!, face[twin[h]!]!].filter((f) => f > 0);
    const faces2 = [face[g]!, face[twin[g]!]!].filter((f) => f > 0);
    const f1 = faces1[0] ?? 0;
    const other = faces2.find((f) => !faces1.includes(f)) ?? faces2[0] ?? 0;
    const key = f1 < other ? `${f1}|${other}` : `${other}|${f1}`;
    if (named.has(key)) return;
    named.add(key);
    const [ix, iy] = crossingPoint(a, b, c, d, xs, ys);
    // A ring crossing itself was named before this check; what is left is between features
    // (or a part of one feature across another of its parts).
    refusal.note(
      f1 === other ? 'selfIntersection' : 'overlap',
      (f1 === other ? 'is self-intersecting: its boundary crosses itself' : `crosses ${refusal.describe(other)} (overlap)`) + (snapNote ? ` (${snapNote})` : ''),
      f1, ix, iy,
    );
  });
}

/**
 * The outside's boundary: a cycle around a hole in the union of the faces is a gap (refused)
 * or, with allowHoles, an enclave (returned); a part of the domain inside another one's area
 * is an overlap (refused).
 */
export function checkOutside(he: HalfEdges, xs: Float64Array, ys: Float64Array, refusal: Refusal, allowHoles: boolean): { area: number; x: number; y: number }[] {
  const { from, to, face, twin } = he;
  const holes: { area: number; x: number; y: number }[] = [];
  const cycles = outsideCycles(he, xs, ys);
  for (const c of cycles) {
    if (c.area2 > 0) {
      // The outside on the left going counterclockwise: a hole in the union of all faces.
      const h = c.hs[0]!;
      if (allowHoles) {
        holes.push({ area: c.area2 / 2, x: xs[from[h]!]!, y: ys[from[h]!]! });
        continue;
      }
      const inner = face[twin[h]!]!;
      const [x0, y0, x1, y1] = c.bbox;
      refusal.note(
        'gap',
        `borders a gap inside the domain (an area no feature covers, ${(c.area2 / 2).toPrecision(4)} square units, bounding box ${[x0, y0, x1, y1].map((v) => Math.round(v * 1000) / 1000).join(', ')}); if it is outside the domain on purpose (an enclave), allow holes (--allow-holes, or "allowHoles": true in the style)`,
        inner, xs[from[h]!], ys[from[h]!],
      );
    }
  }
  // A point just outside the faces along any outside boundary must be outside every other
  // boundary too (counting holes): otherwise a component lies inside another one's area.
  if (cycles.length > 1) {
    for (const c of cycles) {
      const h = c.hs[0]!;
      const a = from[h]!, b = to[h]!;
      const mx = (xs[a]! + xs[b]!) / 2, my = (ys[a]! + ys[b]!) / 2;
      // Left of the half-edge lies the outside: inside c itself only when c is a hole.
      let w = c.area2 > 0 ? 1 : 0;
      for (const d of cycles) {
        if (d === c) continue;
        const [x0, y0, x1, y1] = d.bbox;
        if (mx < x0 || mx > x1 || my < y0 || my > y1) continue;
        w += windingAround(d.hs, from, xs, ys, mx, my);
      }
      if (w !== 0) {
        refusal.note('overlap', 'lies inside the area of other features without a hole for it (overlap)', face[twin[h]!], mx, my);
      }
    }
  }
  return holes;
}

function windingAround(hs: number[], from: Int32Array, xs: Float64Array, ys: Float64Array, px: number, py: number): number {
  let w = 0;
  const n = hs.length;
  for (let i = 0; i < n; i++) {
    const a = from[hs[i]!]!, b = from[hs[(i + 1) % n]!]!;
    const ay = ys[a]!, by = ys[b]!;
    if (ay <= py) {
      if (by > py && orient(xs[a]!, ay, xs[b]!, by, px, py) > 0) w++;
    } else if (by <= py && orient(xs[a]!, ay, xs[b]!, by, px, py) < 0) {
      w--;
    }
  }
  return w;
}

/** A cycle of the outside's half-edges: a hole in the union of the faces when area2 > 0 (counterclockwise). */
export interface OutsideCycle {
  hs: number[];
  area2: number;
  bbox: [number, number, number, number];
}

/** The cycles the outside's half-edges (face 0) form. */
export function outsideCycles(he: HalfEdges, xs: Float64Array, ys: Float64Array): OutsideCycle[] {
  const { from, to, face, twin, count: nh, out } = he;
  const seen = new Uint8Array(nh);
  const cycles: OutsideCycle[] = [];
  for (let h0 = 0; h0 < nh; h0++) {
    if (face[h0] !== 0 || seen[h0]) continue;
    const hs: number[] = [];
    let h = h0;
    let guard = 0;
    do {
      seen[h] = 1;
      hs.push(h);
      h = nextInFace(h, twin, to, out);
      if (++guard > nh) throw new Error('outside boundary does not close');
    } while (h !== h0);
    const ids = hs.map((g) => from[g]!);
    let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
    for (const v of ids) {
      x0 = Math.min(x0, xs[v]!); y0 = Math.min(y0, ys[v]!);
      x1 = Math.max(x1, xs[v]!); y1 = Math.max(y1, ys[v]!);
    }
    cycles.push({ hs, area2: ringArea2(ids, xs, ys), bbox: [x0, y0, x1, y1] });
  }
  return cycles;
}
