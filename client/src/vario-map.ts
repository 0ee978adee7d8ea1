// VarioMap: the public, embeddable map (options, events, camera methods, controls), in the
// manner of MapLibre and Leaflet, and the only map class. Its view (camera/map-view.ts) is the
// one owner of where it looks: the input handlers and these methods change it, and the engine
// beneath (engine/: canvas, chunks, frame loop, picking; internal) reads it every frame.
import type { CubeMeta } from '../../format/cube-index.js';
import type { ClassStyleJson, CubeStyle, StyleJson } from '../../format/style.js';
import { parseSurface, type SurfaceSpec } from '../../format/slicing-surface.js';
import { MapView, type MoveEventType } from './camera/map-view.js';
import { ScaleLimits } from './camera/scale-limits.js';
import { StepZoom } from './camera/step-zoom.js';
import { bindEngine } from './engine/engine-of.js';
import { MapEngine } from './engine/map-engine.js';
import type { FaceFeature, Feature, LineFeature, QueryOptions } from './engine/picking.js';
import { Evented } from './events.js';
import { CrsError, CrsTransform } from './geo/crs-transform.js';
import { LngLat, type LngLatLike } from './geo/lng-lat.js';
import { LngLatBounds, type LngLatBoundsLike } from './geo/lng-lat-bounds.js';
import type { AnimationOptions, CameraOptions, DataEvents, FitBoundsOptions, FlyToOptions, VarioMapEvents, VarioMapOptions, VarioMapSettings } from './map-options.js';
import { FeatureEvents, type MapPointerEvent } from './interaction/feature-events.js';
import { Handlers, type HandlerName } from './interaction/handlers.js';
import type { InteractionContext, InteractionSettings } from './interaction/interaction-context.js';
import { Pointers } from './interaction/pointers.js';
import type { BlendingOptions, BlendMode, BoundaryOptions, DrawnState, StatePaint } from './render/colour-options.js';
import type { FeatureRef, FeatureState } from './style/feature-state.js';
import { lerpCamera, type Camera } from './geometry/camera.js';
import { discreteLevels } from './geometry/discrete-scales.js';
import { easeInOut } from './motion/easing.js';
import { DEFAULT_RHO, flyPath } from './motion/fly-path.js';
import { resolutionAtScale, viewBbox, type Bbox } from './geometry/view.js';
import { scaleAtZoom, zoomAtScale } from './geometry/zoom-levels.js';
import type { SourceErrorInfo } from './source/worker-protocol.js';
import { AttributionControl } from './ui/attribution-control.js';
import { MapDom, type Control, type ControlPosition } from './ui/map-dom.js';
import { UrlHash } from './ui/url-hash.js';

export type { Bbox, FaceFeature, Feature, LineFeature, QueryOptions, FeatureRef, FeatureState, DrawnState, StatePaint, ClassStyleJson, CubeStyle, StyleJson, BlendingOptions, BlendMode, BoundaryOptions, SurfaceSpec, SourceErrorInfo, Camera, HandlerName, InteractionSettings, MapPointerEvent, Control, ControlPosition };
export type { LngLatLike, LngLatBoundsLike };
export type { AnimationOptions, CameraOptions, FitBoundsOptions, FlyToOptions, MapMoveEvent, VarioMapEvents, VarioMapOptions, VarioMapSettings } from './map-options.js';

/** Passed on from the engine as they are ('meta' after the map's own state follows it, 'load' not before 'meta'). */
const DATA_EVENTS: (keyof DataEvents)[] = ['complete', 'idle', 'error', 'contextlost', 'contextrestored', 'dataloading', 'data'];

/** How many views along a flight's path are prefetched. */
const FLIGHT_SAMPLES = 16;

/**
 * A view asked for before the cube (and so its CRS) is known: shown when it is. `lngLat`: it
 * needs the CRS (the cube's index alone does not do).
 */
type PendingView = ({ camera: CameraOptions } | { fit: ProjectedBox; options: FitBoundsOptions } | { maxBounds: ProjectedBox }) & { lngLat: boolean };

/** A box in the cube's CRS, computed when asked (a longitude/latitude box needs the CRS). */
type ProjectedBox = () => Bbox;

