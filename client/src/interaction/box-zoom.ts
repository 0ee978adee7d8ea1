// Shift-drag a box: on release the map zooms to show it whole. Escape cancels.
import { lerpCamera } from '../geometry/camera.js';
import { InputHandler, type ListenerSpec } from './interaction-context.js';

const MIN_BOX_PX = 3;

export class BoxZoom extends InputHandler {
  private start: { id: number; p: [number, number] } | null = null;
  private box: HTMLElement | null = null;

  protected listeners(): ListenerSpec[] {
    return [...this.pointerListeners(this.onDown, this.onMove, this.onUp, this.cancel), ['keydown', this.onKey as EventListener]];
  }

  protected override reset(): void {
    this.cancel();
  }

  private readonly onDown = (ev: PointerEvent): void => {
    if (ev.pointerType !== 'mouse' || ev.button !== 0 || !ev.shiftKey) return;
    ev.preventDefault();
    this.ctx.view.stop(ev);
    this.start = { id: ev.pointerId, p: this.ctx.point(ev) };
    try {
      this.ctx.element.setPointerCapture(ev.pointerId);
    } catch {
      // Works uncaptured too.
    }
  };

  private readonly onMove = (ev: PointerEvent): void => {
    const s = this.start;
    if (!s || s.id !== ev.pointerId) return;
    const p = this.ctx.point(ev);
    if (!this.box) {
      this.box = document.createElement('div');
      this.box.className = 'vario-map-boxzoom';
      this.ctx.element.appendChild(this.box);
    }
    const [x0, y0, x1, y1] = [Math.min(s.p[0], p[0]), Math.min(s.p[1], p[1]), Math.max(s.p[0], p[0]), Math.max(s.p[1], p[1])];
    Object.assign(this.box.style, { left: `${x0}px`, top: `${y0}px`, width: `${x1 - x0}px`, height: `${y1 - y0}px` });
  };

  private readonly onUp = (ev: PointerEvent): void => {
    const s = this.start;
    if (!s || s.id !== ev.pointerId) return;
    const p = this.ctx.point(ev);
    this.cancel();
    const w = Math.abs(p[0] - s.p[0]), h = Math.abs(p[1] - s.p[1]);
    if (w < MIN_BOX_PX || h < MIN_BOX_PX) return;
    const [W, H] = this.ctx.size();
    const view = this.ctx.view;
    const centre: [number, number] = [(p[0] + s.p[0]) / 2, (p[1] + s.p[1]) / 2];
    const target = view.carry(this.ctx.offset(centre), [0, 0], view.camera.scale * Math.max(w / W, h / H));
    const from = view.camera;
    const st = this.ctx.settings();
    void view.animate((t) => lerpCamera(from, target, t), {
      durationMs: st.zoomDurationMs,
      minFrames: st.minZoomFrames,
      originalEvent: ev,
    });
  };

  private readonly onKey = (ev: KeyboardEvent): void => {
    if (ev.key === 'Escape' && this.start) this.cancel();
  };

  private readonly cancel = (): void => {
    this.start = null;
    this.box?.remove();
    this.box = null;
  };
}
