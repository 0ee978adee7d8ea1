// Wheel zoom about the cursor. A mouse wheel click is one zoom step (eased, many slices); a
// trackpad's stream of small deltas zooms continuously, as it comes. With cooperative gestures
// a wheel without Ctrl (or ⌘) is the page's.
import type { CooperativeGestures } from './cooperative-gestures.js';
import { CLASSIFY_WAIT_MS, WheelClassifier, wheelDeltaPx, wheelZoomLevels, type WheelInput } from '../motion/wheel.js';
import { InputHandler, type InteractionContext, type ListenerSpec } from './interaction-context.js';

/** A trackpad gesture ends after this long without an event. */
const TRACKPAD_END_MS = 200;

export class ScrollZoom extends InputHandler {
  private readonly classifier = new WheelClassifier();
  private waiting: ReturnType<typeof setTimeout> | undefined;
  private trackpadEnd: ReturnType<typeof setTimeout> | undefined;

  constructor(
    ctx: InteractionContext,
    private readonly cooperative: CooperativeGestures,
  ) {
    super(ctx);
  }

  protected listeners(): ListenerSpec[] {
    return [
      ['wheel', this.onWheel as EventListener, { passive: false }],
    ];
  }

  protected override reset(): void {
    clearTimeout(this.waiting);
    clearTimeout(this.trackpadEnd);
  }

  private readonly onWheel = (ev: WheelEvent): void => {
    if (!this.cooperative.wheelZooms(ev)) return;
    ev.preventDefault();
    // Shift turns the wheel sideways on some systems; the vertical delta is what zooms.
    const delta = wheelDeltaPx(ev.deltaY || (ev.shiftKey ? ev.deltaX : 0), ev.deltaMode);
    if (delta === 0) return;
    const offset = this.ctx.offset(this.ctx.point(ev));
    clearTimeout(this.waiting);
    const input = this.classifier.push(delta, performance.now());
    if (input) {
      this.zoom(input, offset, ev);
      return;
    }
    // Not yet known as wheel or trackpad, but input all the same: a running animation stops now.
    this.ctx.view.stop(ev);
    this.waiting = setTimeout(() => {
      const first = this.classifier.flush();
      if (first) this.zoom(first, offset, ev);
    }, CLASSIFY_WAIT_MS);
  };

  private zoom(input: WheelInput, offset: [number, number], ev: WheelEvent): void {
    const s = this.ctx.settings();
    const levels = wheelZoomLevels(input, s.zoomStep);
    const view = this.ctx.view;
    if (input.kind === 'trackpad') {
      view.stop(ev);
      view.set(view.around(view.camera.scale * Math.pow(2, levels), offset), ev);
      clearTimeout(this.trackpadEnd);
      this.trackpadEnd = setTimeout(() => view.end(), TRACKPAD_END_MS);
      return;
    }
    void this.ctx.stepZoom.by(levels, offset, { durationMs: s.zoomDurationMs, minFrames: s.minZoomFrames, originalEvent: ev });
  }
}
