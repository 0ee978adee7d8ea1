// The one owner of where a map looks (as OpenLayers' View): the centre, the scale denominator,
// the slice's base z (following the scale, snapped to the comparison scales, or pinned), the
// slicing surface, the limits on the scale and place (view-limits.ts: min and max scale, a box
// the visible area stays inside) and the running animation. Input handlers and the
// API change it; the frame loop reads it. Every change of the camera also yields the movement
// events (movestart, move, moveend; zoomstart, zoom, zoomend), whatever made it.
import type { CubeMeta } from '../../../format/cube-index.js';
import { PIXEL_SIZE_MM } from '../../../format/pixel-size.js';
import { zAtScale } from '../../../format/scale.js';
import type { Surface, SurfaceSpec } from '../../../format/slicing-surface.js';
import { levelFor } from '../geometry/discrete-scales.js';
import { cameraAround, groundAt, zoomAboutPath, type Camera } from '../geometry/camera.js';
import { checkViewLimits, constrainCamera, limitScale, type ViewLimits } from '../geometry/view-limits.js';
import { easeInOut, type Easing } from '../motion/easing.js';
import { resolutionAtScale, type Bbox, type ViewGeometry } from '../geometry/view.js';
import { CameraAnimation, type AnimationSpec } from './camera-animation.js';

export type MoveEventType = 'movestart' | 'move' | 'moveend' | 'zoomstart' | 'zoom' | 'zoomend';

export interface ViewHost {
  /** Asks for a frame, in which tick() runs and the view is drawn. */
  requestFrame(): void;
  /** Whether animations are replaced by jumps (prefers-reduced-motion or the option). */
  reduceMotion(): boolean;
  /** CSS px of the map (what maxBounds must hold). */
  size(): [number, number];
  emit(type: MoveEventType, originalEvent: Event | undefined): void;
}

export interface AnimateOptions {
  durationMs: number;
  easing?: Easing;
  minFrames?: number;
  originalEvent?: Event;
}

/** What the view shows changed; `sliceMoved`: its z or surface did (blending follows that). */
export type ViewListener = (sliceMoved: boolean) => void;

export class MapView {
  private bounds: ViewLimits = { minScale: 1, maxScale: Infinity, maxBounds: null };
  /** Where the map looks; NaN until set or fitted to the cube's extent. */
  private current: Camera = { x: NaN, y: NaN, scale: NaN };
  private zPinned: number | null = null;
  /** The comparison mode's scales: the slice snaps to the nearest (null: it follows the scale). */
  private levels: number[] | null = null;
  private spec: SurfaceSpec = { kind: 'flat' };
  private cube: CubeMeta | null = null;
  private moving = false;
  private zooming = false;
  private readonly animation = new CameraAnimation();
  private listener: ViewListener = () => undefined;

  constructor(private readonly host: ViewHost) {}

  /** The engine's hook: told at once of every change, so what it reports is never a view behind. */
  onChange(fn: ViewListener): void {
    this.listener = fn;
  }

  get camera(): Camera {
    return { ...this.current };
  }

  get pixelSizeMm(): number {
    return this.meta?.pixelSizeMm ?? PIXEL_SIZE_MM;
  }

  /** Between movestart and moveend. */
  get isMoving(): boolean {
    return this.moving;
  }

  get animating(): boolean {
    return this.animation.active;
  }

  /** The cube's metadata, once known. */
  get meta(): CubeMeta | null {
    return this.cube;
  }

  /** The cube is known: z follows its scale table; a view not given yet shows `fit` whole. */
  setMeta(meta: CubeMeta, fit: () => Camera): void {
    this.cube = meta;
    const c = this.current;
    if (!Number.isFinite(c.x) || !Number.isFinite(c.scale)) {
      const f = fit();
      // What the options gave wins over the fitted box.
      this.current = Number.isFinite(c.x) ? { ...f, x: c.x, y: c.y } : Number.isFinite(c.scale) ? { ...f, scale: c.scale } : f;
    }
    this.current = this.within(this.current);
    this.changed(true);
  }

