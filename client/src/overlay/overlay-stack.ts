// A map's overlay layers (one stack per map, made when the first layer is added): the order
// they are drawn in (the order added, the last on top), what the renderer draws, and the
// pointer on them. Hover (mouseenter, mousemove, mouseleave) and click are worked out on the
// CPU at once, topmost layer first, and the cursor becomes a pointer over a feature of a layer
// that listens. The map's own click event is not touched: it still fires, after the layers'
// (it waits for a face lookup); a popup opened by a layer's click stays open through it, as
// one opened in the map's click handler does.
import { engineOf } from '../engine/engine-of.js';
import { CrsError, CrsTransform } from '../geo/crs-transform.js';
import type { LngLat } from '../geo/lng-lat.js';
import { ClickFilter } from '../interaction/click-filter.js';
import type { OverlayDrawable } from '../render/overlay-pass.js';
import { localPoint } from '../ui/map-dom.js';
import type { VarioMap } from '../vario-map.js';

/** Where the pointer is, for a layer's events. */
export interface PointerPlace {
  /** CSS px in the map. */
  point: [number, number];
  /** Null when the cube has no CRS definition. */
  lngLat: LngLat | null;
  /** In the cube's projected CRS. */
  projected: [number, number];
  originalEvent: MouseEvent;
}

/** What the stack needs of a layer. */
export interface StackedLayer {
  drawable(): OverlayDrawable;
  /**
   * The pointer moved to `place` (or `left` the map there). True when it is over a feature the
   * layer answers for (interactive, with listeners): the cursor is a pointer.
   */
  hover(place: PointerPlace, left: boolean): boolean;
  click(place: PointerPlace): void;
  /** The map is going: the layer is off it. */
  detached(): void;
}

const stacks = new WeakMap<VarioMap, OverlayStack>();

/** The click whose layer events are being fired, while they are. */
let clickInHand: MouseEvent | null = null;

/**
 * The click the layers are answering now (null when none): a popup opened in a layer's click
 * handler is not closed by the map's click event of that same click, which comes after.
 */
export function clickBeingAnswered(): MouseEvent | null {
  return clickInHand;
}

export class OverlayStack {
  private readonly layers: StackedLayer[] = [];
  private readonly clicks = new ClickFilter();
  private readonly element: HTMLElement;
  private crs: CrsTransform | null = null;

  private constructor(private readonly map: VarioMap) {
    this.element = map.getCanvasContainer();
    this.element.addEventListener('pointerdown', this.onPress);
    this.element.addEventListener('pointermove', this.onMove);
    this.element.addEventListener('pointerleave', this.onLeave);
    this.element.addEventListener('click', this.onClick);
    map.on('remove', this.onMapRemove);
  }

  static of(map: VarioMap): OverlayStack {
    let s = stacks.get(map);
    if (!s) stacks.set(map, (s = new OverlayStack(map)));
    return s;
  }

  /** On top of the others. */
  add(layer: StackedLayer): void {
    this.layers.push(layer);
    this.changed();
  }

  remove(layer: StackedLayer): void {
    const i = this.layers.indexOf(layer);
    if (i < 0) return;
    this.layers.splice(i, 1);
    this.changed();
    this.setCursor(false);
  }

  /** A layer's data or paint changed: the map shows it at the next frame. */
  changed(): void {
    engineOf(this.map).setOverlays(this.layers.map((l) => l.drawable()));
  }

  /** A layer's geometry is still coming: the map is not idle before it has. */
  holdIdle(coming: Promise<void>): void {
    engineOf(this.map).holdIdle(coming);
  }

  /** Longitude/latitude to the cube's CRS; a CrsError when the cube has none (or is not known yet). */
  toProjected(): CrsTransform {
    const meta = this.map.getMetadata();
    if (!meta) throw new CrsError("longitude/latitude need the cube's CRS: wait for the map's 'meta' event");
    this.crs ??= CrsTransform.of(meta, this.map.getSourceUrl());
    return this.crs;
  }

  private place(ev: MouseEvent): PointerPlace {
    const point = localPoint(this.element, ev);
    let lngLat: LngLat | null = null;
    try {
      lngLat = this.map.unproject(point);
    } catch (err) {
      if (!(err instanceof CrsError)) throw err;
    }
    return { point, lngLat, projected: this.map.unprojectProjected(point), originalEvent: ev };
  }

  /** The layers, topmost first. */
  private topDown(): StackedLayer[] {
    return this.layers.slice().reverse();
  }

  private setCursor(pointer: boolean): void {
    this.map.getCanvas().style.cursor = pointer ? 'pointer' : '';
  }

  private readonly onPress = (ev: PointerEvent): void => {
    this.clicks.press(ev);
  };

  private readonly onMove = (ev: PointerEvent): void => {
    // Hover is for a mouse or pen; a finger's moves are drags.
    if (this.layers.length === 0 || ev.pointerType === 'touch' || !this.map.getMetadata()) return;
    const at = this.place(ev);
    let over = false;
    for (const l of this.topDown()) if (l.hover(at, false)) over = true;
    this.setCursor(over);
  };

  private readonly onLeave = (ev: PointerEvent): void => {
    if (!this.map.getMetadata()) return;
    const at = this.place(ev);
    for (const l of this.topDown()) l.hover(at, true);
    this.setCursor(false);
  };

  private readonly onClick = (ev: MouseEvent): void => {
    if (!this.clicks.isClick(ev) || this.layers.length === 0 || !this.map.getMetadata()) return;
    const at = this.place(ev);
    clickInHand = ev;
    try {
      for (const l of this.topDown()) l.click(at);
    } finally {
      clickInHand = null;
    }
  };

  private readonly onMapRemove = (): void => {
    this.element.removeEventListener('pointerdown', this.onPress);
    this.element.removeEventListener('pointermove', this.onMove);
    this.element.removeEventListener('pointerleave', this.onLeave);
    this.element.removeEventListener('click', this.onClick);
    for (const l of this.layers.splice(0)) l.detached();
    stacks.delete(this.map);
  };
}
