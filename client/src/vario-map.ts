// VarioMap: the public, embeddable map (options, events, camera methods, controls), in the
// manner of MapLibre and Leaflet. SliceMap is its engine (chunks, GPU, frames); the camera,
// the input handlers and the controls live in their own modules.
import { CameraController, type MoveEventType } from './camera/camera-controller.js';
import { StepZoom } from './camera/step-zoom.js';
import { Evented } from './events.js';
import { Handlers, type HandlerFlags, type HandlerName } from './interaction/handlers.js';
import type { InteractionContext, InteractionSettings } from './interaction/interaction-context.js';
import { Pointers } from './interaction/pointers.js';
import { lerpCamera, type Camera } from './shared/camera.js';
import type { CubeMeta } from '../../format/cube-index.js';
import { discreteLevels, levelFor } from './shared/discrete-scales.js';
import { easeInOut, type Easing } from './shared/easing.js';
import { flyPath, DEFAULT_RHO } from './shared/fly-path.js';
import { zAtScale, type ScaleInfo } from '../../format/scale.js';
import type { SurfaceSpec } from '../../format/slicing-surface.js';
import { groundToPixel, resolutionAtScale, scaleAtResolution, viewBbox, type Bbox } from './shared/view.js';
import { scaleAtZoom, zoomAtScale } from './shared/zoom-levels.js';
import { SliceMap, type BlendingOptions, type BlendMode, type BoundaryOptions, type Feature, type PrefetchView, type SliceMapEvents, type SliceMapOptions } from './slice-map.js';
import type { SourceErrorInfo } from './source/worker-protocol.js';
import { AttributionControl } from './ui/attribution-control.js';
import { UrlHash } from './ui/url-hash.js';
import { PIXEL_SIZE_MM } from '../../format/pixel-size.js';

export type { Bbox, Feature, BlendingOptions, BlendMode, BoundaryOptions, SurfaceSpec, SourceErrorInfo, Camera, HandlerName, InteractionSettings };

/** Options handed to the engine as they are (docs/CLIENT.md). */
const ENGINE_OPTIONS = ['center', 'bounds', 'pixelRatio', 'surface', 'blending', 'boundaries', 'supersampling', 'gpuMemoryBudget', 'prefetchMargin', 'sourceOptions'] as const;
type EngineOptions = Pick<SliceMapOptions, (typeof ENGINE_OPTIONS)[number]>;

export interface VarioMapOptions extends Partial<HandlerFlags>, EngineOptions {
  container: HTMLElement | string;
  /** URL of the cube's index.json (or its directory, ending in /). */
  source: string;
  /** Scale denominator; or `zoom` (web map levels: 1:559082264 / 2^zoom). Default: the extent fits. */
  scaleDenominator?: number;
  zoom?: number;
  /** Smallest scale denominator (most detail) and largest; defaults: a quarter of the base scale, 4x the extent. */
  minScale?: number;
  maxScale?: number;
  /** false turns every input handler off. */
  interactive?: boolean;
  /** Keeps centre and scale in the URL's hash (#x/y/scale). */
  hash?: boolean;
  /** Replace animations with jumps; default: the user's prefers-reduced-motion. */
  reduceMotion?: boolean;
  /** Factor of the scale per zoom step (default 2). */
  zoomStep?: number;
  /** ms of a zoom step's animation (default 300; 0: none). */
  zoomDuration?: number;
  /** ms of keyboard pans (default 300; 0: none, and no inertia). */
  panDuration?: number;
  /** A zoom step shows at least this many slices, however slow the frames (default 12). */
  minZoomFrames?: number;
  /** The comparison mode: content only at a few discrete scales, as a classic multi-scale map. */
  comparisonMode?: boolean;
  /** Factor between the comparison mode's scales (default 2). */
  comparisonFactor?: number;
  /** The canvas container's accessible name (default "Map"). */
  ariaLabel?: string;
  /** Shows the dataset's attribution (default true). */
  attributionControl?: boolean;
}

export interface MapMoveEvent {
  /** The input that caused it, when one did. */
  originalEvent?: Event;
}

export interface MapPointerEvent {
  /** CSS px in the map. */
  point: [number, number];
  ground: [number, number];
  /** The face under the pointer (null: none, or not drawn yet). */
  feature: Feature | null;
  originalEvent: MouseEvent;
}

