// What a Marker and a Popup share: an element in the map's canvas container kept on a place
// (longitude/latitude). It is placed again in every frame the map draws ('render', fired in
// the same animation frame, after the view of that frame is drawn), from that frame's view, so
// it moves with the map through animations without lagging a frame behind.
import { Evented } from '../events.js';
import { CrsError } from '../geo/crs-transform.js';
import { LngLat, type LngLatLike } from '../geo/lng-lat.js';
import type { VarioMap } from '../vario-map.js';
import { offsetFor, placeElement, type Anchor, type Offset } from './overlay-position.js';

export abstract class PlacedOverlay<Events extends object> extends Evented<Events> {
  protected map: VarioMap | null = null;
  private place: LngLat | null = null;
  protected offset: Offset;

  constructor(offset: Offset) {
    super();
    this.offset = offset;
  }

  /** The element that is placed. */
  abstract getElement(): HTMLElement;

  /** The anchor for the element at this point of the map (CSS px). */
  protected abstract anchorAt(point: [number, number]): Anchor;

  getLngLat(): LngLat | null {
    return this.place;
  }

  setLngLat(lngLat: LngLatLike): this {
    this.place = LngLat.convert(lngLat);
    this.update();
    return this;
  }

  getOffset(): Offset {
    return this.offset;
  }

  setOffset(offset: Offset): this {
    this.offset = offset;
    this.update();
    return this;
  }

  protected attach(map: VarioMap): void {
    this.map = map;
    map.getCanvasContainer().appendChild(this.getElement());
    map.on('render', this.update);
    // The CRS may come after the frames have stopped (proj4 loads after the first map).
    map.on('meta', this.update);
    this.update();
  }

  protected detach(): void {
    this.map?.off('render', this.update);
    this.map?.off('meta', this.update);
    this.getElement().remove();
    this.map = null;
  }

  /** Places the element from the map's view of now. */
  protected readonly update = (): void => {
    const el = this.getElement();
    const map = this.map;
    if (!map) return;
    const p = this.place && map.getMetadata() ? projected(map, this.place) : null;
    // Without a place, before the cube is known, or on a cube without a CRS definition (the
    // map says so itself), it has nowhere to be.
    if (!p) {
      el.style.visibility = 'hidden';
      return;
    }
    const anchor = this.anchorAt(p);
    const [dx, dy] = offsetFor(anchor, this.offset);
    placeElement(el, [p[0] + dx, p[1] + dy], anchor);
    el.style.visibility = '';
  };
}

/** CSS px of the place, or null when the map cannot convert longitude/latitude. */
function projected(map: VarioMap, place: LngLat): [number, number] | null {
  try {
    return map.project(place);
  } catch (err) {
    if (err instanceof CrsError) return null;
    throw err;
  }
}
