// The engine beneath VarioMap (internal, not exported from the library): the chunk source
// (worker), the renderer (WebGL2), the canvas, which chunks stay on the GPU, and the frame loop
// that reads the map's view and draws it, in the style and feature state of the moment. Its
// events are VarioMap's data and render events.
import type { CubeMeta } from '../../../format/cube-index.js';
import type { CubeStyle } from '../../../format/style.js';
import type { MapView } from '../camera/map-view.js';
import { Evented } from '../events.js';
import { DEFAULT_STATE_PAINTS, DRAWN_STATES, type BlendingOptions, type BoundaryOptions, type DrawnState, type StatePaint } from '../render/colour-options.js';
import type { IdBuffer } from '../render/id-buffer.js';
import type { OverlayDrawable } from '../render/overlay-pass.js';
import { Renderer } from '../render/renderer.js';
import { parseColour } from '../render/style-texture.js';
import type { Camera } from '../geometry/camera.js';
import { groundToPixel, pixelToGround, type Bbox, type ViewGeometry } from '../geometry/view.js';
import { ChunkSource } from '../source/chunk-source.js';
import { FeatureStates, type FeatureRef, type FeatureState } from '../style/feature-state.js';
import { copyStyle, parseMapStyle, withClassStyle } from '../style/map-style.js';
import type { ChunkStatus, SourceErrorInfo, SourceOptions } from '../source/worker-protocol.js';
import { showLoadError } from '../ui/load-error.js';
import { showWebGl2Missing } from '../ui/webgl-missing.js';
import { ChunkResidency } from './chunk-residency.js';
import { EMPTY_STATS, FrameLoop, type RenderSettings, type RenderStats } from './frame-loop.js';
import { MapCanvas } from './map-canvas.js';
import { featuresAt, type Feature, type QueryOptions } from './picking.js';

export interface EngineOptions {
  /** URL of the cube's directory (with or without a trailing /) or of its index.json. */
  source: string;
  blending?: Partial<BlendingOptions>;
  boundaries?: Partial<BoundaryOptions>;
  /** How faces with `highlight: true` and `hover: true` in their feature state are drawn. */
  statePaint?: Partial<Record<DrawnState, Partial<StatePaint>>>;
  /** Frames accumulated (jittered) while the view is still; 1: off. */
  supersampling?: number;
  /** Draw the cube's lines (roads, watercourses collapsed to lines); default true. */
  lines?: boolean;
  /** GPU memory for chunks, bytes. */
  gpuMemoryBudget?: number;
  /** Chunks are also fetched this fraction of the view's size around it. */
  prefetchMargin?: number;
  /** Per frame, at most this many bytes of chunks go to the GPU (the rest wait a frame). */
  uploadBytesPerFrame?: number;
  sourceOptions?: Partial<SourceOptions>;
  /** Overrides window.devicePixelRatio. */
  pixelRatio?: number;
  /**
   * Called when the cube's index has arrived, before the view is placed on the cube; the view
   * waits for the promise it may return (VarioMap: the CRS, when the first view is given in
   * longitude/latitude, so that no chunk of the fitted view is fetched in vain).
   */
  beforeMeta?: (meta: CubeMeta) => Promise<void> | null;
}

export interface EngineEvents {
  /** The first complete map. */
  load: { timeMs: number };
  /**
   * Once per view: the image on screen shows every chunk the view needs (later frames of the
   * same view may still refine it: supersampling, blending turned off once the slice stops).
   */
  complete: { frame: number };
  /** Nothing more to fetch, draw or accumulate. `complete`: every chunk on screen is drawn. */
  idle: { complete: boolean };
  render: RenderStats;
  error: SourceErrorInfo;
  meta: CubeMeta;
  contextlost: Record<string, never>;
  contextrestored: Record<string, never>;
  /** A chunk request went out (`file`), and a chunk went to the GPU. */
  dataloading: { file: string };
  data: { file: string };
}

const DEFAULT_BUDGET = 256 * 1024 * 1024;

export class MapEngine extends Evented<EngineEvents> {
  readonly canvas: MapCanvas;
  private readonly source: ChunkSource;
  private readonly renderer: Renderer | null;
  private readonly residency: ChunkResidency | null = null;
  private readonly loop: FrameLoop | null = null;
  private readonly settings: RenderSettings;
  private readonly startTime = performance.now();
  /** The style drawn: the cube's until changed at run time (null until the cube is known). */
  private style: CubeStyle | null = null;
  private readonly featureStates = new FeatureStates();
  /** The index could not be loaded: nothing will ever be drawn. */
  private failed = false;
  private removed = false;

