// Mouse wheels and trackpads send the same wheel events; they are told apart as MapLibre does
// (a delta under 4 is a trackpad; a multiple of 4.000244140625 is a Mac mouse wheel; else the
// rhythm of the first events decides) because a wheel click is one discrete zoom step while a
// trackpad streams small deltas that should zoom continuously. Pure: time is passed in.

export type WheelKind = 'wheel' | 'trackpad';

/** Delta of one mouse wheel notch in Chromium and Edge (pixel mode). */
export const WHEEL_CLICK_DELTA = 100;
/** macOS mouse wheels send multiples of this. */
export const MAC_WHEEL_DELTA = 4.000244140625;
/** A first event after this long a pause starts a new gesture whose kind is not yet known. */
export const NEW_GESTURE_MS = 400;
/** How long to wait for a second event before calling a lone first event a wheel click. */
export const CLASSIFY_WAIT_MS = 40;
/** Trackpad: log2 of the scale change per delta unit (MapLibre's trackpad rate, 1/100). */
export const TRACKPAD_RATE = 1 / 100;

/** The event's delta in pixels: lines and pages as Chromium would send for the same notch. */
export function wheelDeltaPx(deltaY: number, deltaMode: number): number {
  if (deltaMode === 1) return (deltaY * WHEEL_CLICK_DELTA) / 3; // Firefox: 3 lines a notch
  if (deltaMode === 2) return deltaY * WHEEL_CLICK_DELTA;
  return deltaY;
}

export interface WheelInput {
  kind: WheelKind;
  /** Pixels; positive zooms out (as scrolling down does). */
  delta: number;
}

export class WheelClassifier {
  private kind: WheelKind | null = null;
  private lastTime = -Infinity;
  private pendingDelta = 0;
  private pending = false;

  /**
   * Classifies one event. Returns null when the kind cannot be told yet: the caller waits
   * CLASSIFY_WAIT_MS and then calls flush(), unless another event comes first.
   */
  push(delta: number, now: number): WheelInput | null {
    const dt = now - this.lastTime;
    this.lastTime = now;
    let value = delta;
    if (value !== 0 && value % MAC_WHEEL_DELTA === 0) {
      this.kind = 'wheel';
    } else if (value !== 0 && Math.abs(value) < 4) {
      this.kind = 'trackpad';
    } else if (dt > NEW_GESTURE_MS) {
      this.kind = null;
      this.pending = true;
      this.pendingDelta = value;
      return null;
    } else if (this.kind === null) {
      // A second event soon after the first: a trackpad streams many small ones quickly.
      this.kind = Math.abs(dt * value) < 200 ? 'trackpad' : 'wheel';
    }
    if (this.pending) {
      value += this.pendingDelta;
      this.pending = false;
      this.pendingDelta = 0;
    }
    return { kind: this.kind ?? 'wheel', delta: value };
  }

  /** No second event came: the waiting first one was a wheel click. */
  flush(): WheelInput | null {
    if (!this.pending) return null;
    this.pending = false;
    this.kind = 'wheel';
    const delta = this.pendingDelta;
    this.pendingDelta = 0;
    return { kind: 'wheel', delta };
  }
}

/**
 * log2 of the factor the scale denominator changes by (positive: zoom out). A wheel notch is one
 * zoom step (the seed paper's prototype: a factor 2 by default); a trackpad zooms continuously.
 */
export function wheelZoomLevels(input: WheelInput, zoomStepFactor: number): number {
  if (input.kind === 'trackpad') return input.delta * TRACKPAD_RATE;
  const step = Math.log2(zoomStepFactor);
  // A macOS wheel event is one notch whatever its size; elsewhere a notch is 100 pixels.
  const clicks = input.delta % MAC_WHEEL_DELTA === 0 ? Math.sign(input.delta) : input.delta / WHEEL_CLICK_DELTA;
  return clicks * step;
}
