// What the lens and the control points share: a map control (a toggle button) that owns the
// slicing surface while it is on, and that the settings panel can also drive without its
// button (attach, then enable and disable).
import type { SurfaceSpec } from '../../../format/slicing-surface.js';
import type { Control, VarioMap } from '../vario-map.js';
import { controlButton, controlGroup } from './control-dom.js';

export abstract class SurfaceTool implements Control {
  protected map: VarioMap | null = null;
  private on = false;
  private button: HTMLButtonElement | null = null;

  constructor(
    /** The kind of surface the tool makes (set back to flat when it is turned off). */
    private readonly kind: SurfaceSpec['kind'],
    private readonly label: string,
    private readonly icon: string,
  ) {}

  /** While on: listen to the map (and set the surface when it can). */
  protected abstract start(map: VarioMap): void;
  protected abstract stop(map: VarioMap): void;

  onAdd(map: VarioMap): HTMLElement {
    this.attach(map);
    const group = controlGroup(`vario-map-${this.kind}`);
    this.button = controlButton(`vario-map-${this.kind}-toggle`, this.label, this.icon, () => void (this.on ? this.disable() : this.enable()));
    this.button.setAttribute('aria-pressed', String(this.on));
    group.append(this.button);
    return group;
  }

  onRemove(): void {
    this.detach();
    this.button = null;
  }

  /** Binds the tool to a map without a button (the settings panel's way). */
  attach(map: VarioMap): void {
    if (this.map === map) return;
    this.detach();
    this.map = map;
    if (this.on) this.start(map);
  }

  detach(): void {
    if (this.map && this.on) this.stop(this.map);
    this.map = null;
  }

  get enabled(): boolean {
    return this.on;
  }

  enable(): this {
    if (this.on) return this;
    this.on = true;
    this.button?.setAttribute('aria-pressed', 'true');
    if (this.map) this.start(this.map);
    return this;
  }

  /** Turns the tool off; the surface goes back to flat if it is still the tool's. */
  disable(): this {
    if (!this.on) return this;
    this.on = false;
    this.button?.setAttribute('aria-pressed', 'false');
    const map = this.map;
    if (!map) return this;
    this.stop(map);
    if (map.getSlicingSurface().kind === this.kind) map.setSlicingSurface({ kind: 'flat' });
    return this;
  }
}