  /** Sets the view without movement events (before the cube is known, and the first view). */
  place(c: Partial<Camera>, z?: number | null): void {
    const zBefore = this.z();
    this.current = { ...this.current, ...c };
    if (z !== undefined) this.zPinned = z;
    this.changed(this.z() !== zBefore);
  }

  /** The scale denominator within the limits (with maxBounds, at most the one that fills the view). */
  clamp(scale: number): number {
    return limitScale(scale, this.bounds, this.host.size(), this.pixelSizeMm);
  }

  get limits(): ViewLimits {
    return { ...this.bounds, maxBounds: this.bounds.maxBounds && [...this.bounds.maxBounds] };
  }

  /**
   * Changes the limits (throwing, with the limits unchanged, when they are wrong) and brings the
   * view within them at once: a jump with its movement events, or with `quiet` none (the first
   * view). Every later change of the view is kept within them too.
   */
  setLimits(l: Partial<ViewLimits>, quiet = false): void {
    const next: ViewLimits = { ...this.bounds, ...l };
    checkViewLimits(next);
    this.bounds = { ...next, maxBounds: next.maxBounds && [...next.maxBounds] };
    this.keepWithinLimits(quiet);
  }

  /** Brings the view within the limits (after they or the map's size changed); see setLimits. */
  keepWithinLimits(quiet = false): void {
    const c = this.current;
    if (!this.cube || !Number.isFinite(c.x) || !Number.isFinite(c.scale)) return;
    const to = this.within(c);
    if (to.x === c.x && to.y === c.y && to.scale === c.scale) return;
    if (quiet) this.place(to);
    else this.jump(to);
  }

  private within(c: Camera): Camera {
    return constrainCamera(c, this.bounds, this.host.size(), this.pixelSizeMm);
  }

  // ---- the slice -------------------------------------------------------------------------------

  /** The base z of the slice at a scale denominator: pinned, snapped, or following it. */
  zAt(scale: number): number {
    if (this.zPinned !== null) return this.zPinned;
    if (!this.meta || !Number.isFinite(scale)) return 0;
    return zAtScale(this.meta, this.levels && this.levels.length > 0 ? levelFor(this.levels, scale) : scale);
  }

  /** The base z of the slice shown. */
  z(): number {
    return this.zAt(this.current.scale);
  }

  /** Pins the slice's base z (null: it follows the scale again). */
  pinZ(z: number | null): void {
    this.place({}, z);
  }

  /** The comparison mode's scales, or null to leave it. */
  setLevels(levels: number[] | null): void {
    const zBefore = this.z();
    this.levels = levels;
    this.changed(this.z() !== zBefore);
  }

  surface(): Surface {
    return { base: this.z(), spec: this.spec };
  }

  setSurface(spec: SurfaceSpec): void {
    this.spec = spec;
    this.changed(true);
  }

  /** The view on a canvas of `width` x `height` device pixels, `ratio` device pixels per CSS pixel. */
  geometry(width: number, height: number, ratio: number, c: Camera = this.current): ViewGeometry {
    return { centerX: c.x, centerY: c.y, resolution: resolutionAtScale(c.scale, this.pixelSizeMm) / ratio, width, height };
  }

  /** The camera that shows `bbox` whole, centred, on such a canvas with `padding` device px around it. */
  fitCamera(bbox: Bbox, width: number, height: number, ratio: number, padding = 0): Camera {
    const deviceRes = Math.max((bbox[2] - bbox[0]) / Math.max(1, width - 2 * padding), (bbox[3] - bbox[1]) / Math.max(1, height - 2 * padding));
    return { x: (bbox[0] + bbox[2]) / 2, y: (bbox[1] + bbox[3]) / 2, scale: (deviceRes * ratio * 1000) / this.pixelSizeMm };
  }