  constructor(
    container: HTMLElement,
    private readonly view: MapView,
    options: EngineOptions,
  ) {
    super();
    this.canvas = new MapCanvas(container, options.pixelRatio, () => {
      // A larger map may show more than maxBounds allows.
      view.keepWithinLimits();
      this.loop?.viewChanged(false);
    });
    this.settings = {
      blending: { mode: 'moving', distance: 0.5, ...options.blending },
      boundaries: { enabled: false, width: 1, color: '#000000', opacity: 0.35, ...options.boundaries },
      paints: {
        highlight: checkedPaint('highlight', { ...DEFAULT_STATE_PAINTS.highlight, ...options.statePaint?.highlight }),
        hover: checkedPaint('hover', { ...DEFAULT_STATE_PAINTS.hover, ...options.statePaint?.hover }),
      },
      supersampling: Math.max(1, Math.floor(options.supersampling ?? 16)),
      lines: options.lines ?? true,
      prefetchMargin: options.prefetchMargin ?? 0.25,
    };
    // The source first: its worker's script and index.json are then asked for before the
    // renderer makes its WebGL context and compiles its shaders, not after.
    this.source = new ChunkSource(options.source, options.sourceOptions);
    try {
      this.renderer = Renderer.create(this.canvas.element, options.gpuMemoryBudget ?? DEFAULT_BUDGET, (files) => this.contextLost(files), () => this.contextRestored());
    } catch (err) {
      // A shader that does not compile: the worker, running already, goes with the engine.
      this.source.destroy();
      throw err;
    }
    if (this.renderer) {
      const residency = new ChunkResidency(this.source, this.renderer, options.uploadBytesPerFrame ?? 16 * 1024 * 1024, (file) => this.fire('data', { file }));
      this.residency = residency;
      this.loop = new FrameLoop(view, this.canvas, this.renderer, residency, this.settings, {
        render: (stats) => this.fire('render', stats),
        load: () => this.fire('load', { timeMs: performance.now() - this.startTime }),
        complete: (frame) => this.fire('complete', { frame }),
        idle: (complete) => this.fire('idle', { complete }),
      });
      view.onChange((sliceMoved) => this.loop?.viewChanged(sliceMoved));
    } else {
      showWebGl2Missing(container);
    }
    this.source.on('meta', (meta) => {
      const wait = options.beforeMeta?.(meta) ?? null;
      if (!wait) this.takeMeta(meta);
      else void wait.then(() => this.removed || this.takeMeta(meta));
    });
    this.source.on('needed', (n) => {
      this.residency?.answer(n);
      this.loop?.answered();
      this.loop?.schedule();
    });
    this.source.on('handed-over', () => this.loop?.schedule());
    this.source.on('chunk', (ch) => {
      this.residency?.arrived(ch);
      this.loop?.schedule();
    });
    this.source.on('status', (s) => {
      if (s.status === 'requested') this.fire('dataloading', { file: s.file });
    });
    this.source.on('error', (e) => {
      this.fire('error', e);
      // A failed chunk may be all that kept the map from idling.
      this.loop?.schedule();
    });
    this.source.on('failed', (e) => {
      // The first failure says why the map cannot be shown (no index, no worker); a second,
      // when both fail, would stack another box over it.
      if (this.failed) return;
      this.failed = true;
      showLoadError(container, e);
      // Nothing more will be fetched or drawn: a page waiting for the map learns it is over.
      this.fire('idle', { complete: false });
    });
    this.canvas.measure();
  }

  /** The cube is known: the view fits it, and VarioMap then shows what its options ask for. */
  private takeMeta(meta: CubeMeta): void {
    // The container may have been resized (or shown) since the ResizeObserver last ran: the
    // first fit, and the limits taken from it, need the size it has now.
    this.canvas.measure();
    const g = this.canvas.deviceSize();
    this.view.setMeta(meta, () => this.view.fitCamera(meta.extent, g.width, g.height, this.canvas.deviceRatio()));
    this.style = meta.style;
    this.featureStates.faceCount = meta.faces.count;
    this.renderer?.setMeta(meta);
    this.fire('meta', meta);
  }

  // ---- the view on the canvas --------------------------------------------------------------------

  /** The view in device pixels (what the GPU draws). */
  getView(): ViewGeometry {
    return this.canvas.geometry(this.view);
  }

  /** The ground point at CSS px in the container. */
  unproject(point: [number, number]): [number, number] {
    const r = this.canvas.deviceRatio();
    return pixelToGround(this.getView(), point[0] * r, point[1] * r);
  }