/** A camera asked for before the cube is known; a centre in longitude/latitude or a zoom (which depends on latitude) needs the CRS. */
function pendingCamera(o: CameraOptions): PendingView {
  return { camera: o, lngLat: o.center !== undefined || o.zoom !== undefined };
}

export class VarioMap extends Evented<VarioMapEvents> {
  readonly handlers: Handlers | null;
  /** Chunk loading, rendering and the frame loop (engineOf() reaches it, for tests). */
  private readonly engine: MapEngine;
  private readonly view: MapView;
  private readonly dom: MapDom;
  private readonly stepZoom: StepZoom;
  private readonly features: FeatureEvents;
  private settings: VarioMapSettings;
  private levels: number[] = [];
  private readonly options: VarioMapOptions;
  private readonly motionQuery: MediaQueryList | null;
  private hash: UrlHash | null = null;
  private readonly scaleLimits: ScaleLimits;
  /** Between longitude/latitude and the cube's CRS; the reason there is none; null before it is known (proj4 loads after the index). */
  private crs: CrsTransform | CrsError | null = null;
  /** The 'meta' event has fired: the cube and its CRS are known. */
  private metaFired = false;
  /** Starts loading the CRS, while it waits for the first map (loadCrs). */
  private startCrs: (() => void) | null = null;
  /** The first complete map, when it came before 'meta': its 'load' event waits for it. */
  private loadAfterMeta: DataEvents['load'] | null = null;
  private pending: PendingView[] = [];
  private removed = false;

  constructor(options: VarioMapOptions) {
    super();
    this.options = options;
    this.dom = new MapDom(options.container, options.ariaLabel ?? 'Map');
    this.settings = {
      zoomStep: options.zoomStep ?? 2,
      zoomDurationMs: options.zoomDuration ?? 300,
      panDurationMs: options.panDuration ?? 300,
      minZoomFrames: options.minZoomFrames ?? 12,
      comparisonMode: options.comparisonMode ?? false,
    };
    this.motionQuery = typeof matchMedia === 'function' ? matchMedia('(prefers-reduced-motion: reduce)') : null;

    this.view = new MapView({
      requestFrame: () => this.engine.requestFrame(),
      reduceMotion: () => this.reducedMotion(),
      size: () => this.dom.cssSize(),
      emit: (type: MoveEventType, originalEvent) => this.fire(type, originalEvent ? { originalEvent } : {}),
    });
    this.view.place({}, options.sliceZ ?? null);
    // Longitude/latitude and zoom need the cube's CRS: the first view is set when it is known.
    const { bounds, boundsProjected } = options;
    if (boundsProjected) this.pending.push({ fit: () => boundsProjected, options: {}, lngLat: false });
    else if (bounds) this.pending.push({ fit: () => this.geo().projectedBox(LngLatBounds.convert(bounds)), options: {}, lngLat: true });
    const { center, centerProjected, zoom, scaleDenominator } = options;
    this.pending.push(pendingCamera({ center, centerProjected, zoom, scaleDenominator }));
    this.scaleLimits = new ScaleLimits(this.view, options.minScale, options.maxScale);
    const { maxBounds, maxBoundsProjected } = options;
    if (maxBoundsProjected) this.view.setLimits({ maxBounds: maxBoundsProjected });
    // Before the views, so that they keep to it.
    else if (maxBounds) this.pending.unshift({ maxBounds: () => this.geo().projectedBox(LngLatBounds.convert(maxBounds)), lngLat: true });
    if (options.surface) this.view.setSurface(typeof options.surface === 'string' ? parseSurface(options.surface) : options.surface);
    this.engine = new MapEngine(this.dom.canvasContainer, this.view, { ...options, beforeMeta: (meta) => this.loadCrs(meta) });
    bindEngine(this, this.engine);
    this.stepZoom = new StepZoom(this.view);
    this.forwardEngineEvents();

    const cc = this.dom.canvasContainer;
    const interactive = options.interactive ?? true;
    const flag = (k: HandlerName): boolean => interactive && (options[k] ?? true);
    const ctx: InteractionContext = {
      element: cc,
      view: this.view,
      stepZoom: this.stepZoom,
      pointers: new Pointers(),
      settings: () => this.settings,
      point: (ev) => this.dom.localPoint(ev),
      offset: (p) => {
        const [w, h] = this.dom.cssSize();
        return [p[0] - w / 2, p[1] - h / 2];
      },
      size: () => this.dom.cssSize(),
      pixelSizeMm: () => this.view.pixelSizeMm,
    };
    this.handlers = interactive ? new Handlers(ctx, { scrollZoom: flag('scrollZoom'), dragPan: flag('dragPan'), keyboard: flag('keyboard'), doubleClickZoom: flag('doubleClickZoom'), touchZoomRotate: flag('touchZoomRotate'), boxZoom: flag('boxZoom') }, options.cooperativeGestures ?? false) : null;
    this.features = new FeatureEvents(cc, {
      listens: (type) => this.listens(type),
      fire: (type, ev) => this.fire(type, ev),
      point: (ev) => this.dom.localPoint(ev),
      unprojectProjected: (p) => this.unprojectProjected(p),
      lngLatAt: (p) => (this.crs instanceof CrsTransform ? this.crs.toLngLat(this.unprojectProjected(p)) : null),
      queryFeatures: (p) => this.queryFeatures(p),
    });
    if (options.hash) this.hash = new UrlHash(this);
    if (options.attributionControl ?? true) this.addControl(new AttributionControl(), 'bottom-right');
  }

