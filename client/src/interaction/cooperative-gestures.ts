// Cooperative gestures (as MapLibre's): a map inside a page that scrolls leaves the plain wheel
// and one finger to the page, so a reader scrolling past is not caught by the map. Ctrl (or ⌘)
// with the wheel zooms, as does a trackpad pinch (which browsers send as a wheel with ctrlKey);
// two fingers move the map. A gesture left to the page shows a hint saying so.
import { GestureHint } from '../ui/gesture-hint.js';
import { TOUCH_HINT, wheelHint } from '../ui/gesture-hint-text.js';
import { InputHandler, type ListenerSpec } from './interaction-context.js';

function onMac(): boolean {
  return typeof navigator !== 'undefined' && /^Mac/.test(navigator.platform);
}

export class CooperativeGestures extends InputHandler {
  private hint: GestureHint | null = null;

  protected listeners(): ListenerSpec[] {
    return [['touchmove', this.onTouchMove as EventListener, { passive: false }]];
  }

  override enable(): void {
    if (this.enabled) return;
    super.enable();
    this.hint = new GestureHint(this.ctx.element);
    // One finger pans the page (the browser scrolls and cancels the pointer); pinching the page is left off.
    this.ctx.element.style.touchAction = 'pan-x pan-y';
  }

  override disable(): void {
    if (!this.enabled) return;
    super.disable();
    this.hint?.remove();
    this.hint = null;
    this.ctx.element.style.touchAction = 'none';
  }

  /** Whether this wheel event zooms the map; if not, the page has it and the hint says how. */
  wheelZooms(ev: WheelEvent): boolean {
    if (!this.enabled || ev.ctrlKey || ev.metaKey) return true;
    this.hint?.show(wheelHint(onMac()));
    return false;
  }

  /** Whether a press of this pointer may drag the map: not one finger, which scrolls the page. */
  dragPans(ev: PointerEvent): boolean {
    return !this.enabled || ev.pointerType !== 'touch';
  }

  private readonly onTouchMove = (ev: TouchEvent): void => {
    if (ev.touches.length >= 2) {
      // Two fingers are the map's: the page must not scroll under them.
      if (ev.cancelable) ev.preventDefault();
      this.hint?.hide();
      return;
    }
    this.hint?.show(TOUCH_HINT);
  };
}
