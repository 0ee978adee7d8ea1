// Keeps ctx.pointers up to date: which pointers are down and where. Its listeners go on before
// any handler's, so the handlers see the pointers as they are after each event.
import { InputHandler, type ListenerSpec } from './interaction-context.js';

export class PointerTracker extends InputHandler {
  protected listeners(): ListenerSpec[] {
    return this.pointerListeners(this.track, this.track, this.track);
  }

  protected override reset(): void {
    this.ctx.pointers.clear();
  }

  private readonly track = (ev: PointerEvent): void => {
    const pointers = this.ctx.pointers;
    if (ev.type === 'pointerup' || ev.type === 'pointercancel') {
      pointers.release(ev.pointerId);
      return;
    }
    if (ev.type !== 'pointerdown' && !pointers.down.has(ev.pointerId)) return; // hovering
    const [x, y] = this.ctx.point(ev);
    pointers.update(ev.pointerId, x, y, ev.pointerType);
  };
}