  /** CSS px in the container of a ground point. */
  project(ground: [number, number]): [number, number] {
    const r = this.canvas.deviceRatio();
    const [px, py] = groundToPixel(this.getView(), ground[0], ground[1]);
    return [px / r, py / r];
  }

  /** The camera that shows `bbox` whole on this canvas, `padding` CSS px around it. */
  fitCamera(bbox: Bbox, padding = 0): Camera {
    const g = this.canvas.deviceSize(), r = this.canvas.deviceRatio();
    return this.view.fitCamera(bbox, g.width, g.height, r, padding * r);
  }

  /**
   * Views the map will show soon, in order (a flight's path): their chunks are fetched after
   * those of the current view and its margin, and kept when they arrive. [] forgets them.
   */
  prefetch(cameras: Camera[]): void {
    this.residency?.prefetch(cameras);
    this.loop?.schedule();
  }

  // ---- rendering options -----------------------------------------------------------------------

  setBlending(b: Partial<BlendingOptions>): void {
    this.settings.blending = { ...this.settings.blending, ...b };
    this.redraw();
  }

  getBlending(): BlendingOptions {
    return { ...this.settings.blending };
  }

  setBoundaries(b: Partial<BoundaryOptions>): void {
    this.settings.boundaries = { ...this.settings.boundaries, ...b };
    this.redraw();
  }

  getStatePaint(state: DrawnState): StatePaint {
    return { ...this.settings.paints[drawnState(state)] };
  }

  setStatePaint(state: DrawnState, h: Partial<StatePaint>): void {
    const s = drawnState(state);
    this.settings.paints = { ...this.settings.paints, [s]: checkedPaint(s, { ...this.settings.paints[s], ...h }) };
    this.redraw();
  }

  // ---- the style and feature state ---------------------------------------------------------------

  /** A copy of the style drawn (null until the cube is known). */
  getStyle(): CubeStyle | null {
    return this.style && copyStyle(this.style);
  }

  /** Checks `json` against the schema and the cube's classes; draws it from the next frame. */
  setStyle(json: unknown): CubeStyle {
    return this.changeStyle('setStyle', (meta) => parseMapStyle(json, meta.style.classes));
  }

  setClassStyle(key: string, change: unknown): CubeStyle {
    return this.changeStyle('setClassStyle', (_, style) => withClassStyle(style, key, change));
  }

  setFeatureState(ref: FeatureRef, state: FeatureState): void {
    const face = this.featureStates.set(ref, state);
    this.showFeatureState(face);
  }

  getFeatureState(ref: FeatureRef): FeatureState {
    return this.featureStates.get(ref);
  }

  removeFeatureState(ref: FeatureRef, key?: string): void {
    const face = this.featureStates.remove(ref, key);
    this.showFeatureState(face);
  }

  /** Something the map is to show is still coming (an overlay's geometry): no 'idle' before it has. */
  holdIdle(coming: Promise<void>): void {
    this.loop?.holdIdle(coming);
  }

  /** The overlay layers drawn over the map, bottom first: shown with the finished map at the next frame. */
  setOverlays(layers: readonly OverlayDrawable[]): void {
    this.renderer?.setOverlays(layers);
    this.loop?.overlaysChanged();
  }

  setSupersampling(frames: number): void {
    this.settings.supersampling = Math.max(1, Math.floor(frames));
    this.redraw();
  }

  setLinesVisible(visible: boolean): void {
    this.settings.lines = visible;
    this.redraw();
  }

  getLinesVisible(): boolean {
    return this.settings.lines;
  }

  /**
   * Benchmarks only: draw every triangle of every chunk, as before the drawing order
   * (draw-ranges.ts), to set the two against each other on one page.
   */
  setWholeChunks(whole: boolean): void {
    if (this.renderer) this.renderer.wholeChunks = whole;
    this.redraw();
  }

  setGpuMemoryBudget(bytes: number): void {
    if (this.renderer) this.renderer.store.budgetBytes = bytes;
    this.redraw();
  }

  /** Asks for a frame (in which the view's animation advances). */
  requestFrame(): void {
    this.loop?.schedule();
  }

  /** Renders again from the first frame (e.g. after a style change). */
  redraw(): void {
    this.loop?.redraw();
  }

  // ---- state -------------------------------------------------------------------------------------

  /** There is a frame loop (WebGL2 is there): 'load' and 'idle' will come. */
  draws(): boolean {
    return this.loop !== null;
  }