  // ---- movement --------------------------------------------------------------------------------

  /** Moves now, as part of a movement that goes on (a gesture); end() closes it. */
  set(c: Camera, originalEvent?: Event): void {
    const next = this.within(c);
    const zoomed = next.scale !== this.current.scale;
    const moved = zoomed || next.x !== this.current.x || next.y !== this.current.y;
    if (!this.moving) {
      this.moving = true;
      this.host.emit('movestart', originalEvent);
    }
    if (zoomed && !this.zooming) {
      this.zooming = true;
      this.host.emit('zoomstart', originalEvent);
    }
    const zBefore = this.z();
    this.current = next;
    if (!moved) return;
    this.changed(this.z() !== zBefore);
    this.host.emit('move', originalEvent);
    if (zoomed) this.host.emit('zoom', originalEvent);
  }

  /** The movement is over: moveend (and zoomend), once. */
  end(originalEvent?: Event): void {
    if (this.zooming) {
      this.zooming = false;
      this.host.emit('zoomend', originalEvent);
    }
    if (this.moving) {
      this.moving = false;
      this.host.emit('moveend', originalEvent);
    }
  }

  jump(c: Camera, originalEvent?: Event): void {
    this.animation.stop();
    this.set(c, originalEvent);
    this.end(originalEvent);
  }

  /** Stops a running animation where it is (any new input does this first). */
  stop(originalEvent?: Event): void {
    if (!this.animation.active) return;
    this.animation.stop();
    this.end(originalEvent);
  }

  /**
   * Animates along `path` (eased progress 0..1 to camera); with no duration or reduced motion,
   * jumps to its end. Resolves true at the end, false when something else took over.
   */
  animate(path: (p: number) => Camera, o: AnimateOptions): Promise<boolean> {
    if (o.durationMs <= 0 || this.host.reduceMotion()) {
      this.jump(path(1), o.originalEvent);
      return Promise.resolve(true);
    }
    return new Promise((resolve) => {
      const spec: AnimationSpec = {
        path,
        durationMs: o.durationMs,
        easing: o.easing ?? easeInOut,
        minFrames: o.minFrames ?? 0,
        done: (completed) => {
          if (completed) this.end(o.originalEvent);
          resolve(completed);
        },
      };
      // Taking over keeps the movement open: no moveend/movestart in between.
      this.animation.start(spec, performance.now());
      this.host.requestFrame();
    });
  }

  /** Zooms to `scale` keeping the ground point at `offset` (CSS px from the centre) in place. */
  zoomAbout(scale: number, offset: [number, number], o: AnimateOptions): Promise<boolean> {
    return this.animate(zoomAboutPath(this.current, this.clamp(scale), offset, this.pixelSizeMm), o);
  }

  /** The camera at `scale` keeping the ground point at `offset` in place (no animation). */
  around(scale: number, offset: [number, number]): Camera {
    return zoomAboutPath(this.current, this.clamp(scale), offset, this.pixelSizeMm)(1);
  }

  /** The camera that puts the ground point now at `offset` at `to` (CSS px from the centre), at `scale`. */
  carry(offset: [number, number], to: [number, number], scale: number): Camera {
    return cameraAround(this.groundAtOffset(offset), to, this.clamp(scale), this.pixelSizeMm);
  }

  groundAtOffset(offset: [number, number]): [number, number] {
    return groundAt(this.current, offset, this.pixelSizeMm);
  }

  /** Progress of the running animation: for a zoom that takes over at the same pace. */
  progress(): { t: number; easing: Easing; durationMs: number } | null {
    return this.animation.progress();
  }

  /** Run by the frame loop before it reads the view: advances the running animation. */
  tick(now: number): void {
    this.animation.tick(now, (c) => this.set(c));
    if (this.animation.active) this.host.requestFrame();
  }

  private changed(sliceMoved: boolean): void {
    this.listener(sliceMoved);
  }
}