export interface VarioMapSettings extends InteractionSettings {
  comparisonMode: boolean;
}

/** Passed on from the engine as they are. */
type EngineEvents = Pick<SliceMapEvents, 'load' | 'idle' | 'error' | 'contextlost' | 'contextrestored' | 'dataloading' | 'data' | 'meta'>;
const ENGINE_EVENTS: (keyof EngineEvents)[] = ['load', 'idle', 'error', 'contextlost', 'contextrestored', 'dataloading', 'data', 'meta'];

export interface VarioMapEvents extends EngineEvents {
  movestart: MapMoveEvent;
  move: MapMoveEvent;
  moveend: MapMoveEvent;
  zoomstart: MapMoveEvent;
  zoom: MapMoveEvent;
  zoomend: MapMoveEvent;
  click: MapPointerEvent;
  pointermove: MapPointerEvent;
  /** Every frame drawn: its slice's base z and scale. */
  render: { frame: number; z: number; scaleDenominator: number; triangles: number };
  /** The settings changed (setSettings, setBlending). */
  settings: VarioMapSettings;
  remove: Record<string, never>;
}

export type ControlPosition = 'top-left' | 'top-right' | 'bottom-left' | 'bottom-right';

export interface Control {
  onAdd(map: VarioMap): HTMLElement;
  onRemove(map: VarioMap): void;
}

export interface CameraOptions {
  center?: [number, number];
  scaleDenominator?: number;
  zoom?: number;
}

export interface AnimationOptions {
  /** ms; 0 jumps. */
  duration?: number;
  easing?: Easing;
}

export interface FlyToOptions extends CameraOptions {
  /** Path length per second (default 1.2, as MapLibre); `duration` wins when given. */
  speed?: number;
  duration?: number;
  /** Curvature of the path (default 1.42). */
  rho?: number;
  easing?: Easing;
}

/** How many views along a flight's path are prefetched. */
const FLIGHT_SAMPLES = 16;
const CLICK_TOLERANCE_PX = 3;

export class VarioMap extends Evented<VarioMapEvents> {
  /** The engine: chunk loading, rendering and the frame loop. */
  private readonly engine: SliceMap;
  readonly handlers: Handlers | null;
  private readonly root: HTMLElement;
  private readonly canvasContainer: HTMLElement;
  private readonly controlCorners = new Map<ControlPosition, HTMLElement>();
  private readonly controls = new Map<Control, HTMLElement>();
  private readonly camera: CameraController;
  private readonly stepZoom: StepZoom;
  private settings: VarioMapSettings;
  private readonly comparisonFactor: number;
  private levels: number[] = [];
  private scaleInfo: ScaleInfo | null = null;
  private meta: CubeMeta | null = null;
  private readonly options: VarioMapOptions;
  private readonly motionQuery: MediaQueryList | null;
  private hash: UrlHash | null = null;
  private pressed: { x: number; y: number } | null = null;
  private pointerQuery: { busy: boolean; next: PointerEvent | null } = { busy: false, next: null };
  private removed = false;

