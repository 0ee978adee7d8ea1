// A lens of more detail that follows the pointer: the slicing surface dips (toward the base of
// the cube) around the ground point under the pointer, and stays under it as the map moves.
import { resolutionAtScale } from '../geometry/view.js';
import type { VarioMap } from '../vario-map.js';
import { SurfaceTool } from './surface-tool.js';

export interface LensOptions {
  /** Radius in CSS pixels (turned into ground units at the scale of the moment). */
  radiusPx: number;
  /** How far down the lens reaches at its centre, in steps. */
  depth: number;
}

export class LensControl extends SurfaceTool {
  readonly options: LensOptions;
  /** CSS px of the pointer in the map (null: not seen yet; the lens sits at the centre). */
  private pointer: [number, number] | null = null;

  constructor(options: Partial<LensOptions> = {}) {
    super('lens', 'Lens of more detail at the pointer', '\u25ce');
    this.options = { radiusPx: 120, depth: 200, ...options };
  }

  /** Puts the lens under a CSS pixel position of the map. */
  moveTo(point: [number, number]): void {
    this.pointer = point;
    const map = this.map;
    const meta = map?.getMetadata();
    if (!map || !meta || !this.enabled) return;
    const [cx, cy] = map.unprojectProjected(point);
    const radius = this.options.radiusPx * resolutionAtScale(map.getScaleDenominator(), meta.pixelSizeMm);
    map.setSlicingSurface({ kind: 'lens', cx, cy, radius, depth: this.options.depth });
  }

  protected start(map: VarioMap): void {
    map.getCanvasContainer().addEventListener('pointermove', this.onPointer);
    map.on('move', this.follow);
    // Shown at once when the pointer has been seen or the map is known; else at the first move.
    if (this.pointer || map.getMetadata()) this.follow();
  }

  protected stop(map: VarioMap): void {
    map.getCanvasContainer().removeEventListener('pointermove', this.onPointer);
    map.off('move', this.follow);
  }

  private readonly follow = (): void => {
    const map = this.map;
    if (!map) return;
    const r = map.getCanvasContainer().getBoundingClientRect();
    this.moveTo(this.pointer ?? [r.width / 2, r.height / 2]);
  };

  private readonly onPointer = (ev: PointerEvent): void => {
    const r = this.map?.getCanvasContainer().getBoundingClientRect();
    if (r) this.moveTo([ev.clientX - r.left, ev.clientY - r.top]);
  };
}
