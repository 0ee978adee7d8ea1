// Where a class's pattern shows, in z: its scale range turned into steps. The colour pass
// compares it with the slice's z per pixel, and is compiled with patterns only when some
// pattern's range meets the slice's (a software GPU pays for the pattern code on every pixel).
import { zAtScale, type ScaleInfo } from '../../../format/scale.js';
import type { CubeStyle } from '../../../format/style.js';

type Pattern = NonNullable<CubeStyle['classes'][number]['pattern']>;

/** The z range (steps) in which a pattern shows. */
export function patternZRange(p: Pattern, info: ScaleInfo): [number, number] {
  return [p.minScale !== undefined ? zAtScale(info, p.minScale) : -1, p.maxScale !== undefined ? zAtScale(info, p.maxScale) : 1e30];
}

/** The z range of each class's pattern (classes without one left out). */
export function patternZRanges(style: CubeStyle, info: ScaleInfo): [number, number][] {
  return style.classes.flatMap((c) => (c.pattern ? [patternZRange(c.pattern, info)] : []));
}

/** Some of the pattern ranges `patternZ` meets the z range z0..z1. */
export function patternsMeet(patternZ: readonly [number, number][], z0: number, z1: number): boolean {
  return patternZ.some(([lo, hi]) => lo <= z1 && hi >= z0);
}