  constructor(options: VarioMapOptions) {
    super();
    this.options = options;
    const c = typeof options.container === 'string' ? document.getElementById(options.container) : options.container;
    if (!c) throw new Error(`VarioMap: no container ${JSON.stringify(options.container)}`);
    this.root = c;
    c.classList.add('vario-map');
    if (getComputedStyle(c).position === 'static') c.style.position = 'relative';

    const cc = document.createElement('div');
    cc.className = 'vario-map-canvas-container';
    cc.style.cssText = 'position:absolute;inset:0;overflow:hidden;touch-action:none';
    cc.tabIndex = 0;
    cc.setAttribute('role', 'region');
    cc.setAttribute('aria-roledescription', 'map');
    cc.setAttribute('aria-label', options.ariaLabel ?? 'Map');
    c.appendChild(cc);
    this.canvasContainer = cc;
    const corners = document.createElement('div');
    corners.className = 'vario-map-control-container';
    for (const pos of ['top-left', 'top-right', 'bottom-left', 'bottom-right'] as const) {
      const d = document.createElement('div');
      d.className = `vario-map-ctrl-${pos}`;
      corners.appendChild(d);
      this.controlCorners.set(pos, d);
    }
    c.appendChild(corners);

    this.settings = {
      zoomStep: options.zoomStep ?? 2,
      zoomDurationMs: options.zoomDuration ?? 300,
      panDurationMs: options.panDuration ?? 300,
      minZoomFrames: options.minZoomFrames ?? 12,
      comparisonMode: options.comparisonMode ?? false,
    };
    this.comparisonFactor = options.comparisonFactor ?? 2;
    this.motionQuery = typeof matchMedia === 'function' ? matchMedia('(prefers-reduced-motion: reduce)') : null;

    const scale = options.scaleDenominator ?? (options.zoom !== undefined ? scaleAtZoom(options.zoom) : undefined);
    const engineOptions: SliceMapOptions = { container: cc, source: options.source };
    for (const k of ENGINE_OPTIONS) if (options[k] !== undefined) Object.assign(engineOptions, { [k]: options[k] });
    if (scale !== undefined) engineOptions.scaleDenominator = scale;
    this.engine = new SliceMap(engineOptions);

    this.camera = new CameraController({
      show: (cam) => this.show(cam),
      requestFrame: () => this.engine.requestFrame(),
      pixelSizeMm: () => this.pixelSizeMm(),
      reduceMotion: () => this.reducedMotion(),
      emit: (type, originalEvent) => this.emitMove(type, originalEvent),
    });
    this.stepZoom = new StepZoom(this.camera);
    this.engine.addFrameHook(this.tick);
    this.forwardEngineEvents();

    const interactive = options.interactive ?? true;
    const flag = (k: HandlerName): boolean => interactive && (options[k] ?? true);
    const ctx: InteractionContext = {
      element: cc,
      camera: this.camera,
      stepZoom: this.stepZoom,
      pointers: new Pointers(),
      settings: () => this.settings,
      point: (ev) => this.localPoint(ev),
      offset: (p) => {
        const [w, h] = this.cssSize();
        return [p[0] - w / 2, p[1] - h / 2];
      },
      size: () => this.cssSize(),
      pixelSizeMm: () => this.pixelSizeMm(),
    };
    this.handlers = interactive ? new Handlers(ctx, { scrollZoom: flag('scrollZoom'), dragPan: flag('dragPan'), keyboard: flag('keyboard'), doubleClickZoom: flag('doubleClickZoom'), touchZoomRotate: flag('touchZoomRotate'), boxZoom: flag('boxZoom') }) : null;
    cc.addEventListener('pointerdown', this.onPress);
    cc.addEventListener('click', this.onClick);
    cc.addEventListener('pointermove', this.onPointerMove);
    if (options.hash) this.hash = new UrlHash(this);
    if (options.attributionControl ?? true) this.addControl(new AttributionControl(), 'bottom-right');
  }

  // ---- the camera -----------------------------------------------------------------------------

  getCenter(): [number, number] {
    const c = this.camera.camera;
    return [c.x, c.y];
  }

  getScaleDenominator(): number {
    return this.camera.camera.scale;
  }

  /** The scale as a web map zoom level (see the zoom option). */
  getZoom(): number {
    return zoomAtScale(this.getScaleDenominator());
  }

  /** The ground box on screen: x0, y0, x1, y1. */
  getBounds(): Bbox {
    return viewBbox(this.engine.getView());
  }

  /** The base z (step) of the slice shown. */
  getSliceZ(): number {
    return this.engine.getZ();
  }

  isMoving(): boolean {
    return this.camera.isMoving;
  }

  jumpTo(o: CameraOptions): this {
    if (!this.ready(o)) return this;
    this.camera.jump(this.target(o));
    return this;
  }

  /** Animates linearly in position and geometrically in scale. Resolves true if it completed. */
  easeTo(o: CameraOptions & AnimationOptions): Promise<boolean> {
    if (!this.ready(o)) return Promise.resolve(true);
    const from = this.camera.camera;
    const to = this.target(o);
    return this.camera.animate((t) => lerpCamera(from, to, t), { durationMs: o.duration ?? 500, easing: o.easing ?? easeInOut });
  }

