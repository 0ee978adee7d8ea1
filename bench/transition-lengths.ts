// How long the transitions of a cube last in scale (issue 11, "Transitions long enough to see"):
// per merge or split event the ratio S(end)/S(start) of the scales at which its change starts
// and ends, summarised as the median and 10th percentile, and as the number of frames of a
// default zoom step that show the median event part-way. Any cube can report these from the z
// range of its events: the classic cube's ranges come from classicTransitions, the smooth
// cube's from smoothTransitions with the merge and split transitions its build (buildSurfaces)
// returns.
import { scaleAtZ, type ScaleInfo } from '../format/scale.js';
import { EventKind, LAST_REMOVAL_PHASE, phaseZ, type TgapEvent } from '../format/tgap-model.js';
import type { MergeTransition, SplitTransition } from '../preprocess/ssc/surfaces.js';
import { median, percentile } from './stats.js';

/** A default zoom step: x2 in scale over 10 frames (issue 11). */
export const FRAMES_PER_ZOOM_STEP = 10;

/** The z range over which one event's change is seen. */
export interface Transition {
  zStart: number;
  zEnd: number;
}

/**
 * In the classic cube an event of step k lives inside its own step: the merge or split at phase
 * 0, the simplification of the boundaries it changed up to the last removal phase (re-draws at
 * phase 7 show nothing new). The merge itself is one horizontal surface, so this is the most a
 * classic event can be said to last.
 */
export function classicTransitions(events: readonly Pick<TgapEvent, 'kind' | 'step'>[]): Transition[] {
  return events
    .filter((e) => e.kind === EventKind.Merge || e.kind === EventKind.Split)
    .map((e) => ({ zStart: phaseZ(e.step, 0), zEnd: phaseZ(e.step, LAST_REMOVAL_PHASE) }));
}

/**
 * The smooth cube's events: a tilted merge lasts its transition, from zStart to the merge, and
 * a split from where its first part starts to the split; a merge or split drawn flat lasts as
 * in the classic cube.
 */
export function smoothTransitions(
  events: readonly Pick<TgapEvent, 'kind' | 'step' | 'loser'>[], merges: readonly Pick<MergeTransition, 'step' | 'loser' | 'zStart' | 'zMerge' | 'tilted' | 'held'>[], splits: readonly SplitTransition[],
): Transition[] {
  const tilted = new Map<number, { step: number; zStart: number; zEnd: number }>();
  for (const m of merges) if (m.tilted || m.held) tilted.set(m.loser, { step: m.step, zStart: m.zStart, zEnd: m.zMerge });
  for (const p of splits) if (p.zStart < p.zSplit) tilted.set(p.loser, { step: p.step, zStart: p.zStart, zEnd: p.zSplit });
  return events.flatMap((e) => {
    const m = e.kind === EventKind.Merge || e.kind === EventKind.Split ? tilted.get(e.loser) : undefined;
    if (m && m.step !== e.step) throw new Error(`the ${e.kind === EventKind.Merge ? 'merge' : 'split'} of face ${e.loser} is at step ${e.step}, its transition at step ${m.step}`);
    return m ? [{ zStart: m.zStart, zEnd: m.zEnd }] : classicTransitions([e]);
  });
}

/** S(end)/S(start) of each transition, with the scales the map gives those z. */
export function scaleRatios(transitions: readonly Transition[], info: ScaleInfo): number[] {
  return transitions.map((t) => scaleAtZ(info, t.zEnd) / scaleAtZ(info, t.zStart));
}

export interface TransitionLengths {
  events: number;
  median: number;
  p10: number;
  /** Frames of a default zoom step over which the median event is part-way: 10 log2(median). */
  framesAtMedian: number;
}

/** The summary of the ratios (NaN figures when there are none). */
export function transitionLengths(ratios: readonly number[]): TransitionLengths {
  if (ratios.length === 0) return { events: 0, median: NaN, p10: NaN, framesAtMedian: NaN };
  const m = median([...ratios]);
  return { events: ratios.length, median: m, p10: percentile([...ratios], 0.1), framesAtMedian: FRAMES_PER_ZOOM_STEP * Math.log2(m) };
}
