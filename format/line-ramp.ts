// How wide a cube line is drawn at a z, as a share of its style's width: lines appear and go
// smoothly (issue 12, item 2). A line grows from nothing over the first half zoom level of its
// scale range (its face narrows meanwhile, so the handover from area to line shows no jump) and
// shrinks to nothing over the last (it is pruned, or its style's scale range ends), instead of
// popping in and out whole. The same rule for the GPU's line pass, the CPU reference drawer and
// picking, so that all three agree pixel for pixel.
//
// Each end of the range ramps linearly in z, from 0 at the end to 1 where the scale is half a
// zoom level (a factor of sqrt 2) inside it. A line's own range and its rule's scale range
// ramp separately and the smaller factor holds: both are known apart (the line in its chunk,
// the rule in the style, which may change at run time), and their minimum is still 0 at
// whichever end comes first. An end at the cube's floor or top (or none) does not ramp: a line
// there is on the map from the first state or to the last.
import { scaleAtZ, zAtScale, type ScaleInfo } from './scale.js';

/** A zoom level is a factor of 2 in scale; the ramps take half of one. */
export const LINE_RAMP_SCALE = Math.SQRT2;

/** A z range [z0, z1) and where inside it the width is full: [z0Full, z1Full]. */
export interface LineRamp {
  z0: number;
  z0Full: number;
  z1Full: number;
  z1: number;
}

/** The ramp of a line or a rule on the map for z0 <= z < z1 (infinite ends: none). */
export function lineRamp(info: ScaleInfo, z0: number, z1: number): LineRamp {
  const floor = 0, top = info.zMax;
  const z0Full = z0 > floor && Number.isFinite(z0) ? Math.min(z1, zAtScale(info, scaleAtZ(info, z0) * LINE_RAMP_SCALE)) : z0;
  const z1Full = z1 < top && Number.isFinite(z1) ? Math.max(z0, zAtScale(info, scaleAtZ(info, z1) / LINE_RAMP_SCALE)) : z1;
  return { z0, z0Full, z1Full, z1 };
}

/** The ramp of a style rule's scale range (format/line-style.ts), which a denominator bounds from below in z. */
export function ruleRamp(info: ScaleInfo, r: { minScale?: number | undefined; maxScale?: number | undefined }): LineRamp {
  return lineRamp(info, r.minScale !== undefined ? zAtScale(info, r.minScale) : -Infinity, r.maxScale !== undefined ? zAtScale(info, r.maxScale) : Infinity);
}

/** The share of the full width drawn at z by one ramp: 0 outside [z0, z1), 1 between the full points. */
export function rampShare(r: LineRamp, z: number): number {
  if (!(z >= r.z0 && z < r.z1)) return 0;
  const grow = r.z0Full > r.z0 ? (z - r.z0) / (r.z0Full - r.z0) : 1;
  const shrink = r.z1 > r.z1Full ? (r.z1 - z) / (r.z1 - r.z1Full) : 1;
  return Math.max(0, Math.min(1, grow, shrink));
}

/** The share of its width a line is drawn with at z: the smaller of its own ramp and its rule's. */
export const lineWidthShare = (line: LineRamp, rule: LineRamp, z: number): number => Math.min(rampShare(line, z), rampShare(rule, z));
