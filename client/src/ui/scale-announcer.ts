// The scale told to screen readers: a visually hidden polite live region, written when a
// movement ends (every frame would flood the reader) and only when its text changes (a pan
// keeps the scale, and a rewrite would be read again).
import { spokenScale } from '../geometry/scale-bar-length.js';

export class ScaleAnnouncer {
  readonly element: HTMLElement;

  constructor() {
    const el = document.createElement('div');
    el.className = 'vario-map-sr-only vario-map-scale-announcer';
    el.setAttribute('role', 'status');
    el.setAttribute('aria-live', 'polite');
    el.setAttribute('aria-atomic', 'true');
    this.element = el;
  }

  announce(denominator: number): void {
    const text = spokenScale(denominator);
    if (this.element.textContent !== text) this.element.textContent = text;
  }
}
