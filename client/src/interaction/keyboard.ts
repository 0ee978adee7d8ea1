// Keys on the focused map: + and - zoom one step about the centre, the arrows pan about 100 px
// (shift: three times as far), eased over the pan duration.
import type { Camera } from '../geometry/camera.js';
import { easeInOut } from '../motion/easing.js';
import { resolutionAtScale } from '../geometry/view.js';
import { InputHandler, type ListenerSpec } from './interaction-context.js';

export const KEY_PAN_PX = 100;

export class Keyboard extends InputHandler {

  protected listeners(): ListenerSpec[] {
    return [
      ['keydown', this.onKey as EventListener],
    ];
  }

  private readonly onKey = (ev: KeyboardEvent): void => {
    if (ev.altKey || ev.ctrlKey || ev.metaKey) return;
    const s = this.ctx.settings();
    const step = ev.shiftKey ? 3 : 1;
    let pan: [number, number] | null = null;
    switch (ev.key) {
      case '+':
      case '=':
        void this.ctx.stepZoom.by(-Math.log2(s.zoomStep), [0, 0], { durationMs: s.zoomDurationMs, minFrames: s.minZoomFrames, originalEvent: ev });
        break;
      case '-':
      case '_':
        void this.ctx.stepZoom.by(Math.log2(s.zoomStep), [0, 0], { durationMs: s.zoomDurationMs, minFrames: s.minZoomFrames, originalEvent: ev });
        break;
      case 'ArrowLeft':
        pan = [-KEY_PAN_PX * step, 0];
        break;
      case 'ArrowRight':
        pan = [KEY_PAN_PX * step, 0];
        break;
      case 'ArrowUp':
        pan = [0, -KEY_PAN_PX * step];
        break;
      case 'ArrowDown':
        pan = [0, KEY_PAN_PX * step];
        break;
      default:
        return;
    }
    ev.preventDefault();
    if (!pan) return;
    // The view moves toward the arrow: the centre goes that many pixels that way.
    const view = this.ctx.view;
    const from: Camera = view.camera;
    const res = resolutionAtScale(from.scale, this.ctx.pixelSizeMm());
    const [dx, dy] = pan;
    void view.animate((t) => ({ x: from.x + dx * t * res, y: from.y - dy * t * res, scale: from.scale }), { durationMs: s.panDurationMs, easing: easeInOut, originalEvent: ev });
  };
}
