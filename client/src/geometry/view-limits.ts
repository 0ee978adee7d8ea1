// The limits on where a map may look: the scale between a smallest and a largest denominator,
// and, when given, a ground box the visible area stays inside (MapLibre's maxBounds): the view
// cannot be panned past its edges nor zoomed out beyond the scale at which it fills the view.
// Pure and in the cube's projected coordinates, so the view applies it to every change alike.
import { resolutionAtScale, scaleAtResolution, type Bbox } from './view.js';
import type { Camera } from './camera.js';

export interface ViewLimits {
  /** Smallest scale denominator (most detail). */
  minScale: number;
  /** Largest scale denominator (Infinity: none). */
  maxScale: number;
  /** The ground box the visible area stays inside (null: anywhere). */
  maxBounds: Bbox | null;
}

/** Throws an error naming what is wrong with the limits. */
export function checkViewLimits(l: ViewLimits): void {
  if (!(Number.isFinite(l.minScale) && l.minScale > 0)) throw new Error(`minScale must be a finite number > 0, not ${l.minScale}`);
  if (!(l.maxScale >= l.minScale)) throw new Error(`maxScale (${l.maxScale}) must be at least minScale (${l.minScale})`);
  const b = l.maxBounds;
  if (b === null) return;
  if (!Array.isArray(b) || b.length !== 4 || !b.every((v) => Number.isFinite(v))) throw new Error(`maxBounds must be [x0, y0, x1, y1] of finite numbers, not ${JSON.stringify(b)}`);
  if (!(b[0] < b[2] && b[1] < b[3])) throw new Error(`maxBounds must have x0 < x1 and y0 < y1, not ${JSON.stringify(b)}`);
}

/**
 * The scale denominator within the limits for a view of `size` CSS px: with maxBounds, no larger
 * than the one at which the box fills the view. minScale wins where the box is smaller than the
 * view even at the most detail.
 */
export function limitScale(scale: number, l: ViewLimits, size: readonly [number, number], pixelSizeMm: number): number {
  let max = l.maxScale;
  const b = l.maxBounds;
  if (b) max = Math.min(max, scaleAtResolution(Math.min((b[2] - b[0]) / size[0], (b[3] - b[1]) / size[1]), pixelSizeMm));
  return Math.max(l.minScale, Math.min(scale, max));
}

/** The camera within the limits nearest `c`: its scale limited, then its view moved inside maxBounds. */
export function constrainCamera(c: Camera, l: ViewLimits, size: readonly [number, number], pixelSizeMm: number): Camera {
  const scale = limitScale(c.scale, l, size, pixelSizeMm);
  const b = l.maxBounds;
  if (!b) return { ...c, scale };
  const res = resolutionAtScale(scale, pixelSizeMm);
  return { x: inside(c.x, b[0], b[2], (size[0] * res) / 2), y: inside(c.y, b[1], b[3], (size[1] * res) / 2), scale };
}

/** A centre coordinate keeping `half` either side within [lo, hi]; the middle where it cannot. */
function inside(v: number, lo: number, hi: number, half: number): number {
  return hi - lo >= 2 * half ? Math.min(Math.max(v, lo + half), hi - half) : (lo + hi) / 2;
}
