// The scale limits as the API sets them: each given (option or setter) or, when not, the cube's
// default (a quarter of its base scale; 4x the scale that shows its whole extent), handed to the
// view, which keeps to them. A change that would cross the two is refused and undone.
import type { MapView } from './map-view.js';

type Which = 'min' | 'max';

export class ScaleLimits {
  private readonly given: Record<Which, number | undefined>;
  private defaults: Record<Which, number> | null = null;

  /** Wrong limits are refused here, with an error naming them, before anything is fetched. */
  constructor(
    private readonly view: MapView,
    min: number | undefined,
    max: number | undefined,
  ) {
    this.given = { min, max };
    this.apply(true);
  }

  /** The cube is known: its defaults, the first view brought within them without movement events. */
  setDefaults(min: number, max: number): void {
    this.defaults = { min, max };
    this.apply(true);
  }

  /** One limit given (null: the default again); the view zooms within it at once. */
  set(which: Which, scale: number | null): void {
    const before = { ...this.given };
    this.given[which] = scale ?? undefined;
    try {
      this.apply(false);
    } catch (e) {
      Object.assign(this.given, before);
      throw e;
    }
  }

  /** Before the cube is known, a limit not given is none. */
  private apply(quiet: boolean): void {
    const d = this.defaults;
    const min = this.given.min ?? (d ? Math.min(d.min, this.given.max ?? Infinity) : 1);
    const max = this.given.max ?? (d ? Math.max(d.max, min) : Infinity);
    this.view.setLimits({ minScale: min, maxScale: max }, quiet);
  }
}