  /**
   * Flies along van Wijk and Nuij's path (out, across, in). The path is known at the start, so
   * the chunks along it are fetched ahead of the view. Resolves true if it arrived.
   */
  flyTo(o: FlyToOptions): Promise<boolean> {
    if (!this.ready(o)) return Promise.resolve(true);
    const from = this.camera.camera;
    const to = this.target(o);
    const path = flyPath(from, to, this.cssSize()[0], this.pixelSizeMm(), o.rho ?? DEFAULT_RHO);
    const durationMs = o.duration ?? path.durationMs(o.speed ?? 1.2);
    if (durationMs <= 0 || this.reducedMotion()) {
      this.camera.jump(to);
      return Promise.resolve(true);
    }
    const samples = path.samples(FLIGHT_SAMPLES);
    let passed = -1;
    const ahead = (i: number): void => {
      passed = i;
      this.engine.prefetch(samples.slice(i + 1).map((c) => this.prefetchView(c)));
    };
    ahead(0);
    return this.camera
      .animate(
        (p) => {
          const i = Math.floor(p * FLIGHT_SAMPLES);
          if (i > passed) ahead(i);
          return path.at(p);
        },
        { durationMs, easing: o.easing ?? easeInOut },
      )
      .finally(() => this.engine.prefetch([]));
  }

  /** Shows the box whole (with `padding` CSS px around it), eased over the zoom duration unless told otherwise. */
  fitBounds(bbox: Bbox, o: AnimationOptions & { padding?: number } = {}): Promise<boolean> {
    const [w, h] = this.cssSize();
    const pad = o.padding ?? 0;
    const res = Math.max((bbox[2] - bbox[0]) / Math.max(1, w - 2 * pad), (bbox[3] - bbox[1]) / Math.max(1, h - 2 * pad));
    return this.easeTo({ center: [(bbox[0] + bbox[2]) / 2, (bbox[1] + bbox[3]) / 2], scaleDenominator: scaleAtResolution(res, this.pixelSizeMm()), duration: o.duration ?? this.settings.zoomDurationMs, ...(o.easing ? { easing: o.easing } : {}) });
  }

  /** One zoom step (the zoom step factor) in or out about the centre, as the + and - keys. */
  zoomIn(): Promise<boolean> {
    return this.zoomSteps(-1);
  }

  zoomOut(): Promise<boolean> {
    return this.zoomSteps(1);
  }

  /** Pans by CSS px (the view's content moves the other way), over the pan duration. */
  panBy(offset: [number, number], o: AnimationOptions = {}): Promise<boolean> {
    const from = this.camera.camera;
    const res = resolutionAtScale(from.scale, this.pixelSizeMm());
    const to = { x: from.x + offset[0] * res, y: from.y - offset[1] * res, scale: from.scale };
    return this.camera.animate((t) => lerpCamera(from, to, t), { durationMs: o.duration ?? this.settings.panDurationMs, easing: o.easing ?? easeInOut });
  }

  /** Stops a running animation where it is. */
  stop(): this {
    this.camera.stop();
    return this;
  }

  /** CSS px in the map of a ground point. */
  project(ground: [number, number]): [number, number] {
    const v = this.engine.getView();
    const r = v.width / Math.max(1, this.cssSize()[0]);
    const [px, py] = groundToPixel(v, ground[0], ground[1]);
    return [px / r, py / r];
  }

  /** The ground point at CSS px in the map. */
  unproject(point: [number, number]): [number, number] {
    return this.engine.unproject(point);
  }

  // ---- content ------------------------------------------------------------------------------------

  setSlicingSurface(spec: SurfaceSpec | string): this {
    this.engine.setSurface(spec);
    return this;
  }

  getSlicingSurface(): SurfaceSpec {
    return this.engine.getSurface().spec;
  }

  setBlending(b: Partial<BlendingOptions>): this {
    this.engine.setBlending(b);
    this.fire('settings', this.getSettings());
    return this;
  }

  getBlending(): BlendingOptions {
    return this.engine.getBlending();
  }

  setBoundaries(b: Partial<BoundaryOptions>): this {
    this.engine.setBoundaries(b);
    return this;
  }

  getSettings(): VarioMapSettings {
    return { ...this.settings };
  }

  /** Zoom step factor, animation durations, minimum frames per step, comparison mode. */
  setSettings(s: Partial<VarioMapSettings>): this {
    if (s.zoomStep !== undefined && !(s.zoomStep > 1)) throw new Error('zoomStep must be > 1');
    this.settings = { ...this.settings, ...s };
    if (s.comparisonMode !== undefined && this.meta) this.show(this.camera.camera);
    this.fire('settings', this.getSettings());
    return this;
  }

  /** The scales the comparison mode shows content at. */
  getComparisonScales(): number[] {
    return this.levels.slice();
  }

