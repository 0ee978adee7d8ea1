// What the input handlers get from the map: the element they listen on, the map's view, the
// settings of the moment and pixel helpers. Each handler is one kind of input and can be
// turned on and off on its own (map.handlers.scrollZoom.disable(), ...).
import type { MapView } from '../camera/map-view.js';
import type { StepZoom } from '../camera/step-zoom.js';
import type { Pointers } from './pointers.js';

export interface InteractionSettings {
  /** Factor of the scale denominator per zoom step (wheel click, key, button, double click). */
  zoomStep: number;
  /** ms a zoom step is eased over; 0: jumps. */
  zoomDurationMs: number;
  /** ms of keyboard pans; 0: jumps, and no inertia after a drag. */
  panDurationMs: number;
  /** A zoom step shows at least this many frames (slices), however slow the frames. */
  minZoomFrames: number;
}

export interface InteractionContext {
  /** The focusable element around the canvas; handlers listen on it. */
  readonly element: HTMLElement;
  readonly view: MapView;
  readonly stepZoom: StepZoom;
  readonly pointers: Pointers;
  settings(): InteractionSettings;
  /** CSS px of an event from the element's top left. */
  point(ev: { clientX: number; clientY: number }): [number, number];
  /** CSS px from the view's centre (x right, y down). */
  offset(p: [number, number]): [number, number];
  size(): [number, number];
  /** Paper size of a CSS pixel, mm (the cube's). */
  pixelSizeMm(): number;
}

export interface Handler {
  readonly enabled: boolean;
  enable(): void;
  disable(): void;
}

export type ListenerSpec = [type: string, fn: EventListener, options?: AddEventListenerOptions];

/**
 * A handler listening on the map's element: its listeners go on with enable() and off with
 * disable(), which also calls reset() to drop a gesture in progress.
 */
export abstract class InputHandler implements Handler {
  private on = false;
  private specs: ListenerSpec[] | null = null;

  constructor(protected readonly ctx: InteractionContext) {}

  /** The listeners (asked for on the first enable, when the subclass's fields exist). */
  protected abstract listeners(): ListenerSpec[];

  /** pointerdown, pointermove, pointerup and pointercancel (handled as up unless given). */
  protected pointerListeners(down: (ev: PointerEvent) => void, move: (ev: PointerEvent) => void, up: (ev: PointerEvent) => void, cancel = up): ListenerSpec[] {
    return [
      ['pointerdown', down as EventListener],
      ['pointermove', move as EventListener],
      ['pointerup', up as EventListener],
      ['pointercancel', cancel as EventListener],
    ];
  }

  /** Forgets a gesture in progress (on disable). */
  protected reset(): void {
    // Most handlers hold nothing between events.
  }

  get enabled(): boolean {
    return this.on;
  }

  enable(): void {
    if (this.on) return;
    this.on = true;
    this.specs ??= this.listeners();
    for (const [type, fn, o] of this.specs) this.ctx.element.addEventListener(type, fn, o);
  }

  disable(): void {
    if (!this.on) return;
    this.on = false;
    for (const [type, fn, o] of this.specs ?? []) this.ctx.element.removeEventListener(type, fn, o);
    this.reset();
  }
}
