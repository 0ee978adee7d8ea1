// Tells a click from the end of a drag, for everything that listens for clicks on the map (its
// click event, overlay layers): a click counts when the pointer moved at most a few pixels
// since it was pressed.

const CLICK_TOLERANCE_PX = 3;

export class ClickFilter {
  private pressed: { x: number; y: number } | null = null;

  press(ev: { clientX: number; clientY: number }): void {
    this.pressed = { x: ev.clientX, y: ev.clientY };
  }

  /** Whether this click is one (not the end of a drag); the press is used up. */
  isClick(ev: { clientX: number; clientY: number }): boolean {
    const p = this.pressed;
    this.pressed = null;
    return !p || Math.hypot(ev.clientX - p.x, ev.clientY - p.y) <= CLICK_TOLERANCE_PX;
  }
}