  /** The dataset's metadata (null until it has loaded). */
  getMetadata(): CubeMeta | null {
    return this.meta;
  }

  /** The faces under a CSS px point of the map. */
  queryFeatures(point: [number, number]): Promise<Feature[]> {
    return this.engine.queryFeatures(point);
  }

  /** The absolute URL of the cube's index.json (the `source` option resolved). */
  getSourceUrl(): string {
    return this.engine.getSourceUrl();
  }

  /**
   * Absolute URLs of the cube's files this map has received (index, pages, chunks), oldest
   * first: what a service worker that took control after the map started must still cache for
   * these views to work offline (docs/deploy.md).
   */
  getLoadedUrls(): Promise<string[]> {
    return this.engine.getLoadedUrls();
  }

  loaded(): boolean {
    return this.engine.loaded();
  }

  /** Resolves when the map is next idle (at once if it is). */
  whenIdle(): Promise<{ complete: boolean }> {
    return this.engine.whenIdle();
  }

  // ---- the page ----------------------------------------------------------------------------------

  getContainer(): HTMLElement {
    return this.root;
  }

  /** The focusable element around the canvas, where input is handled. */
  getCanvasContainer(): HTMLElement {
    return this.canvasContainer;
  }

  getCanvas(): HTMLCanvasElement {
    return this.engine.canvas;
  }

  addControl(control: Control, position: ControlPosition = 'top-right'): this {
    const el = control.onAdd(this);
    this.controlCorners.get(position)!.appendChild(el);
    this.controls.set(control, el);
    return this;
  }

  removeControl(control: Control): this {
    const el = this.controls.get(control);
    if (!el) return this;
    this.controls.delete(control);
    control.onRemove(this);
    el.remove();
    return this;
  }

  /** Measures the container again after its size changed (automatic where ResizeObserver is). */
  resize(): this {
    this.engine.resize();
    return this;
  }

  /** Frees the GPU memory, ends the worker, removes every listener and element the map added. */
  remove(): void {
    if (this.removed) return;
    this.removed = true;
    this.camera.stop();
    this.engine.prefetch([]);
    for (const control of [...this.controls.keys()]) this.removeControl(control);
    this.hash?.remove();
    this.handlers?.destroy();
    const cc = this.canvasContainer;
    cc.removeEventListener('pointerdown', this.onPress);
    cc.removeEventListener('click', this.onClick);
    cc.removeEventListener('pointermove', this.onPointerMove);
    this.engine.removeFrameHook(this.tick);
    this.engine.remove();
    cc.remove();
    this.root.querySelector(':scope > .vario-map-control-container')?.remove();
    this.root.classList.remove('vario-map');
    this.fire('remove', {});
    this.removeAllListeners();
  }

  // ---- internals ---------------------------------------------------------------------------------

  private readonly tick = (now: number): void => this.camera.tick(now);

  private reducedMotion(): boolean {
    return this.options.reduceMotion ?? this.motionQuery?.matches ?? false;
  }

  private pixelSizeMm(): number {
    return this.meta?.pixelSizeMm ?? PIXEL_SIZE_MM;
  }

  private cssSize(): [number, number] {
    const r = this.canvasContainer.getBoundingClientRect();
    return [Math.max(1, r.width), Math.max(1, r.height)];
  }

  private localPoint(ev: { clientX: number; clientY: number }): [number, number] {
    const r = this.canvasContainer.getBoundingClientRect();
    return [ev.clientX - r.left, ev.clientY - r.top];
  }

  /** Before the cube's metadata the engine takes the view as it is (no camera, no events). */
  private ready(o: CameraOptions): boolean {
    if (this.meta) return true;
    const scale = o.scaleDenominator ?? (o.zoom !== undefined ? scaleAtZoom(o.zoom) : undefined);
    this.engine.jumpTo({ ...(o.center ? { center: o.center } : {}), ...(scale !== undefined ? { scaleDenominator: scale } : {}) });
    return false;
  }

  private target(o: CameraOptions): Camera {
    const c = this.camera.camera;
    const scale = o.scaleDenominator ?? (o.zoom !== undefined ? scaleAtZoom(o.zoom) : c.scale);
    if (!(scale > 0)) throw new Error('scaleDenominator must be > 0');
    return { x: o.center?.[0] ?? c.x, y: o.center?.[1] ?? c.y, scale: this.camera.clamp(scale) };
  }

