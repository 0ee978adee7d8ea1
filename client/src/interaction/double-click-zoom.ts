// Double click (mouse) or double tap (touch): one zoom step in about the point; with shift,
// out.
import { InputHandler, type ListenerSpec } from './interaction-context.js';

const TAP_MS = 300;
const TAP_SLOP_PX = 10;
const DOUBLE_TAP_PX = 30;

export class DoubleClickZoom extends InputHandler {
  private down: { id: number; t: number; p: [number, number] } | null = null;
  private lastTap: { t: number; p: [number, number] } | null = null;
  private lastTouch = -Infinity;

  protected listeners(): ListenerSpec[] {
    return [
      ['dblclick', this.onDblClick as EventListener],
      ['pointerdown', this.onDown as EventListener],
      ['pointerup', this.onUp as EventListener],
    ];
  }

  private zoom(p: [number, number], out: boolean, ev: Event): void {
    const s = this.ctx.settings();
    const levels = Math.log2(s.zoomStep) * (out ? 1 : -1);
    void this.ctx.stepZoom.by(levels, this.ctx.offset(p), { durationMs: s.zoomDurationMs, minFrames: s.minZoomFrames, originalEvent: ev });
  }

  private readonly onDblClick = (ev: MouseEvent): void => {
    // A browser may also send dblclick for a double tap: the taps have zoomed already.
    if (ev.timeStamp - this.lastTouch < 1000) return;
    ev.preventDefault();
    this.zoom(this.ctx.point(ev), ev.shiftKey, ev);
  };

  private readonly onDown = (ev: PointerEvent): void => {
    if (ev.pointerType !== 'touch') return;
    // Events' own times: on a busy page they are handled late, and a tap would read as a press.
    this.lastTouch = ev.timeStamp;
    this.down = this.ctx.pointers.touches().length > 1 ? null : { id: ev.pointerId, t: ev.timeStamp, p: this.ctx.point(ev) };
    if (!this.down) this.lastTap = null;
  };

  private readonly onUp = (ev: PointerEvent): void => {
    if (ev.pointerType !== 'touch') return;
    this.lastTouch = ev.timeStamp;
    const d = this.down;
    this.down = null;
    if (!d || d.id !== ev.pointerId) return;
    const p = this.ctx.point(ev);
    if (ev.timeStamp - d.t > TAP_MS || Math.hypot(p[0] - d.p[0], p[1] - d.p[1]) > TAP_SLOP_PX) {
      this.lastTap = null;
      return;
    }
    const last = this.lastTap;
    if (last && ev.timeStamp - last.t < TAP_MS && Math.hypot(p[0] - last.p[0], p[1] - last.p[1]) < DOUBLE_TAP_PX) {
      this.lastTap = null;
      this.zoom(last.p, false, ev);
      return;
    }
    this.lastTap = { t: ev.timeStamp, p };
  };
}
