// The camera of a VarioMap: where it looks, the limits on its scale, the running animation,
// and the movement events (movestart, move, moveend; zoomstart, zoom, zoomend) that follow
// from its changes, whatever made them (a method, a gesture or an animation).
import { cameraAround, clampScale, groundAt, zoomAboutPath, type Camera } from '../shared/camera.js';
import { easeInOut, type Easing } from '../shared/easing.js';
import { CameraAnimation, type AnimationSpec } from './camera-animation.js';

export type MoveEventType = 'movestart' | 'move' | 'moveend' | 'zoomstart' | 'zoom' | 'zoomend';

export interface CameraHost {
  /** Shows the camera (on the engine). */
  show(c: Camera): void;
  /** Asks for a frame, in which tick() runs. */
  requestFrame(): void;
  pixelSizeMm(): number;
  /** Whether animations are replaced by jumps (prefers-reduced-motion or the option). */
  reduceMotion(): boolean;
  emit(type: MoveEventType, originalEvent: Event | undefined): void;
}

export interface AnimateOptions {
  durationMs: number;
  easing?: Easing;
  minFrames?: number;
  originalEvent?: Event;
}

export class CameraController {
  minScale = 1;
  maxScale = Infinity;
  private current: Camera = { x: 0, y: 0, scale: 1 };
  private moving = false;
  private zooming = false;
  private readonly animation = new CameraAnimation();

  constructor(private readonly host: CameraHost) {}

  get camera(): Camera {
    return { ...this.current };
  }

  /** Between movestart and moveend. */
  get isMoving(): boolean {
    return this.moving;
  }

  get animating(): boolean {
    return this.animation.active;
  }

  /** Takes the engine's camera without events (the first view, once the cube is known). */
  reset(c: Camera): void {
    this.current = { ...c, scale: this.clamp(c.scale) };
  }

  clamp(scale: number): number {
    return clampScale(scale, this.minScale, this.maxScale);
  }

  /** Moves now, as part of a movement that goes on (a gesture); end() closes it. */
  set(c: Camera, originalEvent?: Event): void {
    const next = { ...c, scale: this.clamp(c.scale) };
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
    this.current = next;
    this.host.show(next);
    if (!moved) return;
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
    const path = zoomAboutPath(this.current, this.clamp(scale), offset, this.host.pixelSizeMm());
    return this.animate(path, o);
  }

  /** The camera at `scale` keeping the ground point at `offset` in place (no animation). */
  around(scale: number, offset: [number, number]): Camera {
    return zoomAboutPath(this.current, this.clamp(scale), offset, this.host.pixelSizeMm())(1);
  }

  /** The camera that puts the ground point now at `offset` at `to` (CSS px from the centre), at `scale`. */
  carry(offset: [number, number], to: [number, number], scale: number): Camera {
    return cameraAround(this.groundAtOffset(offset), to, this.clamp(scale), this.host.pixelSizeMm());
  }

  groundAtOffset(offset: [number, number]): [number, number] {
    return groundAt(this.current, offset, this.host.pixelSizeMm());
  }

  /** Progress of the running animation: for a zoom that takes over at the same pace. */
  progress(): { t: number; easing: Easing; durationMs: number } | null {
    return this.animation.progress();
  }

  /** The frame hook: advances the running animation. */
  tick(now: number): void {
    this.animation.tick(now, (c) => this.set(c));
    if (this.animation.active) this.host.requestFrame();
  }
}
