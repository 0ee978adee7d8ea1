// How long this device takes to draw a frame: the shortest gap between the starts of the last
// frames drawn. Frames drawn back to back (a zoom, a chunk coming, the accumulation of a still
// view) come one frame apart; a longer gap is a pause between them, and a gap over a second
// is not counted at all. The chunk worker waits longer for a view to rest on a slow device
// (ChunkScheduler, the margin).

/** A gap between frames longer than this is a pause, not the device's pace (ms). */
export const PAUSE_MS = 1000;
/** The gaps remembered. */
const KEPT = 5;

export class FramePace {
  private last: number | null = null;
  private readonly gaps: number[] = [];

  /** A frame was drawn, starting at `t` (ms). */
  frameAt(t: number): void {
    if (this.last !== null && t - this.last < PAUSE_MS) {
      this.gaps.push(t - this.last);
      if (this.gaps.length > KEPT) this.gaps.shift();
    }
    this.last = t;
  }

  /** The device's time per frame (ms); 0 until two frames came less than PAUSE_MS apart. */
  get ms(): number {
    return this.gaps.length === 0 ? 0 : Math.min(...this.gaps);
  }
}
