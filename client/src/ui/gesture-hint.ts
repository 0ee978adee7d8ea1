// The short message over the map that says how to move it when a gesture was left to the page
// (cooperative gestures): shown for a moment, and announced to screen readers through a polite
// live region that stays in the map (a region added with its text would not be read).

/** How long the hint stays after the last gesture that called for it. */
const SHOWN_MS = 1500;
/** Its fade (vario-map.css); the text goes after it, so the same hint another time is read again. */
const FADE_MS = 300;

export class GestureHint {
  readonly element: HTMLElement;
  private timer: ReturnType<typeof setTimeout> | undefined;
  private clearing: ReturnType<typeof setTimeout> | undefined;

  constructor(parent: HTMLElement) {
    const el = document.createElement('div');
    el.className = 'vario-map-gesture-hint';
    el.setAttribute('role', 'status');
    el.setAttribute('aria-live', 'polite');
    el.setAttribute('aria-atomic', 'true');
    parent.appendChild(el);
    this.element = el;
  }

  show(text: string): void {
    clearTimeout(this.clearing);
    // Rewritten only when it changes: every wheel notch would be read again.
    if (this.element.textContent !== text) this.element.textContent = text;
    this.element.classList.add('vario-map-gesture-hint-shown');
    clearTimeout(this.timer);
    this.timer = setTimeout(() => this.hide(), SHOWN_MS);
  }

  hide(): void {
    clearTimeout(this.timer);
    if (!this.element.classList.contains('vario-map-gesture-hint-shown')) return;
    this.element.classList.remove('vario-map-gesture-hint-shown');
    clearTimeout(this.clearing);
    this.clearing = setTimeout(() => (this.element.textContent = ''), FADE_MS);
  }

  remove(): void {
    clearTimeout(this.timer);
    clearTimeout(this.clearing);
    this.element.remove();
  }
}
