// One camera animation at a time, advanced by the map's frame loop. A new one (or any input)
// takes over from wherever the running one has got to, so nothing jumps. `minFrames` makes a
// zoom show at least that many content steps even where frames are slow: the animation then
// takes longer rather than skipping slices (the seed paper's "many small steps per zoom").
import type { Camera } from '../geometry/camera.js';
import type { Easing } from '../motion/easing.js';

export interface AnimationSpec {
  /** Camera at eased progress p in [0, 1]. */
  path: (p: number) => Camera;
  durationMs: number;
  easing: Easing;
  /** Fewest frames from start to end (0: as many as time allows). */
  minFrames?: number;
  /** Called once with true at the end, false when something else took over. */
  done?: (completed: boolean) => void;
}

interface Running {
  spec: AnimationSpec;
  start: number;
  t: number;
}

export class CameraAnimation {
  private running: Running | null = null;

  get active(): boolean {
    return this.running !== null;
  }

  /** Starts `spec` at `now`, ending the running one (its done(false) is called). */
  start(spec: AnimationSpec, now: number): void {
    this.stop();
    this.running = { spec, start: now, t: 0 };
  }

  /** Ends the running animation where it is. */
  stop(): void {
    const r = this.running;
    this.running = null;
    r?.spec.done?.(false);
  }

  /** Time progress (0..1) and its easing of the running animation, or null. */
  progress(): { t: number; easing: Easing; durationMs: number } | null {
    const r = this.running;
    return r ? { t: r.t, easing: r.spec.easing, durationMs: r.spec.durationMs } : null;
  }

  /** Shows the frame at `now` through `apply`; false when nothing runs. */
  tick(now: number, apply: (c: Camera) => void): boolean {
    const r = this.running;
    if (!r) return false;
    const { spec } = r;
    let t = spec.durationMs > 0 ? (now - r.start) / spec.durationMs : 1;
    if (spec.minFrames && spec.minFrames > 0) t = Math.min(t, r.t + 1 / spec.minFrames);
    t = Math.min(Math.max(t, 0), 1);
    r.t = t;
    apply(spec.path(t >= 1 ? 1 : spec.easing(t)));
    // The last frame is shown before done() ends the movement.
    if (t >= 1 && this.running === r) {
      this.running = null;
      spec.done?.(true);
    }
    return true;
  }
}
