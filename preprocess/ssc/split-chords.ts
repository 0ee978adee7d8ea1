// A smooth merge's front leaves every vertex of the shared boundary at once, so a triangle whose
// three corners all lie on that boundary would be flat at the ramp's foot and go at once: a
// jump of up to a tenth of a merge's area (measured on bgt_otterlo_1800m and nlcd_zion). Its
// edges between two boundary vertices that are not a piece of the boundary (chords through the
// loser's interior) get a vertex at their midpoint, which the front reaches later: the triangle
// then rises from its boundary side.
import { orient } from '../geom/predicates.js';

/** An undirected edge's name: a chord's midpoint is shared by the triangles on either side of it. */
export const edgeKey = (a: number, b: number): string => (a < b ? `${a} ${b}` : `${b} ${a}`);

/**
 * `tris` (vertex ids, 3 per triangle, counterclockwise) with every chord split at its
 * midpoint: an edge inside the area they cover whose two ends satisfy `onBoundary` but which
 * is not a boundary segment (`segment`). `addVertex` makes a new vertex and returns its id.
 */
export function splitChords(
  tris: readonly number[], xs: ArrayLike<number>, ys: ArrayLike<number>,
  onBoundary: (v: number) => boolean, segment: (a: number, b: number) => boolean, addVertex: (x: number, y: number) => number,
): number[] {
  // Only an edge that two of the triangles share, one each way, lies inside the area (a flat
  // triangle along the outline counts for nothing). One on its outline borders another
  // surface, whose triangles would not take the midpoint: a T-junction there, and a crack once
  // the midpoint is put on the chunks' grid (snap-new-vertices.ts), off the line.
  const sides = new Set<string>();
  for (let i = 0; i + 2 < tris.length; i += 3) {
    const a = tris[i]!, b = tris[i + 1]!, c = tris[i + 2]!;
    if (orient(xs[a]!, ys[a]!, xs[b]!, ys[b]!, xs[c]!, ys[c]!) === 0) continue;
    sides.add(`${a}>${b}`).add(`${b}>${c}`).add(`${c}>${a}`);
  }
  const mids = new Map<string, number>();
  const midOf = (a: number, b: number): number => {
    if (!onBoundary(a) || !onBoundary(b) || segment(a, b) || !sides.has(`${a}>${b}`) || !sides.has(`${b}>${a}`)) return -1;
    const k = edgeKey(a, b);
    let m = mids.get(k);
    if (m === undefined) mids.set(k, (m = addVertex((xs[a]! + xs[b]!) / 2, (ys[a]! + ys[b]!) / 2)));
    return m;
  };
  const out: number[] = [];
  for (let i = 0; i + 2 < tris.length; i += 3) {
    const c = [tris[i]!, tris[i + 1]!, tris[i + 2]!];
    // m[j]: the midpoint of edge j (corner j to corner j + 1), or -1.
    const m = [0, 1, 2].map((j) => midOf(c[j]!, c[(j + 1) % 3]!));
    const split = m.filter((x) => x >= 0).length;
    if (split === 0) {
      out.push(c[0]!, c[1]!, c[2]!);
    } else if (split === 3) {
      out.push(c[0]!, m[0]!, m[2]!, c[1]!, m[1]!, m[0]!, c[2]!, m[2]!, m[1]!, m[0]!, m[1]!, m[2]!);
    } else {
      // Rotate so that edge 0 is split (and edge 1 too when two are).
      const r = split === 1 ? m.findIndex((x) => x >= 0) : m[0]! >= 0 ? (m[1]! >= 0 ? 0 : 2) : 1;
      const a = c[r]!, b = c[(r + 1) % 3]!, d = c[(r + 2) % 3]!;
      const mab = m[r]!, mbd = m[(r + 1) % 3]!;
      if (split === 1) {
        out.push(a, mab, d, mab, b, d);
      } else {
        out.push(a, mab, d, mab, b, mbd, mab, mbd, d);
      }
    }
  }
  return out;
}
