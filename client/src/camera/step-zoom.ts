// Discrete zoom steps (a wheel click, a key, a button, a double click): each changes the scale
// by the zoom step factor about a point, eased over the zoom duration with at least a minimum
// number of frames. A step that comes while the last one still runs adds to its target and
// continues at the pace it had, so a quick series of clicks is one smooth zoom.
import { continuingEasing, easeInOut, easingSpeed } from '../motion/easing.js';
import type { MapView } from './map-view.js';

export interface StepOptions {
  durationMs: number;
  minFrames: number;
  originalEvent?: Event;
}

export class StepZoom {
  private target: number | null = null;
  private startScale = 0;
  private seq = 0;

  constructor(private readonly view: MapView) {}

  /** Zooms by 2^levels (positive: out) about `offset` (CSS px from the view centre). */
  by(levels: number, offset: [number, number], o: StepOptions): Promise<boolean> {
    const view = this.view;
    const running = this.target !== null && view.animating;
    const now = view.camera.scale;
    const target = view.clamp((running ? this.target! : now) * Math.pow(2, levels));
    let easing = easeInOut;
    const prog = view.progress();
    if (running && prog && prog.durationMs > 0 && o.durationMs > 0) {
      // The running step's pace in log scale per ms, as a slope of the new step's progress.
      const rate = (Math.log(this.target! / this.startScale) * easingSpeed(prog.easing, prog.t)) / prog.durationMs;
      const span = Math.log(target / now);
      if (span !== 0 && Math.sign(rate) === Math.sign(span)) easing = continuingEasing((rate * o.durationMs) / span);
    }
    const token = ++this.seq;
    this.target = target;
    this.startScale = now;
    return view.zoomAbout(target, offset, { durationMs: o.durationMs, minFrames: o.minFrames, easing, originalEvent: o.originalEvent }).then((done) => {
      if (this.seq === token) this.target = null;
      return done;
    });
  }
}
