// The map's click and pointermove events, with the place (longitude/latitude and projected) and
// the face under the pointer.
// A face is looked up only when someone listens, one lookup at a time (the latest position
// waits for it), and the end of a drag is not a click.
import type { Feature } from '../engine/picking.js';
import type { LngLat } from '../geo/lng-lat.js';
import { ClickFilter } from './click-filter.js';

export interface MapPointerEvent {
  /** CSS px in the map. */
  point: [number, number];
  /** The place under the pointer (null when the cube has no CRS definition: docs/embedding.md). */
  lngLat: LngLat | null;
  /** The same place in the cube's projected CRS. */
  projected: [number, number];
  /** What is on top under the pointer: a line of the cube, else the face (null: none, or not drawn yet). */
  feature: Feature | null;
  /** Everything under the pointer, topmost first: the line, if any, then the face. */
  features: Feature[];
  originalEvent: MouseEvent;
}

export interface FeatureEventHost {
  listens(type: 'click' | 'pointermove'): boolean;
  fire(type: 'click' | 'pointermove', ev: MapPointerEvent): void;
  point(ev: { clientX: number; clientY: number }): [number, number];
  unprojectProjected(point: [number, number]): [number, number];
  /** The place at a CSS px point, null when it cannot be converted (no CRS). */
  lngLatAt(point: [number, number]): LngLat | null;
  queryFeatures(point: [number, number]): Promise<Feature[]>;
}

export class FeatureEvents {
  private readonly clicks = new ClickFilter();
  private readonly query: { busy: boolean; next: PointerEvent | null } = { busy: false, next: null };
  private removed = false;

  constructor(
    private readonly element: HTMLElement,
    private readonly host: FeatureEventHost,
  ) {
    element.addEventListener('pointerdown', this.onPress);
    element.addEventListener('click', this.onClick);
    element.addEventListener('pointermove', this.onPointerMove);
  }

  remove(): void {
    this.removed = true;
    this.element.removeEventListener('pointerdown', this.onPress);
    this.element.removeEventListener('click', this.onClick);
    this.element.removeEventListener('pointermove', this.onPointerMove);
  }

  private readonly onPress = (ev: PointerEvent): void => {
    this.clicks.press(ev);
    // Focus from a pointer shows no ring, as a native click's would not: the ring is for keys.
    if (document.activeElement !== this.element) this.element.focus({ preventScroll: true, focusVisible: false });
  };

  private readonly onClick = (ev: MouseEvent): void => {
    if (!this.clicks.isClick(ev)) return;
    if (this.host.listens('click')) void this.send('click', ev);
  };

  private readonly onPointerMove = (ev: PointerEvent): void => {
    if (!this.host.listens('pointermove')) return;
    const q = this.query;
    if (q.busy) {
      q.next = ev;
      return;
    }
    q.busy = true;
    void this.send('pointermove', ev).finally(() => {
      q.busy = false;
      const next = q.next;
      q.next = null;
      if (next && !this.removed) this.onPointerMove(next);
    });
  };

  private async send(type: 'click' | 'pointermove', originalEvent: MouseEvent): Promise<void> {
    const point = this.host.point(originalEvent);
    const projected = this.host.unprojectProjected(point);
    const lngLat = this.host.lngLatAt(point);
    let features: Feature[] = [];
    try {
      features = await this.host.queryFeatures(point);
    } catch {
      // Removed meanwhile, or a failed page of attributes: the event goes without the face.
    }
    if (!this.removed) this.host.fire(type, { point, lngLat, projected, feature: features[0] ?? null, features, originalEvent });
  }
}
