// No sudden changes (issue 11): apart from the floor, no horizontal surface should change the
// class of what is shown, for a horizontal triangle swaps its whole area at one z. Counted per
// kind of event the triangle comes from, so the count says what is left to make smooth.
import { orient } from '../geom/predicates.js';
import type { OriginKind, SurfaceOrigin, Surfaces } from './surfaces.js';

/**
 * merge, split: a merge, or a part of a split given to one face, drawn flat; mergeFlat,
 * splitFlat: a flat triangle inside one that tilts (all its corners at one z: that part of the
 * area goes at once); simplify: a removal drawn flat; reemit: a redrawn face.
 */
export type ChangeKind = 'merge' | 'mergeFlat' | 'split' | 'splitFlat' | 'simplify' | 'reemit';
export const CHANGE_KINDS: readonly ChangeKind[] = ['merge', 'mergeFlat', 'split', 'splitFlat', 'simplify', 'reemit'];

export interface HorizontalChanges {
  /** Horizontal triangles above the floor whose upper and lower faces differ in class. */
  total: number;
  byKind: Record<ChangeKind, number>;
  /** Their ground area, per kind (what the eye sees jump). */
  areaByKind: Record<ChangeKind, number>;
}

const flat = (s: Surfaces, i: number): boolean => s.z[3 * i] === s.z[3 * i + 1] && s.z[3 * i] === s.z[3 * i + 2];

/**
 * Counts the horizontal class changes of surfaces `s`, whose faces have the classes
 * `classOf` gives; `origins` (from the same build) tell the event each triangle came from.
 */
export function horizontalChanges(s: Surfaces, origins: readonly SurfaceOrigin[], classOf: (face: number) => number): HorizontalChanges {
  const byKind = Object.fromEntries(CHANGE_KINDS.map((k) => [k, 0])) as Record<ChangeKind, number>;
  const areaByKind = { ...byKind };
  let total = 0;
  const { xs, ys } = s; // the tGAP's vertices and any the build added
  for (const o of origins) {
    if (o.kind === 'floor') continue;
    let tilted = false;
    for (let i = o.first; i < o.end && !tilted; i++) tilted = !flat(s, i);
    const kind: ChangeKind = ({ merge: tilted ? 'mergeFlat' : 'merge', split: tilted ? 'splitFlat' : 'split', simplify: 'simplify', reemit: 'reemit' } as Record<Exclude<OriginKind, 'floor'>, ChangeKind>)[o.kind];
    for (let i = o.first; i < o.end; i++) {
      if (!flat(s, i)) continue;
      const up = s.upper[i]!, lo = s.lower[i]!;
      if (lo === 0 || s.z[3 * i]! <= 0 || classOf(up) === classOf(lo)) continue;
      byKind[kind]++;
      total++;
      const a = s.v[3 * i]!, b = s.v[3 * i + 1]!, c = s.v[3 * i + 2]!;
      areaByKind[kind] += Math.abs(orient(xs[a]!, ys[a]!, xs[b]!, ys[b]!, xs[c]!, ys[c]!)) / 2;
    }
  }
  return { total, byKind, areaByKind };
}