  // ---- the camera -----------------------------------------------------------------------------

  getCenter(): LngLat {
    return this.geo().toLngLat(this.getCenterProjected());
  }

  /** The centre in the cube's projected CRS. */
  getCenterProjected(): [number, number] {
    const c = this.view.camera;
    return [c.x, c.y];
  }

  getScaleDenominator(): number {
    return this.view.camera.scale;
  }

  /** MapLibre's zoom at the centre's latitude: the same zoom there shows the same scale. */
  getZoom(): number {
    return zoomAtScale(this.getScaleDenominator(), this.getCenter().lat, this.view.pixelSizeMm);
  }

  setZoom(zoom: number): this {
    return this.jumpTo({ zoom });
  }

  setCenter(center: LngLatLike): this {
    return this.jumpTo({ center });
  }

  /** The longitude/latitude box around the screen (its edges are curves in longitude/latitude). */
  getBounds(): LngLatBounds {
    return this.geo().lngLatBox(this.getBoundsProjected());
  }

  /** The box on screen in the cube's projected CRS: x0, y0, x1, y1. */
  getBoundsProjected(): Bbox {
    return viewBbox(this.engine.getView());
  }

  /** The base z (step) of the slice shown. */
  getSliceZ(): number {
    return this.view.z();
  }

  isMoving(): boolean {
    return this.view.isMoving;
  }

  /** Goes there at once (asked before the cube is known: when it is, without movement events). */
  jumpTo(o: CameraOptions): this {
    const p = pendingCamera(o);
    if (this.placeable(p)) this.view.jump(this.target(o));
    else this.queue(p);
    return this;
  }

  /** Animates linearly in position and geometrically in scale. Resolves true if it completed. */
  easeTo(o: CameraOptions & AnimationOptions): Promise<boolean> {
    if (this.setBeforeMeta(o)) return Promise.resolve(true);
    const from = this.view.camera;
    const to = this.target(o);
    return this.view.animate((t) => lerpCamera(from, to, t), { durationMs: o.duration ?? 500, easing: o.easing ?? easeInOut });
  }

  /**
   * Flies along van Wijk and Nuij's path (out, across, in). The path is known at the start, so
   * the chunks along it are fetched ahead of the view. Resolves true if it arrived.
   */
  flyTo(o: FlyToOptions): Promise<boolean> {
    if (this.setBeforeMeta(o)) return Promise.resolve(true);
    const from = this.view.camera;
    const to = this.target(o);
    const path = flyPath(from, to, this.dom.cssSize()[0], this.view.pixelSizeMm, o.rho ?? DEFAULT_RHO);
    const durationMs = o.duration ?? path.durationMs(o.speed ?? 1.2);
    if (durationMs <= 0 || this.reducedMotion()) {
      this.view.jump(to);
      return Promise.resolve(true);
    }
    const samples = path.samples(FLIGHT_SAMPLES);
    let passed = -1;
    const ahead = (i: number): void => {
      passed = i;
      this.engine.prefetch(samples.slice(i + 1));
    };
    ahead(0);
    const along = (p: number): Camera => {
      const i = Math.floor(p * FLIGHT_SAMPLES);
      if (i > passed) ahead(i);
      return path.at(p);
    };
    return this.view.animate(along, { durationMs, easing: o.easing ?? easeInOut }).finally(() => this.engine.prefetch([]));
  }

