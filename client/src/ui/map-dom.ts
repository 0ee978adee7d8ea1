// The elements a map adds to its container: the focusable canvas container (where input is
// handled) and the four corners controls go in.
import type { VarioMap } from '../vario-map.js';

export type ControlPosition = 'top-left' | 'top-right' | 'bottom-left' | 'bottom-right';

export interface Control {
  onAdd(map: VarioMap): HTMLElement;
  onRemove(map: VarioMap): void;
}

/** CSS px of an event from the element's top left (the map's: its canvas container). */
export function localPoint(element: HTMLElement, ev: { clientX: number; clientY: number }): [number, number] {
  const r = element.getBoundingClientRect();
  return [ev.clientX - r.left, ev.clientY - r.top];
}

export class MapDom {
  readonly root: HTMLElement;
  readonly canvasContainer: HTMLElement;
  private readonly corners: HTMLElement;
  private readonly cornerOf = new Map<ControlPosition, HTMLElement>();
  private readonly elementOf = new Map<Control, HTMLElement>();

  constructor(container: HTMLElement | string, ariaLabel: string) {
    const c = typeof container === 'string' ? document.getElementById(container) : container;
    if (!c) throw new Error(`VarioMap: no container ${JSON.stringify(container)}`);
    this.root = c;
    c.classList.add('vario-map');
    if (getComputedStyle(c).position === 'static') c.style.position = 'relative';
    const cc = document.createElement('div');
    cc.className = 'vario-map-canvas-container';
    cc.style.cssText = 'position:absolute;inset:0;overflow:hidden;touch-action:none';
    cc.tabIndex = 0;
    cc.setAttribute('role', 'region');
    cc.setAttribute('aria-roledescription', 'map');
    cc.setAttribute('aria-label', ariaLabel);
    c.appendChild(cc);
    this.canvasContainer = cc;
    this.corners = document.createElement('div');
    this.corners.className = 'vario-map-control-container';
    for (const pos of ['top-left', 'top-right', 'bottom-left', 'bottom-right'] as const) {
      const d = document.createElement('div');
      d.className = `vario-map-ctrl-${pos}`;
      this.corners.appendChild(d);
      this.cornerOf.set(pos, d);
    }
    c.appendChild(this.corners);
  }

  /** CSS size of the map, at least 1 x 1. */
  cssSize(): [number, number] {
    const r = this.canvasContainer.getBoundingClientRect();
    return [Math.max(1, r.width), Math.max(1, r.height)];
  }

  /** CSS px of an event from the map's top left. */
  localPoint(ev: { clientX: number; clientY: number }): [number, number] {
    return localPoint(this.canvasContainer, ev);
  }

  add(control: Control, el: HTMLElement, position: ControlPosition): void {
    this.cornerOf.get(position)?.appendChild(el);
    this.elementOf.set(control, el);
  }

  /** Takes the control's element out; false if it was not there. */
  removeControl(control: Control): boolean {
    const el = this.elementOf.get(control);
    if (!el) return false;
    this.elementOf.delete(control);
    el.remove();
    return true;
  }

  controls(): Control[] {
    return [...this.elementOf.keys()];
  }

  remove(): void {
    this.canvasContainer.remove();
    this.corners.remove();
    this.root.classList.remove('vario-map');
  }
}
