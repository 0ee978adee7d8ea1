// A lens of more detail that follows the pointer: the slicing surface dips (toward the base of
// the cube) around the ground point under the pointer.
import type { SliceMap } from '../slice-map.js';
import { resolutionAtScale } from '../shared/view.js';
import { PIXEL_SIZE_MM } from '../../../format/pixel-size.js';

export interface LensOptions {
  /** Radius in CSS pixels (turned into ground units at the scale of the moment). */
  radiusPx: number;
  /** How far down the lens reaches at its centre, in steps. */
  depth: number;
}

export class LensControl {
  private enabled = false;

  constructor(
    private readonly map: SliceMap,
    public options: LensOptions = { radiusPx: 120, depth: 200 },
  ) {}

  enable(): this {
    if (this.enabled) return this;
    this.enabled = true;
    this.map.canvas.addEventListener('pointermove', this.onMove);
    return this;
  }

  disable(): this {
    this.enabled = false;
    this.map.canvas.removeEventListener('pointermove', this.onMove);
    return this;
  }

  /** Puts the lens under a CSS pixel position of the container. */
  moveTo(point: [number, number]): void {
    const [cx, cy] = this.map.unproject(point);
    const pixelSizeMm = this.map.cubeMeta?.pixelSizeMm ?? PIXEL_SIZE_MM;
    const radius = this.options.radiusPx * resolutionAtScale(this.map.getScale(), pixelSizeMm);
    this.map.setSurface({ kind: 'lens', cx, cy, radius, depth: this.options.depth });
  }

  private readonly onMove = (ev: PointerEvent): void => {
    const rect = this.map.container.getBoundingClientRect();
    this.moveTo([ev.clientX - rect.left, ev.clientY - rect.top]);
  };
}
