// Marker, as MapLibre GL JS's: an element (by default a pin) kept on a place through every
// movement of the map, optionally with a Popup that a click or Enter toggles.
import type { LngLatLike } from '../geo/lng-lat.js';
import type { VarioMap } from '../vario-map.js';
import { createPin, PIN_HEIGHT_PX } from './marker-pin.js';
import type { Anchor, Offset } from './overlay-position.js';
import { PlacedOverlay } from './placed-overlay.js';
import type { Popup } from './popup.js';

export interface MarkerOptions {
  /** Your own element (default: a pin in `color`). */
  element?: HTMLElement;
  /** The point of the element on the place (default: 'bottom' for the pin, its tip; else 'center'). */
  anchor?: Anchor;
  /** CSS px: [x, y], or a distance away from the place in the anchor's direction. */
  offset?: Offset;
  /** The pin's colour (default MapLibre's #3FB1CE). */
  color?: string;
  /** Classes added to the element. */
  className?: string;
}

export class Marker extends PlacedOverlay<Record<string, never>> {
  private readonly element: HTMLElement;
  private readonly anchor: Anchor;
  /** The element is the default pin. */
  private readonly pin: boolean;
  private popup: Popup | null = null;

  constructor(options: MarkerOptions = {}) {
    super(options.offset ?? 0);
    this.anchor = options.anchor ?? (options.element ? 'center' : 'bottom');
    this.pin = !options.element;
    this.element = options.element ?? createPin(options.color ?? '#3FB1CE');
    this.element.classList.add('vario-map-marker', ...(options.className ?? '').split(/\s+/).filter((c) => c !== ''));
    if (this.pin) {
      this.element.setAttribute('role', 'img');
      this.element.setAttribute('aria-label', 'Map marker');
    }
    this.element.addEventListener('pointerdown', this.onPress);
    this.element.addEventListener('click', this.onClick);
    this.element.addEventListener('keydown', this.onKey);
  }

  getElement(): HTMLElement {
    return this.element;
  }

  addTo(map: VarioMap): this {
    this.remove();
    this.attach(map);
    return this;
  }

  remove(): this {
    this.popup?.remove();
    this.detach();
    return this;
  }

  override setLngLat(lngLat: LngLatLike): this {
    super.setLngLat(lngLat);
    this.popup?.setLngLat(lngLat);
    return this;
  }

  /** The popup a click on the marker (or Enter on it) opens and closes; null: none. */
  setPopup(popup: Popup | null): this {
    const old = this.popup;
    old?.off('open', this.onPopupOpen).off('close', this.onPopupClose).remove();
    this.popup = popup;
    const el = this.element;
    if (popup) {
      const at = this.getLngLat();
      if (at) popup.setLngLat(at);
      // Above the pin rather than over it, unless the popup says where.
      if (!popup.hasOffset() && this.anchor === 'bottom') popup.setOffset(this.pin ? PIN_HEIGHT_PX : el.offsetHeight);
      el.tabIndex = 0;
      el.setAttribute('role', 'button');
      el.setAttribute('aria-expanded', 'false');
      popup.on('open', this.onPopupOpen);
      popup.on('close', this.onPopupClose);
    } else {
      el.removeAttribute('tabindex');
      el.removeAttribute('aria-expanded');
      el.setAttribute('role', 'img');
    }
    return this;
  }

  getPopup(): Popup | null {
    return this.popup;
  }

  togglePopup(): this {
    const p = this.popup;
    if (!p || !this.map) return this;
    if (p.isOpen()) p.remove();
    else p.addTo(this.map);
    return this;
  }

  protected anchorAt(): Anchor {
    return this.anchor;
  }

  /**
   * A press on a marker with a popup is the marker's: the map's drag would capture the pointer,
   * and the click would then go to the map instead (a plain marker still lets a drag start on it).
   */
  private readonly onPress = (ev: PointerEvent): void => {
    if (this.popup) ev.stopPropagation();
  };

  private readonly onClick = (ev: MouseEvent): void => {
    if (!this.popup) return;
    // The click is the marker's: the map does not hear it (its popups would close on it).
    ev.stopPropagation();
    this.togglePopup();
  };

  private readonly onKey = (ev: KeyboardEvent): void => {
    if (!this.popup || (ev.key !== 'Enter' && ev.key !== ' ')) return;
    ev.preventDefault();
    ev.stopPropagation();
    this.togglePopup();
  };

  private readonly onPopupOpen = (): void => this.element.setAttribute('aria-expanded', 'true');
  private readonly onPopupClose = (): void => this.element.setAttribute('aria-expanded', 'false');
}
