// Drag to pan (mouse, one finger or a pen), gliding on after the release with MapLibre's
// inertia. A second finger hands the gesture to the pinch; lifting it hands it back. With
// cooperative gestures one finger is the page's.
import type { CooperativeGestures } from './cooperative-gestures.js';
import { inertiaEasing } from '../motion/easing.js';
import { InertiaBuffer } from '../motion/inertia.js';
import type { Camera } from '../geometry/camera.js';
import { resolutionAtScale } from '../geometry/view.js';
import { InputHandler, type InteractionContext, type ListenerSpec } from './interaction-context.js';

/** A mouse must move this far (CSS px) before a press becomes a drag (a click stays a click). */
const CLICK_TOLERANCE_PX = 3;

interface Drag {
  id: number;
  last: [number, number];
  start: [number, number];
  moved: boolean;
}

export class DragPan extends InputHandler {
  private drag: Drag | null = null;
  private readonly inertia = new InertiaBuffer();

  constructor(
    ctx: InteractionContext,
    private readonly cooperative: CooperativeGestures,
  ) {
    super(ctx);
  }

  protected listeners(): ListenerSpec[] {
    return this.pointerListeners(this.onDown, this.onMove, this.onUp);
  }

  protected override reset(): void {
    if (this.drag?.moved) this.ctx.view.end();
    this.drag = null;
    this.inertia.clear();
  }

  /** True while a drag is moving the map (a click that follows is not a click). */
  get dragging(): boolean {
    return this.drag?.moved ?? false;
  }

  private readonly onDown = (ev: PointerEvent): void => {
    if (ev.pointerType === 'mouse' && (ev.button !== 0 || ev.shiftKey)) return; // shift-drag: box zoom
    if (!this.cooperative.dragPans(ev)) return;
    if (this.ctx.pointers.touches().length > 1) {
      // A second finger: the pinch takes over from here.
      this.drag = null;
      this.inertia.clear();
      return;
    }
    this.ctx.view.stop(ev);
    this.begin(ev);
  };

  private begin(ev: PointerEvent): void {
    const p = this.ctx.point(ev);
    this.drag = { id: ev.pointerId, last: p, start: p, moved: false };
    this.inertia.clear();
    this.inertia.push({ time: performance.now(), x: p[0], y: p[1] });
    if (ev.type === 'pointerdown') {
      try {
        this.ctx.element.setPointerCapture(ev.pointerId);
      } catch {
        // A synthetic pointer cannot be captured; the drag works without.
      }
    }
  }

  private readonly onMove = (ev: PointerEvent): void => {
    const d = this.drag;
    if (!d) {
      // The pinch ended with one finger still down: it pans on from where it is.
      if (ev.pointerType === 'touch' && this.ctx.pointers.down.has(ev.pointerId) && this.ctx.pointers.touches().length === 1 && this.cooperative.dragPans(ev)) this.begin(ev);
      return;
    }
    if (d.id !== ev.pointerId) return;
    const p = this.ctx.point(ev);
    if (!d.moved && ev.pointerType === 'mouse' && Math.hypot(p[0] - d.start[0], p[1] - d.start[1]) < CLICK_TOLERANCE_PX) return;
    d.moved = true;
    const view = this.ctx.view;
    view.set(view.carry(this.ctx.offset(d.last), this.ctx.offset(p), view.camera.scale), ev);
    this.inertia.push({ time: performance.now(), x: p[0], y: p[1] });
    d.last = p;
  };

  private readonly onUp = (ev: PointerEvent): void => {
    const d = this.drag;
    if (!d || d.id !== ev.pointerId) return;
    this.drag = null;
    if (!d.moved) return;
    const glide = ev.type === 'pointerup' && this.ctx.settings().panDurationMs > 0 ? this.inertia.release(performance.now()) : null;
    this.inertia.clear();
    const view = this.ctx.view;
    if (!glide) {
      view.end(ev);
      return;
    }
    const from: Camera = view.camera;
    const res = resolutionAtScale(from.scale, this.ctx.pixelSizeMm());
    void view.animate((t) => ({ x: from.x - glide.dx * t * res, y: from.y + glide.dy * t * res, scale: from.scale }), { durationMs: glide.durationMs, easing: inertiaEasing, originalEvent: ev });
  };
}
