// No sudden changes (issue 11): apart from the floor, no horizontal surface should change the
// class of what is shown, for a horizontal triangle swaps its whole area at one z. Counted per
// kind of event the triangle comes from, so the count says what is left to make smooth.
import { faceEndZ, REEMIT_PHASE, type Tgap } from '../../format/tgap-model.js';
import type { MergeTransition, Surfaces } from './surfaces.js';

/**
 * merge: a merge drawn flat; mergeFlat: a flat triangle inside a tilted merge (all its corners
 * at the ramp's foot, on the shared boundary, or at its top): that part of the loser goes at once.
 */
export type ChangeKind = 'merge' | 'mergeFlat' | 'split' | 'simplify' | 'reemit';
export const CHANGE_KINDS: readonly ChangeKind[] = ['merge', 'mergeFlat', 'split', 'simplify', 'reemit'];

export interface HorizontalChanges {
  /** Horizontal triangles above the floor whose upper and lower faces differ in class. */
  total: number;
  byKind: Record<ChangeKind, number>;
  /** Their ground area, per kind (what the eye sees jump). */
  areaByKind: Record<ChangeKind, number>;
}

/**
 * Counts the horizontal class changes of surfaces `s` built from `t`; `transitions` (from the
 * same build) tell a merge's triangles (first..end). Otherwise a triangle whose lower face ends at its z by a replacement is a
 * re-emit, by a split a split; any other (the lower face lives on) moves a boundary: simplification.
 */
export function horizontalChanges(t: Tgap, s: Surfaces, transitions: readonly MergeTransition[]): HorizontalChanges {
  const merges = new Map<number, MergeTransition>();
  for (const m of transitions) merges.set(m.loser, m);
  const byKind = Object.fromEntries(CHANGE_KINDS.map((k) => [k, 0])) as Record<ChangeKind, number>;
  const areaByKind = { ...byKind };
  let total = 0;
  const { faces, xs, ys } = t;
  for (let i = 0; i < s.count; i++) {
    const z = s.z[3 * i]!;
    if (z !== s.z[3 * i + 1] || z !== s.z[3 * i + 2]) continue;
    const up = s.upper[i]!, lo = s.lower[i]!;
    if (lo === 0 || z <= 0) continue; // the floor
    if (faces[up]!.classIndex === faces[lo]!.classIndex) continue;
    const face = faces[lo]!;
    const m = merges.get(lo);
    const ended = z === faceEndZ(face, t.meta.steps);
    let kind: ChangeKind = 'simplify';
    if (m && i >= m.first && i < m.end) kind = m.tilted ? 'mergeFlat' : 'merge';
    else if (ended && face.endPhase === REEMIT_PHASE) kind = 'reemit';
    else if (ended && face.mergedInto < 0) kind = 'split';
    byKind[kind]++;
    total++;
    const a = s.v[3 * i]!, b = s.v[3 * i + 1]!, c = s.v[3 * i + 2]!;
    areaByKind[kind] += Math.abs((xs[b]! - xs[a]!) * (ys[c]! - ys[a]!) - (xs[c]! - xs[a]!) * (ys[b]! - ys[a]!)) / 2;
  }
  return { total, byKind, areaByKind };
}
