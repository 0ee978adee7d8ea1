// Pan inertia as MapLibre computes it: the pointer's speed over the last 160 ms of a drag,
// scaled by the linearity, capped, then decelerated at a constant rate. The speed is measured
// from where the pointer was 160 ms before its last move (the latest sample at or before then),
// so that it holds where moves arrive sparsely (slow frames coalesce them). Pure: times are
// passed in.

export interface InertiaOptions {
  /** The speed is measured over about this many ms before the last move. */
  cutoffMs: number;
  linearity: number;
  /** px/s^2 */
  deceleration: number;
  /** px/s */
  maxSpeed: number;
}

export const PAN_INERTIA: InertiaOptions = { cutoffMs: 160, linearity: 0.3, deceleration: 2500, maxSpeed: 1400 };

export interface PanSample {
  /** ms */
  time: number;
  /** Pointer position, CSS px. */
  x: number;
  y: number;
}

export interface Glide {
  /** How far the map goes on after the release, CSS px. */
  dx: number;
  dy: number;
  durationMs: number;
}

/** Keeps the recent pointer positions of a drag. */
export class InertiaBuffer {
  private samples: PanSample[] = [];

  constructor(private readonly options: InertiaOptions = PAN_INERTIA) {}

  push(s: PanSample): void {
    this.samples.push(s);
    // Older than the one that starts the window is never needed again.
    const start = windowStart(this.samples, s.time - this.options.cutoffMs);
    if (start > 0) this.samples.splice(0, start);
  }

  clear(): void {
    this.samples = [];
  }

  /** The glide after a release at `now`, or null when the pointer had stopped. */
  release(now: number): Glide | null {
    const g = panInertia(this.samples, now, this.options);
    this.samples = [];
    return g;
  }
}

/** Index of the latest sample at or before `t` (0 when none is). */
function windowStart(samples: readonly PanSample[], t: number): number {
  let k = 0;
  for (let i = 0; i < samples.length; i++) if (samples[i]!.time <= t) k = i;
  return k;
}

/** The glide after a release at `now` from the drag's samples (oldest first). */
export function panInertia(samples: readonly PanSample[], now: number, o: InertiaOptions = PAN_INERTIA): Glide | null {
  const last = samples[samples.length - 1];
  // A pointer that rested before the release does not throw the map.
  if (!last || now - last.time > o.cutoffMs) return null;
  const first = samples[windowStart(samples, last.time - o.cutoffMs)]!;
  const seconds = (last.time - first.time) / 1000;
  const sx = last.x - first.x, sy = last.y - first.y;
  const amount = Math.hypot(sx, sy);
  if (amount === 0 || !(seconds > 0)) return null;
  const speed = Math.min((amount * o.linearity) / seconds, o.maxSpeed);
  const duration = speed / (o.deceleration * o.linearity);
  const distance = (speed * duration) / 2;
  return { dx: (sx / amount) * distance, dy: (sy / amount) * distance, durationMs: duration * 1000 };
}
