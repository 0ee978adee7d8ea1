// Two fingers: pinch to zoom about their midpoint, move them together to pan. The ground point
// under the midpoint stays under it.
import { InputHandler, type ListenerSpec } from './interaction-context.js';
import type { TrackedPointer } from './pointers.js';

interface Pinch {
  mid: [number, number];
  dist: number;
}

export class TouchZoom extends InputHandler {
  private pinch: Pinch | null = null;

  protected listeners(): ListenerSpec[] {
    return this.pointerListeners(this.onDown, this.onMove, this.onUp);
  }

  protected override reset(): void {
    this.finish();
  }

  private measure(): Pinch | null {
    const t = this.ctx.pointers.touches();
    if (t.length < 2) return null;
    const a: TrackedPointer = t[0]!, b: TrackedPointer = t[1]!;
    return { mid: [(a.x + b.x) / 2, (a.y + b.y) / 2], dist: Math.max(1, Math.hypot(a.x - b.x, a.y - b.y)) };
  }

  private readonly onDown = (ev: PointerEvent): void => {
    if (ev.pointerType !== 'touch') return;
    const m = this.measure();
    if (!m) return;
    this.ctx.view.stop(ev);
    this.pinch = m;
  };

  private readonly onMove = (ev: PointerEvent): void => {
    if (!this.pinch || ev.pointerType !== 'touch') return;
    const m = this.measure();
    if (!m) return;
    const view = this.ctx.view;
    const scale = (view.camera.scale * this.pinch.dist) / m.dist;
    view.set(view.carry(this.ctx.offset(this.pinch.mid), this.ctx.offset(m.mid), scale), ev);
    this.pinch = m;
  };

  private readonly onUp = (ev: PointerEvent): void => {
    if (!this.pinch || ev.pointerType !== 'touch') return;
    if (this.ctx.pointers.touches().length >= 2) {
      this.pinch = this.measure();
      return;
    }
    this.finish(ev);
  };

  private finish(ev?: Event): void {
    if (!this.pinch) return;
    this.pinch = null;
    this.ctx.view.end(ev);
  }
}