  /**
   * Shows the longitude/latitude box whole and centred (the projected box around it), with
   * `padding` CSS px around it. Eased over the zoom duration unless `duration` says otherwise
   * (0: at once). Resolves true if it completed.
   */
  fitBounds(bounds: LngLatBoundsLike, o: FitBoundsOptions = {}): Promise<boolean> {
    return this.fitBox(() => this.geo().projectedBox(LngLatBounds.convert(bounds)), o, true);
  }

  /**
   * fitBounds for a box in the cube's projected CRS: without padding exactly the box
   * `ssc slice --bbox` shows on a canvas of this size.
   */
  fitBoundsProjected(bbox: Bbox, o: FitBoundsOptions = {}): Promise<boolean> {
    return this.fitBox(() => bbox, o, false);
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
    const from = this.view.camera;
    const res = resolutionAtScale(from.scale, this.view.pixelSizeMm);
    const to = { x: from.x + offset[0] * res, y: from.y - offset[1] * res, scale: from.scale };
    return this.view.animate((t) => lerpCamera(from, to, t), { durationMs: o.duration ?? this.settings.panDurationMs, easing: o.easing ?? easeInOut });
  }

  // ---- the limits ------------------------------------------------------------------------------

  /**
   * The longitude/latitude box the visible area stays inside (the projected box around it;
   * null: none). The view moves within it at once; no pan, zoom or animation leaves it after.
   */
  setMaxBounds(bounds: LngLatBoundsLike | null): this {
    if (bounds === null) return this.setMaxBoundsProjected(null);
    const box = (): Bbox => this.geo().projectedBox(LngLatBounds.convert(bounds));
    const p: PendingView = { maxBounds: box, lngLat: true };
    if (this.placeable(p)) return this.setMaxBoundsProjected(box());
    this.queue(p);
    return this;
  }

  /** setMaxBounds for a box in the cube's projected CRS: x0, y0, x1, y1. */
  setMaxBoundsProjected(bounds: Bbox | null): this {
    this.view.setLimits({ maxBounds: bounds });
    return this;
  }

  /** The longitude/latitude box around the limit (null: none). */
  getMaxBounds(): LngLatBounds | null {
    const b = this.getMaxBoundsProjected();
    return b ? this.geo().lngLatBox(b) : null;
  }

  getMaxBoundsProjected(): Bbox | null {
    return this.view.limits.maxBounds;
  }

  /** The smallest scale denominator (most detail); null: the default, a quarter of the base scale. The view zooms out to it at once if it must. */
  setMinScale(scale: number | null): this {
    this.scaleLimits.set('min', scale);
    return this;
  }

  getMinScale(): number {
    return this.view.limits.minScale;
  }

  /** The largest scale denominator; null: the default, 4x the scale that shows the whole extent. */
  setMaxScale(scale: number | null): this {
    this.scaleLimits.set('max', scale);
    return this;
  }

  getMaxScale(): number {
    return this.view.limits.maxScale;
  }

  /** Stops a running animation where it is. */
  stop(): this {
    this.view.stop();
    return this;
  }

  /** CSS px in the map of a place. */
  project(lngLat: LngLatLike): [number, number] {
    return this.engine.project(this.geo().toProjected(LngLat.convert(lngLat)));
  }

  /** The place at CSS px in the map. */
  unproject(point: [number, number]): LngLat {
    return this.geo().toLngLat(this.engine.unproject(point));
  }

  /** CSS px in the map of a point in the cube's projected CRS. */
  projectProjected(xy: [number, number]): [number, number] {
    return this.engine.project(xy);
  }

  /** The point in the cube's projected CRS at CSS px in the map. */
  unprojectProjected(point: [number, number]): [number, number] {
    return this.engine.unproject(point);
  }

  // ---- content ------------------------------------------------------------------------------------

  /** The slicing surface around the slice's base z ('flat', 'lens', 'tilted', 'sine', 'idw'; or its text form). */
  setSlicingSurface(spec: SurfaceSpec | string): this {
    const s = typeof spec === 'string' ? parseSurface(spec) : spec;
    this.view.setSurface(s);
    this.fire('surface', s);
    return this;
  }

