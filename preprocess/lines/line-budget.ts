// How much line a map may carry at each step: line density (mm of line on the map per mm² of
// map) held constant over scale. At 1:S, L metres of line over A m² give L·1000/S mm over
// A·1e6/S² mm², a density of L·S / (A·1000); the same density at a smaller scale allows
// length in proportion to 1/S. The scale of every step is the tGAP's (format/scale.ts: a
// constant number of faces per map area), so lines thin out as the faces do.
import { scaleAtZ, type ScaleInfo } from '../../format/scale.js';

/** Line density in mm per mm² of `lengthM` metres of line over `areaM2` m², at 1:scale. */
export function mapDensity(lengthM: number, areaM2: number, scale: number): number {
  return (lengthM * scale) / (areaM2 * 1000);
}

/** Metres of line that give `density` mm per mm² over `areaM2` m² at 1:scale. */
export function lengthAtDensity(density: number, areaM2: number, scale: number): number {
  return (density * areaM2 * 1000) / scale;
}

/** The line length allowed at every state 0..steps (index = state) for the given density. */
export function lineBudget(info: ScaleInfo, steps: number, areaM2: number, density: number): Float64Array {
  if (!(areaM2 > 0) || !Number.isFinite(areaM2)) throw new Error(`line budget: the map's area must be a positive number of m², got ${areaM2}`);
  if (!(density >= 0) || !Number.isFinite(density)) throw new Error(`line budget: the density must be a number >= 0 (mm per mm²), got ${density}`);
  const out = new Float64Array(steps + 1);
  for (let s = 0; s <= steps; s++) out[s] = lengthAtDensity(density, areaM2, scaleAtZ(info, s));
  return out;
}
