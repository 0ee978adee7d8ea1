// Smooth simplification of cube lines (issue 12, item 2): a vertex that simplification takes
// away at its leave z does not vanish at once, cutting its corner in one frame. Over the half
// zoom level before it goes it glides, linearly in z, to the nearest point of the chord between
// its neighbours that stay (the nearest vertex on each side whose leave z is later), where its
// two segments lie on that chord when it goes: the line straightens gradually. The same rule for
// the GPU's line pass, the CPU reference drawer and picking.
//
// Derived from what the line chunk stores (positions and leave z), so the format is unchanged.
// A neighbour that is itself gliding then is taken where it stands, not where it is going: the
// corner it leaves is at most that neighbour's own glide, a fraction of a pixel.
import type { LineRecord, LineSegment } from './line-record.js';
import { lineSegments } from './line-record.js';
import { LINE_RAMP_SCALE } from './line-ramp.js';
import { scaleAtZ, zAtScale, type ScaleInfo } from './scale.js';
import { projectOnSegment } from './point-segment.js';

/** Per vertex of one polyline: where it glides to, and from which z (to its leave z). */
export interface PathGlides {
  tx: Float64Array;
  ty: Float64Array;
  from: Float64Array;
}

/** A segment with how each end glides: to (tx, ty) from z `from` to `to` (its leave z). */
export interface GlidingSegment extends LineSegment {
  atx: number;
  aty: number;
  aFrom: number;
  aTo: number;
  btx: number;
  bty: number;
  bFrom: number;
  bTo: number;
}

/** The glides of every vertex of a line (a vertex that stays glides nowhere: its own point, from its leave z). */
export function lineGlides(l: LineRecord, info: ScaleInfo): PathGlides[] {
  return l.paths.map((p, k) => {
    const leave = l.leaveZ[k]!, n = leave.length;
    const tx = new Float64Array(n), ty = new Float64Array(n), from = Float64Array.from(leave);
    for (let v = 0; v < n; v++) {
      const x = p[2 * v]!, y = p[2 * v + 1]!, gone = leave[v]!;
      tx[v] = x;
      ty[v] = y;
      if (!(gone < l.zEnd)) continue;
      let a = v - 1, b = v + 1;
      while (a >= 0 && !(leave[a]! > gone)) a--;
      while (b < n && !(leave[b]! > gone)) b++;
      // Simplification keeps a polyline's ends; without a neighbour on each side there is no chord.
      if (a < 0 || b >= n) continue;
      const ax = p[2 * a]!, ay = p[2 * a + 1]!, bx = p[2 * b]!, by = p[2 * b + 1]!;
      const t = projectOnSegment(x, y, ax, ay, bx, by);
      tx[v] = ax + t * (bx - ax);
      ty[v] = ay + t * (by - ay);
      from[v] = Math.max(l.zStart, Math.min(gone, zAtScale(info, scaleAtZ(info, gone) / LINE_RAMP_SCALE)));
    }
    return { tx, ty, from };
  });
}

/** Every segment of the line (lineSegments) with how its ends glide. */
export function glidingSegments(l: LineRecord, info: ScaleInfo): GlidingSegment[] {
  const glides = lineGlides(l, info);
  return lineSegments(l).map((s) => {
    const g = glides[s.path]!, leave = l.leaveZ[s.path]!;
    return {
      ...s,
      atx: g.tx[s.a]!, aty: g.ty[s.a]!, aFrom: g.from[s.a]!, aTo: leave[s.a]!,
      btx: g.tx[s.b]!, bty: g.ty[s.b]!, bFrom: g.from[s.b]!, bTo: leave[s.b]!,
    };
  });
}

/** How far along its glide a vertex is at z: 0 before `from`, 1 at `to`, linear between. */
export function glideShare(from: number, to: number, z: number): number {
  if (!(to > from)) return z >= to ? 1 : 0;
  return Math.max(0, Math.min(1, (z - from) / (to - from)));
}

/** The segment's ends at z: [ax, ay, bx, by]. */
export function segmentAt(s: GlidingSegment, z: number): [number, number, number, number] {
  const ga = glideShare(s.aFrom, s.aTo, z), gb = glideShare(s.bFrom, s.bTo, z);
  return [s.ax + (s.atx - s.ax) * ga, s.ay + (s.aty - s.ay) * ga, s.bx + (s.btx - s.bx) * gb, s.by + (s.bty - s.by) * gb];
}
