// The map's input handlers, made from the options and reachable by name
// (map.handlers.scrollZoom.disable()). The pointer tracker listens first, so every handler sees
// the pointers as they are after the event. Cooperative gestures (off unless asked for) decide
// which wheel events and presses the wheel zoom and the drag leave to the page.
import { BoxZoom } from './box-zoom.js';
import { CooperativeGestures } from './cooperative-gestures.js';
import { DoubleClickZoom } from './double-click-zoom.js';
import { DragPan } from './drag-pan.js';
import type { Handler, InteractionContext } from './interaction-context.js';
import { Keyboard } from './keyboard.js';
import { PointerTracker } from './pointer-tracker.js';
import { ScrollZoom } from './scroll-zoom.js';
import { TouchZoom } from './touch-zoom.js';

export interface HandlerFlags {
  scrollZoom: boolean;
  dragPan: boolean;
  keyboard: boolean;
  doubleClickZoom: boolean;
  /** Pinch zoom and two-finger pan (MapLibre's touchZoomRotate, without rotation). */
  touchZoomRotate: boolean;
  boxZoom: boolean;
}

export type HandlerName = keyof HandlerFlags;

export class Handlers {
  readonly scrollZoom: ScrollZoom;
  readonly dragPan: DragPan;
  readonly keyboard: Keyboard;
  readonly doubleClickZoom: DoubleClickZoom;
  readonly touchZoomRotate: TouchZoom;
  readonly boxZoom: BoxZoom;
  readonly cooperativeGestures: CooperativeGestures;
  private readonly tracking: PointerTracker;

  constructor(ctx: InteractionContext, flags: HandlerFlags, cooperative = false) {
    this.tracking = new PointerTracker(ctx);
    this.tracking.enable();
    this.cooperativeGestures = new CooperativeGestures(ctx);
    if (cooperative) this.cooperativeGestures.enable();
    this.scrollZoom = new ScrollZoom(ctx, this.cooperativeGestures);
    this.dragPan = new DragPan(ctx, this.cooperativeGestures);
    this.keyboard = new Keyboard(ctx);
    this.doubleClickZoom = new DoubleClickZoom(ctx);
    this.touchZoomRotate = new TouchZoom(ctx);
    this.boxZoom = new BoxZoom(ctx);
    for (const name of Object.keys(flags) as HandlerName[]) if (flags[name]) this.get(name).enable();
  }

  get(name: HandlerName): Handler {
    return this[name];
  }

  /** Turns every handler off and stops tracking pointers. */
  destroy(): void {
    for (const name of ['scrollZoom', 'dragPan', 'keyboard', 'doubleClickZoom', 'touchZoomRotate', 'boxZoom'] as const) this.get(name).disable();
    this.cooperativeGestures.disable();
    this.tracking.disable();
  }
}
