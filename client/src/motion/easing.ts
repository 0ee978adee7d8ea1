// Easing curves for the map's animations (cubic Béziers, as in CSS), and the curve that
// continues a running animation at the speed it had, so a new wheel click does not stall it.
import bezier from 'bezier-easing';

export type Easing = (t: number) => number;

export const linear: Easing = (t) => t;
/** Accelerates, then decelerates (the seed paper's "lift" curve for zooming and panning). */
export const easeInOut: Easing = bezier(0.42, 0, 0.58, 1);
/** Pan inertia: starts at the release speed and slows to a stop (MapLibre's curve). */
export const inertiaEasing: Easing = bezier(0, 0, 0.3, 1);

/** Slope of an easing at t (progress per unit of t), by a small forward difference. */
export function easingSpeed(e: Easing, t: number): number {
  const h = 0.01;
  const t0 = Math.min(Math.max(t, 0), 1 - h);
  return (e(t0 + h) - e(t0)) / h;
}

/**
 * An ease-out curve whose initial slope is `speed` (progress per unit of t), for an animation
 * that takes over from a running one: the motion keeps its pace instead of starting from rest.
 * A slope of 0 gives a plain ease-in-out.
 */
export function continuingEasing(speed: number): Easing {
  if (!(speed > 0.05)) return easeInOut;
  // The first control point sets the initial slope y1 / x1; 0.27 is its distance (MapLibre's).
  const len = 0.27;
  const x1 = len / Math.sqrt(1 + speed * speed);
  const y1 = Math.min(1, x1 * speed);
  return bezier(x1, y1, 0.25, 1);
}
