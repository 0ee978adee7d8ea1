// A tilted triangle cut at horizontal levels (z = level), for a smooth merge whose winner is
// re-emitted during the transition: below a re-emit's z the winner has its old id, above it the
// new one, so the part of a ramp triangle on each side of the level is drawn with that side's
// id. z is linear over a planar triangle, so the part between two levels is convex and its
// corners are the triangle's corners in that range and the points where its edges cross the
// levels: walking the edges, with the crossings put in, and keeping the points in range gives
// the part's outline in order.

export interface LevelPart {
  /** The part's outline (convex, in the triangle's turning direction): vertex ids and their z. */
  verts: number[];
  zs: number[];
  /** How many levels lie at or below the part: the id the winner has there. */
  group: number;
}

/**
 * Cuts triangle (verts, zs) at the sorted `levels`. `cut(p, q, level)` gives the vertex where
 * edge p-q crosses the level (the same for both triangles beside the edge). Returns the parts
 * between consecutive levels (parts with no area left out, by `hasArea`) and, per level, the
 * outline of the part at or below it (undefined when none).
 */
export function cutAtLevels(
  verts: readonly number[], zs: readonly number[], levels: readonly number[], cut: (p: number, q: number, level: number) => number, hasArea: (outline: readonly number[]) => boolean,
): { parts: LevelPart[]; below: (number[] | undefined)[] } {
  // The outline with every crossing put in.
  const ring: number[] = [], ringZ: number[] = [];
  for (let k = 0; k < 3; k++) {
    const p = verts[k]!, q = verts[(k + 1) % 3]!, zp = zs[k]!, zq = zs[(k + 1) % 3]!;
    ring.push(p);
    ringZ.push(zp);
    const crossing = levels.filter((l) => Math.min(zp, zq) < l && l < Math.max(zp, zq));
    if (zq < zp) crossing.reverse();
    for (const l of crossing) {
      ring.push(cut(p, q, l));
      ringZ.push(l);
    }
  }
  const within = (lo: number, hi: number): number[] | undefined => {
    const out: number[] = [];
    const outZ: number[] = [];
    ring.forEach((v, i) => {
      if (ringZ[i]! >= lo && ringZ[i]! <= hi) {
        out.push(v);
        outZ.push(ringZ[i]!);
      }
    });
    return out.length >= 3 && hasArea(out) ? [...out, ...outZ] : undefined;
  };
  const lo = Math.min(...zs), hi = Math.max(...zs);
  const parts: LevelPart[] = [];
  for (let g = 0; g <= levels.length; g++) {
    const bottom = g === 0 ? -Infinity : levels[g - 1]!, top = g === levels.length ? Infinity : levels[g]!;
    // A triangle flat at a level is above it, as a corner at a level is.
    const overlaps = lo === hi ? bottom <= lo && lo < top : bottom < hi && lo < top;
    if (!overlaps) continue;
    const both = within(bottom, top);
    if (!both) continue;
    const n = both.length / 2;
    parts.push({ verts: both.slice(0, n), zs: both.slice(n), group: g });
  }
  const below = levels.map((l) => {
    if (!(lo < l)) return undefined;
    const both = within(-Infinity, l);
    return both?.slice(0, both.length / 2);
  });
  return { parts, below };
}