  getSlicingSurface(): SurfaceSpec {
    return this.view.surface().spec;
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

  /** Shows or hides the cube's lines (roads and watercourses drawn as lines at smaller scales). */
  setLinesVisible(visible: boolean): this {
    this.engine.setLinesVisible(visible);
    return this;
  }

  getLinesVisible(): boolean {
    return this.engine.getLinesVisible();
  }

  getSettings(): VarioMapSettings {
    return { ...this.settings };
  }

  /** Zoom step factor, animation durations, minimum frames per step, comparison mode. */
  setSettings(s: Partial<VarioMapSettings>): this {
    if (s.zoomStep !== undefined && !(s.zoomStep > 1)) throw new Error('zoomStep must be > 1');
    this.settings = { ...this.settings, ...s };
    if (s.comparisonMode !== undefined) this.view.setLevels(s.comparisonMode ? this.levels : null);
    this.fire('settings', this.getSettings());
    return this;
  }

  /** The scales the comparison mode shows content at. */
  getComparisonScales(): number[] {
    return this.levels.slice();
  }

  /** The dataset's metadata (null until the 'meta' event: the cube and its CRS known). */
  getMetadata(): CubeMeta | null {
    return this.metaFired ? this.view.meta : null;
  }

  /** The faces under a CSS px point of the map (`{ outline: true }`: with the face's outline on screen). */
  queryFeatures(point: [number, number], options?: QueryOptions): Promise<Feature[]> {
    return this.engine.queryFeatures(point, options);
  }

  // ---- run-time style and feature state ----------------------------------------------------------

  /** A copy of the style drawn: the cube's, with the changes made since (null until the cube is known). */
  getStyle(): CubeStyle | null {
    return this.engine.getStyle();
  }

  /**
   * Draws the map in another style from the next frame, without fetching anything: checked with
   * the cube's style schema, and it must give every class of the cube and no other. A style
   * that fails throws an Error naming each problem, and the map stays as it was.
   */
  setStyle(style: StyleJson): this {
    this.fire('style', this.engine.setStyle(style));
    return this;
  }

  /** Changes one class's colour, label or pattern (`pattern: null` takes it away). */
  setClassStyle(classKey: string, change: ClassStyleJson): this {
    this.fire('style', this.engine.setClassStyle(classKey, change));
    return this;
  }

  /**
   * Merges `state` into the face's feature state (as MapLibre's). `highlight: true` and
   * `hover: true` draw the face with that state's paint (the `statePaint` option), wherever and
   * at whatever scale that face id is shown.
   */
  setFeatureState(feature: FeatureRef, state: FeatureState): this {
    this.engine.setFeatureState(feature, state);
    return this;
  }

  getFeatureState(feature: FeatureRef): FeatureState {
    return this.engine.getFeatureState(feature);
  }

  /** Removes one key of the face's state, or all of it. */
  removeFeatureState(feature: FeatureRef, key?: string): this {
    this.engine.removeFeatureState(feature, key);
    return this;
  }

  /** How faces with `highlight: true` (or `hover: true`) are drawn: fill colour and opacity, outline colour and width. */
  setStatePaint(state: DrawnState, paint: Partial<StatePaint>): this {
    this.engine.setStatePaint(state, paint);
    return this;
  }

  getStatePaint(state: DrawnState): StatePaint {
    return this.engine.getStatePaint(state);
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

  /** Every chunk the view shows is drawn. */
  loaded(): boolean {
    return this.engine.loaded();
  }

  /** Resolves when the map is next idle (at once if it is). */
  whenIdle(): Promise<{ complete: boolean }> {
    return this.engine.whenIdle();
  }

  // ---- the page ----------------------------------------------------------------------------------

  getContainer(): HTMLElement {
    return this.dom.root;
  }

  /** The focusable element around the canvas, where input is handled. */
  getCanvasContainer(): HTMLElement {
    return this.dom.canvasContainer;
  }

  getCanvas(): HTMLCanvasElement {
    return this.engine.canvas.element;
  }

  addControl(control: Control, position: ControlPosition = 'top-right'): this {
    this.dom.add(control, control.onAdd(this), position);
    return this;
  }

  removeControl(control: Control): this {
    if (this.dom.removeControl(control)) control.onRemove(this);
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
    this.view.stop();
    this.engine.prefetch([]);
    for (const control of this.dom.controls()) this.removeControl(control);
    this.hash?.remove();
    this.handlers?.destroy();
    this.features.remove();
    this.engine.remove();
    this.dom.remove();
    this.fire('remove', {});
    this.removeAllListeners();
  }

  // ---- internals ---------------------------------------------------------------------------------

  /** The fit of a box in the cube's CRS (before the cube is known: when it is). */
  private fitBox(box: ProjectedBox, o: FitBoundsOptions, lngLat: boolean): Promise<boolean> {
    const p: PendingView = { fit: box, options: o, lngLat };
    if (!this.placeable(p)) {
      this.queue(p);
      return Promise.resolve(true);
    }
    const c = this.engine.fitCamera(box(), o.padding ?? 0);
    const sliceZ = o.sliceZ !== undefined ? { sliceZ: o.sliceZ } : {};
    return this.easeTo({ centerProjected: [c.x, c.y], scaleDenominator: c.scale, ...sliceZ, duration: o.duration ?? this.settings.zoomDurationMs, ...(o.easing ? { easing: o.easing } : {}) });
  }

  /** Before the cube is known there is nothing to animate over: the view is just set then (true). */
  private setBeforeMeta(o: CameraOptions): boolean {
    const p = pendingCamera(o);
    if (this.placeable(p)) return false;
    this.queue(p);
    return true;
  }

  /**
   * A view can be set now: the cube is known, and its CRS when the view needs it (in the cube's
   * own coordinates the map moves while proj4 still loads), and no view asked for before waits.
   */
  private placeable(p: PendingView): boolean {
    return this.view.meta !== null && this.pending.length === 0 && (!p.lngLat || this.crs !== null);
  }

  /** The conversion of longitude/latitude, or a clear error why there is none. */
  private geo(): CrsTransform {
    if (this.crs instanceof CrsTransform) return this.crs;
    throw new CrsError(this.crs?.message ?? `longitude/latitude need the cube's CRS, known once its index (${this.getSourceUrl()}) has loaded: wait for the 'meta' event`);
  }

  /**
   * The views asked for before the cube was known, in order, set without movement events; while
   * the CRS is still loading, up to the first that needs it.
   */
  private placePending(): void {
    const waits = this.crs === null ? this.pending.findIndex((p) => p.lngLat) : -1;
    for (const p of waits < 0 ? this.pending.splice(0) : this.pending.splice(0, waits)) {
      try {
        if ('camera' in p) this.view.place(this.target(p.camera));
        else if ('maxBounds' in p) this.view.setLimits({ maxBounds: p.maxBounds() });
        else {
          if (p.options.sliceZ !== undefined) this.view.pinZ(p.options.sliceZ);
          this.view.place(this.engine.fitCamera(p.fit(), p.options.padding ?? 0));
        }
      } catch (err) {
        // Nobody is there to catch it now: the page hears of it as a load error of the index.
        this.fire('error', { kind: 'index', message: err instanceof Error ? err.message : String(err), url: this.getSourceUrl() });
      }
    }
  }

  private reducedMotion(): boolean {
    return this.options.reduceMotion ?? this.motionQuery?.matches ?? false;
  }

  /** The camera the options ask for (pinning or freeing the slice's z at once). */
  private target(o: CameraOptions): Camera {
    if (o.center !== undefined && o.centerProjected !== undefined) throw new Error('give center (longitude/latitude) or centerProjected, not both');
    const c = this.view.camera;
    const [x, y] = o.centerProjected ?? (o.center !== undefined ? this.geo().toProjected(LngLat.convert(o.center)) : [c.x, c.y]);
    // MapLibre's zoom at the latitude of where the view goes.
    const scale = o.scaleDenominator ?? (o.zoom !== undefined ? scaleAtZoom(o.zoom, this.geo().toLngLat([x, y]).lat, this.view.pixelSizeMm) : undefined);
    if (scale !== undefined && !(scale > 0)) throw new Error('scaleDenominator must be > 0');
    if (o.sliceZ !== undefined) this.view.pinZ(o.sliceZ);
    return { x, y, scale: scale ?? c.scale };
  }

  private zoomSteps(n: number): Promise<boolean> {
    const s = this.settings;
    return this.stepZoom.by(n * Math.log2(s.zoomStep), [0, 0], { durationMs: s.zoomDurationMs, minFrames: s.minZoomFrames });
  }

  /**
   * The cube's index has arrived: its CRS is to be loaded (proj4 is imported then, not with the
   * library). When the views asked for so far need longitude/latitude (or the hash, which is in
   * longitude/latitude, will place the view) the view waits for it. Else the map starts at once
   * and proj4 is fetched after the first map, so as not to share a slow network with its chunks;
   * or sooner, when a call needs it (queue).
   */
  private loadCrs(meta: CubeMeta): Promise<void> | null {
    const start = (): Promise<void> => {
      this.startCrs = null;
      return CrsTransform.load(meta, this.getSourceUrl())
        .catch((err: unknown) => (err instanceof CrsError ? err : new CrsError(err instanceof Error ? err.message : String(err))))
        .then((crs) => {
          if (this.removed) return;
          this.crs = crs;
          this.showMeta();
        });
    };
    if (this.hash || this.pending.some((p) => p.lngLat)) return start();
    // Without WebGL2, or with a worker that failed before the index came, no first map or idle
    // comes to wait for.
    if (!this.engine.draws() || this.engine.hasFailed()) {
      void start();
      return null;
    }
    this.startCrs = () => void start();
    return null;
  }

  /** A view for when the cube and its CRS are known; one that needs the CRS has it loaded now. */
  private queue(p: PendingView): void {
    this.pending.push(p);
    if (p.lngLat) this.startCrs?.();
  }

  /** The cube is known (the view has fitted itself): the scale limits and the comparison scales. */
  private onMeta(meta: CubeMeta): void {
    // The scale the view fitted the whole extent at (the view's own fit: one formula).
    const extentScale = this.engine.fitCamera(meta.extent).scale;
    this.scaleLimits.setDefaults(meta.baseScale / 4, extentScale * 4);
    this.levels = discreteLevels(meta.baseScale, extentScale, this.options.comparisonFactor ?? 2);
    if (this.settings.comparisonMode) this.view.setLevels(this.levels);
    this.placePending();
    this.view.place({ scale: this.view.clamp(this.view.camera.scale) });
    if (this.options.style !== undefined) {
      try {
        this.engine.setStyle(this.options.style);
      } catch (err) {
        // The cube's own style stays; the page hears why its own was not drawn.
        this.fire('error', { kind: 'style', message: err instanceof Error ? err.message : String(err), url: this.getSourceUrl() });
      }
    }
    this.showMeta();
  }

  /** Once both the cube and its CRS are known: the views that waited for the CRS, and the 'meta' event. */
  private showMeta(): void {
    const meta = this.view.meta;
    if (this.metaFired || !meta || this.crs === null) return;
    this.metaFired = true;
    this.placePending();
    this.fire('meta', meta);
    const style = this.getStyle();
    if (style) this.fire('style', style);
    if (this.hash && !(this.crs instanceof CrsTransform)) {
      // The hash is in longitude/latitude, as MapLibre's.
      this.hash.remove();
      this.hash = null;
      this.fire('error', { kind: 'index', message: `hash: ${this.crs.message}`, url: this.getSourceUrl() });
    }
    this.hash?.apply();
    const load = this.loadAfterMeta;
    this.loadAfterMeta = null;
    if (load) this.fire('load', load);
  }

  private forwardEngineEvents(): void {
    const e = this.engine;
    // The map's own state follows the metadata before anyone else hears of it.
    e.on('meta', (m) => this.onMeta(m));
    for (const type of DATA_EVENTS) e.on(type, (ev) => this.fire(type, ev));
    // The first map may be drawn before proj4 has come: a page's 'load' handler can use
    // longitude/latitude, as in MapLibre.
    e.on('load', (ev) => {
      if (this.metaFired) this.fire('load', ev);
      else this.loadAfterMeta = ev;
      this.startCrs?.();
    });
    // A first map whose chunks failed never loads; its CRS is still wanted.
    e.on('idle', () => this.startCrs?.());
    e.on('render', (st) => this.fire('render', { frame: st.frame, z: this.view.z(), scaleDenominator: this.getScaleDenominator(), triangles: st.triangles }));
  }
}