  private zoomSteps(n: number): Promise<boolean> {
    const s = this.settings;
    return this.stepZoom.by(n * Math.log2(s.zoomStep), [0, 0], { durationMs: s.zoomDurationMs, minFrames: s.minZoomFrames });
  }

  /** The slice's base z for a camera: following the scale, or snapped in the comparison mode. */
  private sliceZ(scale: number): number | null {
    if (!this.settings.comparisonMode || !this.scaleInfo || this.levels.length === 0) return null;
    return zAtScale(this.scaleInfo, levelFor(this.levels, scale));
  }

  private show(c: Camera): void {
    this.engine.jumpTo({ center: [c.x, c.y], scaleDenominator: c.scale, z: this.sliceZ(c.scale) });
  }

  private prefetchView(c: Camera): PrefetchView {
    return { center: [c.x, c.y], scaleDenominator: c.scale, z: this.sliceZ(c.scale) };
  }

  private emitMove(type: MoveEventType, originalEvent: Event | undefined): void {
    this.fire(type, originalEvent ? { originalEvent } : {});
  }

  private onMeta(meta: CubeMeta): void {
    this.meta = meta;
    this.scaleInfo = { baseScale: meta.baseScale, baseFaces: meta.baseFaces, scaleTable: meta.scaleTable, zMax: meta.zMax };
    const [w, h] = this.cssSize();
    const extentScale = scaleAtResolution(Math.max((meta.extent[2] - meta.extent[0]) / w, (meta.extent[3] - meta.extent[1]) / h), meta.pixelSizeMm);
    this.camera.minScale = this.options.minScale ?? meta.baseScale / 4;
    this.camera.maxScale = this.options.maxScale ?? extentScale * 4;
    this.levels = discreteLevels(meta.baseScale, extentScale, this.comparisonFactor);
    const [x, y] = this.engine.getCenter();
    this.camera.reset({ x, y, scale: this.engine.getScale() });
    this.show(this.camera.camera);
    this.fire('meta', meta);
    this.hash?.apply();
  }

  private forwardEngineEvents(): void {
    const e = this.engine;
    // The map's own state follows the metadata before anyone else hears of it.
    e.on('meta', (m) => this.onMeta(m));
    for (const type of ENGINE_EVENTS) if (type !== 'meta') this.forward(type);
    e.on('render', (st) => this.fire('render', { frame: st.frame, z: e.getZ(), scaleDenominator: e.getScale(), triangles: st.triangles }));
  }

  private forward<K extends keyof EngineEvents>(type: K): void {
    this.engine.on(type, (ev) => this.fire(type, ev as VarioMapEvents[K]));
  }

  private readonly onPress = (ev: PointerEvent): void => {
    this.pressed = { x: ev.clientX, y: ev.clientY };
    if (document.activeElement !== this.canvasContainer) this.canvasContainer.focus({ preventScroll: true });
  };

  private readonly onClick = (ev: MouseEvent): void => {
    const p = this.pressed;
    this.pressed = null;
    // The end of a drag is not a click.
    if (p && Math.hypot(ev.clientX - p.x, ev.clientY - p.y) > CLICK_TOLERANCE_PX) return;
    if (!this.listens('click')) return;
    const point = this.localPoint(ev);
    void this.pointerEvent('click', point, ev);
  };

  private readonly onPointerMove = (ev: PointerEvent): void => {
    if (!this.listens('pointermove')) return;
    // One lookup at a time; the latest position waits for it.
    const q = this.pointerQuery;
    if (q.busy) {
      q.next = ev;
      return;
    }
    q.busy = true;
    void this.pointerEvent('pointermove', this.localPoint(ev), ev).finally(() => {
      q.busy = false;
      const next = q.next;
      q.next = null;
      if (next && !this.removed) this.onPointerMove(next);
    });
  };

  private async pointerEvent(type: 'click' | 'pointermove', point: [number, number], originalEvent: MouseEvent): Promise<void> {
    const ground = this.unproject(point);
    let feature: Feature | null = null;
    try {
      feature = (await this.queryFeatures(point))[0] ?? null;
    } catch {
      // Removed meanwhile, or a failed page of attributes: the event goes without the face.
    }
    if (!this.removed) this.fire(type, { point, ground, feature, originalEvent });
  }
}
