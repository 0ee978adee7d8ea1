// Popup, as MapLibre GL JS's: a box of text or HTML with a tip pointing at a place, kept there
// through every movement of the map; a close button, and closed by a click on the map
// (closeOnClick; not by the click that opened it, when a GeoJSON layer's click handler did).
// Its anchor is chosen to keep it inside the map unless one is given.
import type { VarioMap } from '../vario-map.js';
import type { MapPointerEvent } from '../interaction/feature-events.js';
import { clickBeingAnswered } from './overlay-stack.js';
import { autoAnchor, type Anchor, type Offset } from './overlay-position.js';
import { PlacedOverlay } from './placed-overlay.js';

export interface PopupOptions {
  /** A close button in the corner (default true). */
  closeButton?: boolean;
  /** A click on the map closes it (default true). */
  closeOnClick?: boolean;
  /** Where the tip is (default: chosen to keep the popup in the map, 'bottom' if it fits). */
  anchor?: Anchor;
  /** CSS px: [x, y], or a distance away from the place in the anchor's direction (default 0). */
  offset?: Offset;
  /** Classes added to the popup's element. */
  className?: string;
  /** CSS max-width of the popup (default '240px'). */
  maxWidth?: string;
  /** Focuses the first focusable element in it (the close button) when it opens (default true). */
  focusAfterOpen?: boolean;
}

export interface PopupEvents {
  open: Record<string, never>;
  close: Record<string, never>;
}

const ANCHORS: Anchor[] = ['center', 'top', 'bottom', 'left', 'right', 'top-left', 'top-right', 'bottom-left', 'bottom-right'];

export class Popup extends PlacedOverlay<PopupEvents> {
  private readonly options: PopupOptions;
  private readonly offsetGiven: boolean;
  private readonly element: HTMLElement;
  private readonly content: HTMLElement;
  private anchorShown: Anchor | null = null;
  /** The click an overlay layer's handler opened it in: the map's event of that click does not close it. */
  private openedBy: MouseEvent | null = null;

  constructor(options: PopupOptions = {}) {
    super(options.offset ?? 0);
    this.options = options;
    this.offsetGiven = options.offset !== undefined;
    const el = document.createElement('div');
    el.className = ['vario-map-popup', ...(options.className ?? '').split(/\s+/).filter((c) => c !== '')].join(' ');
    el.style.maxWidth = options.maxWidth ?? '240px';
    const tip = document.createElement('div');
    tip.className = 'vario-map-popup-tip';
    this.content = document.createElement('div');
    this.content.className = 'vario-map-popup-content';
    el.append(tip, this.content);
    // What happens in the popup (selecting its text, a link, the close button) is not the map's.
    for (const type of ['pointerdown', 'click', 'dblclick'] as const) el.addEventListener(type, (e) => e.stopPropagation());
    this.element = el;
  }

  getElement(): HTMLElement {
    return this.element;
  }

  /** An offset was given (a marker then leaves it as it is). */
  hasOffset(): boolean {
    return this.offsetGiven;
  }

  isOpen(): boolean {
    return this.map !== null;
  }

  /** The content as text (nothing in it is read as HTML). */
  setText(text: string): this {
    return this.setDOMContent(document.createTextNode(text));
  }

  /** The content as HTML: yours, trusted as it is (as MapLibre's setHTML). */
  setHTML(html: string): this {
    return this.setDOMContent(document.createRange().createContextualFragment(html));
  }

  setDOMContent(node: Node): this {
    this.content.replaceChildren(node);
    if (this.options.closeButton ?? true) {
      const close = document.createElement('button');
      close.type = 'button';
      close.className = 'vario-map-popup-close-button';
      close.setAttribute('aria-label', 'Close popup');
      close.textContent = '×';
      close.addEventListener('click', () => this.remove());
      this.content.appendChild(close);
    }
    this.update();
    return this;
  }

  addTo(map: VarioMap): this {
    if (this.map) this.remove();
    this.attach(map);
    this.openedBy = clickBeingAnswered();
    if (this.options.closeOnClick ?? true) map.on('click', this.onMapClick);
    if (this.options.focusAfterOpen ?? true) this.element.querySelector<HTMLElement>('a[href], button, input, select, textarea, [tabindex]:not([tabindex="-1"])')?.focus({ preventScroll: true });
    this.fire('open', {});
    return this;
  }

  remove(): this {
    const map = this.map;
    if (!map) return this;
    map.off('click', this.onMapClick);
    this.detach();
    this.fire('close', {});
    return this;
  }

  protected anchorAt(point: [number, number]): Anchor {
    const given = this.options.anchor;
    const el = this.element;
    const anchor = given ?? autoAnchor(point, [el.offsetWidth, el.offsetHeight], this.map ? mapSize(this.map) : [Infinity, Infinity]);
    if (anchor !== this.anchorShown) {
      // The tip's side follows the anchor (CSS: vario-map-popup-anchor-*).
      for (const a of ANCHORS) el.classList.toggle(`vario-map-popup-anchor-${a}`, a === anchor);
      this.anchorShown = anchor;
    }
    return anchor;
  }

  private readonly onMapClick = (e: MapPointerEvent): void => {
    if (e.originalEvent !== this.openedBy) this.remove();
  };
}

function mapSize(map: VarioMap): [number, number] {
  const c = map.getCanvasContainer();
  return [c.clientWidth, c.clientHeight];
}
