// How long a view must rest before its prefetch margin is fetched, from the pace at which views
// have been coming. During a zoom or a pan each view's margin is soon left behind. On a device
// whose frames take longer than the fixed rest (a slow phone, a software GPU), every view of a
// zoom rested that long and fetched its margin (bench:session, nlcd_zion with 393 ms frames:
// 4.94 MB, of which 3.93 its views' own chunks). A view has rested once it has outlasted the
// pace of the views before it.

/** A gap between views longer than this is a pause, not the pace of a motion (ms). */
export const PAUSE_MS = 1000;
/** A view has rested once it has lasted this many times the motion's pace. */
export const PACE_FACTOR = 1.5;
/** The gaps remembered. */
const KEPT = 3;

export class ViewCadence {
  private last: number | null = null;
  private readonly gaps: number[] = [];

  /** A new view came at time `t` (ms). */
  viewAt(t: number): void {
    if (this.last !== null) {
      this.gaps.push(t - this.last);
      if (this.gaps.length > KEPT) this.gaps.shift();
    }
    this.last = t;
  }

  /**
   * The rest a view needs: `minimum`, or longer when the last views came in a motion slower than
   * that (the longest of the last gaps that were not pauses, times PACE_FACTOR).
   */
  restMs(minimum: number): number {
    let pace = 0;
    for (const g of this.gaps) if (g < PAUSE_MS && g > pace) pace = g;
    return Math.max(minimum, PACE_FACTOR * pace);
  }
}