  /** The source has failed for good (no index, no worker): no first map will come. */
  hasFailed(): boolean {
    return this.failed;
  }

  /** Every chunk the view shows is on the GPU: the map is complete. */
  loaded(): boolean {
    return this.loop?.loaded() ?? false;
  }

  /** Resolves at the next idle, or now when the map is idle. */
  whenIdle(): Promise<{ complete: boolean }> {
    if (this.failed) return Promise.resolve({ complete: false });
    return this.loop ? this.loop.whenIdle(() => this.once('idle')) : this.once('idle');
  }

  /** performance.now() of the first complete map, or null. */
  get firstCompleteAt(): number | null {
    return this.loop?.firstCompleteAt ?? null;
  }

  chunkStatuses(): Map<string, ChunkStatus> {
    return this.source.allStatuses();
  }

  /** The chunks the current view needs: on screen, in the prefetch margin and ahead. */
  neededChunks(): { visible: string[]; margin: string[]; ahead: string[] } {
    return this.residency?.neededChunks() ?? { visible: [], margin: [], ahead: [] };
  }

  stats(): RenderStats {
    return this.loop?.stats() ?? EMPTY_STATS;
  }

  /** The ID buffer of the current view (device pixels, rows from the top). */
  readIds(): IdBuffer | null {
    this.loop?.renderNowIfDirty();
    return this.renderer?.readIds() ?? null;
  }

  /** The face under a CSS px point of the container, with its class, attributes and steps. */
  async queryFeatures(point: [number, number], options: QueryOptions = {}): Promise<Feature[]> {
    const meta = this.view.meta;
    if (!this.renderer || !meta || !this.style) return [];
    this.loop?.renderNowIfDirty();
    const r = this.canvas.deviceRatio();
    const x = Math.floor(point[0] * r), y = Math.floor(point[1] * r);
    const g = this.canvas.deviceSize();
    if (x < 0 || y < 0 || x >= g.width || y >= g.height) return [];
    return featuresAt({ renderer: this.renderer, source: this.source, meta, style: this.style, view: this.getView() }, x, y, options);
  }

  /** The absolute URL of the cube's index.json. */
  getSourceUrl(): string {
    return this.source.url;
  }

  /** Absolute URLs of the cube's files received so far, oldest first. */
  getLoadedUrls(): Promise<string[]> {
    return this.source.loadedUrls();
  }

  resize(): void {
    this.canvas.measure();
  }

  remove(): void {
    this.removed = true;
    this.loop?.stop();
    this.source.destroy();
    this.renderer?.destroy();
    this.canvas.remove();
    this.removeAllListeners();
  }

  private contextLost(files: string[]): void {
    this.source.evicted(files);
    this.loop?.lost();
    this.fire('contextlost', {});
  }

  private contextRestored(): void {
    if (this.view.meta) this.renderer?.setMeta(this.view.meta, this.style ?? this.view.meta.style);
    this.fire('contextrestored', {});
    this.loop?.redraw();
  }

  /** A new style from `make`, or an error naming what is wrong with the style as it was. */
  private changeStyle(caller: string, make: (meta: CubeMeta, style: CubeStyle) => CubeStyle): CubeStyle {
    const meta = this.view.meta;
    if (!meta || !this.style) throw new Error(`${caller}: the cube's classes are not known yet; call it once the map's 'meta' event has fired`);
    const style = make(meta, this.style);
    this.style = style;
    this.renderer?.setStyle(style);
    this.redraw();
    return copyStyle(style);
  }

  private showFeatureState(face: number): void {
    this.renderer?.setFaceState(face, this.featureStates.bits(face, DRAWN_STATES));
    this.redraw();
  }
}

function drawnState(state: string): DrawnState {
  const s = DRAWN_STATES.find((d) => d === state);
  if (!s) throw new Error(`state paint: ${JSON.stringify(state)} is not a drawn feature state (${DRAWN_STATES.join(', ')})`);
  return s;
}

/** A state's paint, or an error naming the value that is wrong. */
function checkedPaint(state: DrawnState, h: StatePaint): StatePaint {
  for (const k of ['color', 'outlineColor'] as const) parseColour(h[k], `${state} paint ${k}`);
  if (!(h.opacity >= 0 && h.opacity <= 1)) throw new Error(`${state} paint opacity must be in [0, 1], not ${h.opacity}`);
  if (!(h.outlineWidth >= 0 && Number.isFinite(h.outlineWidth))) throw new Error(`${state} paint outlineWidth must be a number of CSS px >= 0, not ${h.outlineWidth}`);
  return h;
}
