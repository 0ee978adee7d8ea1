// SliceMap: a vario-scale map in a container. It ties the chunk source (worker), the renderer
// (WebGL2) and the view together and runs the frame loop; the embedding API (VarioMap) and the
// UI controls build on its methods and events.
import type { CubeMeta } from '../../format/cube-index.js';
import { boxMeets, type QueryBox } from '../../format/index-query.js';
import { scaleAtZ } from '../../format/scale.js';
import { parseSurface, type Surface, type SurfaceSpec } from '../../format/slicing-surface.js';
import { pixelToGround, type Bbox, type ViewGeometry } from './shared/view.js';
import { Evented } from './events.js';
import { colourParams, type BlendingOptions, type BoundaryOptions } from './render/colour-options.js';
import { Renderer, type IdBuffer } from './render/renderer.js';
import { jitter, weight } from './render/supersampling.js';
import { ChunkSource } from './source/chunk-source.js';
import type { AheadView, ChunkPayload, ChunkStatus, NeededChunks, SourceErrorInfo, SourceOptions } from './source/worker-protocol.js';
import { showWebGl2Missing } from './ui/webgl-missing.js';
import { ViewState } from './view-state.js';

export type { BlendingOptions, BlendMode, BoundaryOptions } from './render/colour-options.js';

export interface SliceMapOptions {
  container: HTMLElement | string;
  /** URL of the cube directory (ending in /) or of its index.json. */
  source: string;
  /** Ground coordinates of the centre (default: the centre of the extent). */
  center?: [number, number];
  /** Scale denominator (default: the whole extent fits). */
  scaleDenominator?: number;
  /** Instead of center and scale: the ground box to show whole (as fitBounds). */
  bounds?: Bbox;
  /** Pins the base z (steps) of the slice instead of deriving it from the scale. */
  z?: number | null;
  surface?: SurfaceSpec | string;
  blending?: Partial<BlendingOptions>;
  boundaries?: Partial<BoundaryOptions>;
  /** Frames accumulated (jittered) while the view is still; 1: off. */
  supersampling?: number;
  /** GPU memory for chunks, bytes. */
  gpuMemoryBudget?: number;
  /** Chunks are also fetched this fraction of the view's size around it. */
  prefetchMargin?: number;
  /** Per frame, at most this many bytes of chunks go to the GPU (the rest wait a frame). */
  uploadBytesPerFrame?: number;
  sourceOptions?: Partial<SourceOptions>;
  /** Overrides window.devicePixelRatio. */
  pixelRatio?: number;
}

export interface Feature {
  face: number;
  /** The face below the slice at that point (0: none). */
  lowerFace: number;
  classIndex: number;
  classKey: string;
  classLabel: string;
  feature: number;
  properties: Record<string, unknown> | null;
  /** The states the face is alive in: stepLow <= s < stepHigh. */
  stepLow: number;
  stepHigh: number;
  /** Scale denominators at stepLow and stepHigh. */
  scaleRange: [number, number];
  /** z of the surface under the point and of the slice there. */
  z: number;
  sliceZ: number;
}

export interface RenderStats {
  frame: number;
  triangles: number;
  chunks: number;
  /** Last index query in the worker. */
  queryMs: number;
  gpuBytes: number;
  jittered: boolean;
}

export interface SliceMapEvents {
  /** The first complete map. */
  load: { timeMs: number };
  /** Nothing more to fetch, draw or accumulate. `complete`: every chunk on screen is drawn. */
  idle: { complete: boolean };
  render: RenderStats;
  error: SourceErrorInfo;
  meta: CubeMeta;
  move: { view: ViewGeometry; z: number };
  surface: Surface;
  contextlost: Record<string, never>;
  contextrestored: Record<string, never>;
  /** A chunk request went out (`file`), and a chunk went to the GPU. */
  dataloading: { file: string };
  data: { file: string };
}

/** A view to come, for prefetching: centre and scale denominator on this canvas. */
export interface PrefetchView {
  center: [number, number];
  scaleDenominator: number;
  /** The slice's base z there, when it does not follow the scale. */
  z?: number | null;
}

/** Runs at the start of every frame, before it is drawn (e.g. to advance an animation). */
export type FrameHook = (now: number) => void;

const DEFAULT_BUDGET = 256 * 1024 * 1024;
/** Blending in the 'moving' mode stays on this long after the slice last moved (ms). */
const MOVING_MS = 300;

export class SliceMap extends Evented<SliceMapEvents> {
  readonly container: HTMLElement;
  readonly canvas: HTMLCanvasElement;
  private readonly source: ChunkSource;
  private readonly renderer: Renderer | null;
  private readonly state = new ViewState();
  private readonly pixelRatioOption: number | undefined;
  private initialBounds: Bbox | null;
  private cssWidth = 0;
  private cssHeight = 0;

  private blending: BlendingOptions;
  private boundaries: BoundaryOptions;
  private supersampling: number;
  private readonly prefetchMargin: number;
  private readonly uploadBytesPerFrame: number;

  // Frame loop state.
  private raf = 0;
  private frameNo = 0;
  private accumulated = 0;
  private viewSeq = 0;
  private sentSeq = -1;
  private needed: NeededChunks | null = null;
  private visibleSet = new Set<string>();
  /** Kept on the GPU beyond the budget besides those on screen: margin and ahead. */
  private keptSet = new Set<string>();
  private ahead: PrefetchView[] = [];
  private aheadChanged = false;
  private readonly frameHooks = new Set<FrameHook>();
  private readonly pending: ChunkPayload[] = [];
  private lastSliceMove = -Infinity;
  private blendingWasOn = false;
  private loadFired = false;
  /** performance.now() (ms since the page's navigation) of the first complete map, or null. */
  firstCompleteAt: number | null = null;
  private idleFired = false;
  private readonly startTime = performance.now();
  private lastStats: RenderStats = { frame: 0, triangles: 0, chunks: 0, queryMs: 0, gpuBytes: 0, jittered: false };
  private readonly resizeObserver: ResizeObserver;
  private dprQuery: MediaQueryList | null = null;
  private removed = false;

  constructor(options: SliceMapOptions) {
    super();
    const c = typeof options.container === 'string' ? document.getElementById(options.container) : options.container;
    if (!c) throw new Error(`SliceMap: no container ${JSON.stringify(options.container)}`);
    this.container = c;
    if (getComputedStyle(c).position === 'static') c.style.position = 'relative';
    this.canvas = document.createElement('canvas');
    this.canvas.className = 'ssc-canvas';
    this.canvas.style.cssText = 'position:absolute;left:0;top:0;width:100%;height:100%;display:block;touch-action:none';
    c.appendChild(this.canvas);

    this.pixelRatioOption = options.pixelRatio;
    if (options.center) [this.state.centerX, this.state.centerY] = options.center;
    if (options.scaleDenominator !== undefined) this.state.scale = options.scaleDenominator;
    this.state.zPinned = options.z ?? null;
    this.initialBounds = options.bounds ?? null;
    if (options.surface) this.state.spec = typeof options.surface === 'string' ? parseSurface(options.surface) : options.surface;
    this.blending = { mode: 'moving', distance: 0.5, ...options.blending };
    this.boundaries = { enabled: false, width: 1, color: '#000000', opacity: 0.35, ...options.boundaries };
    this.supersampling = Math.max(1, Math.floor(options.supersampling ?? 16));
    this.prefetchMargin = options.prefetchMargin ?? 0.25;
    this.uploadBytesPerFrame = options.uploadBytesPerFrame ?? 16 * 1024 * 1024;

    this.renderer = Renderer.create(this.canvas, options.gpuMemoryBudget ?? DEFAULT_BUDGET, (files) => this.contextLost(files), () => this.contextRestored());
    if (!this.renderer) showWebGl2Missing(c);

    this.source = new ChunkSource(options.source, options.sourceOptions);
    this.source.on('meta', (m) => this.onMeta(m));
    this.source.on('needed', (n) => this.onNeeded(n));
    this.source.on('chunk', (ch) => {
      this.pending.push(ch);
      this.schedule();
    });
    this.source.on('status', (s) => {
      if (s.status === 'requested') this.fire('dataloading', { file: s.file });
    });
    this.source.on('error', (e) => {
      this.fire('error', e);
      // A failed chunk may be all that kept the map from idling.
      this.schedule();
    });

    this.resizeObserver = new ResizeObserver(() => this.measure());
    this.resizeObserver.observe(c);
    this.watchPixelRatio();
    this.measure();
  }

  // ---- view ----------------------------------------------------------------------------------

  get cubeMeta(): CubeMeta | null {
    return this.state.meta;
  }

  /** Device pixels per CSS pixel of the canvas. */
  get pixelRatio(): number {
    return this.pixelRatioOption ?? window.devicePixelRatio ?? 1;
  }

  getCenter(): [number, number] {
    return [this.state.centerX, this.state.centerY];
  }

  getScale(): number {
    return this.state.scale;
  }

  /** The base z of the slice (steps). */
  getZ(): number {
    return this.state.z();
  }

  jumpTo(v: { center?: [number, number]; scaleDenominator?: number; z?: number | null }): this {
    const zBefore = this.getZ();
    if (v.center) [this.state.centerX, this.state.centerY] = v.center;
    if (v.scaleDenominator !== undefined) {
      if (!(v.scaleDenominator > 0)) throw new Error('scaleDenominator must be > 0');
      this.state.scale = v.scaleDenominator;
    }
    if (v.z !== undefined) this.state.zPinned = v.z;
    if (this.getZ() !== zBefore) this.lastSliceMove = performance.now();
    this.viewChanged();
    return this;
  }

  /** Shows `bbox` whole, centred (the same box `ssc slice --bbox` shows at this canvas size). */
  fitBounds(bbox: Bbox, opts: { z?: number | null } = {}): this {
    const zBefore = this.getZ();
    const g = this.deviceSize();
    this.state.fit(bbox, g.width, g.height, this.deviceRatio());
    if (opts.z !== undefined) this.state.zPinned = opts.z;
    if (this.getZ() !== zBefore) this.lastSliceMove = performance.now();
    this.viewChanged();
    return this;
  }

  /** The view in device pixels (what the GPU draws). */
  getView(): ViewGeometry {
    const g = this.deviceSize();
    return this.state.geometry(g.width, g.height, this.deviceRatio());
  }

  /** Ground point under a CSS pixel position in the container. */
  unproject(point: [number, number]): [number, number] {
    const r = this.deviceRatio();
    return pixelToGround(this.getView(), point[0] * r, point[1] * r);
  }

  /**
   * Views the map will show soon, in order (a flight's path): their chunks are fetched after
   * those of the current view and its margin, and kept when they arrive. [] forgets them.
   */
  prefetch(views: PrefetchView[]): this {
    this.ahead = views.slice();
    this.aheadChanged = true;
    this.schedule();
    return this;
  }

  /** `fn` runs at the start of every frame; requestFrame() asks for one. */
  addFrameHook(fn: FrameHook): this {
    this.frameHooks.add(fn);
    return this;
  }

  removeFrameHook(fn: FrameHook): this {
    this.frameHooks.delete(fn);
    return this;
  }

  requestFrame(): void {
    this.schedule();
  }

  // ---- surface and rendering options ---------------------------------------------------------------

  getSurface(): Surface {
    return this.state.surface();
  }

  setSurface(spec: SurfaceSpec | string): this {
    this.state.spec = typeof spec === 'string' ? parseSurface(spec) : spec;
    this.lastSliceMove = performance.now();
    this.viewChanged();
    this.fire('surface', this.getSurface());
    return this;
  }

  setBlending(b: Partial<BlendingOptions>): this {
    this.blending = { ...this.blending, ...b };
    this.redraw();
    return this;
  }

  getBlending(): BlendingOptions {
    return { ...this.blending };
  }

  setBoundaries(b: Partial<BoundaryOptions>): this {
    this.boundaries = { ...this.boundaries, ...b };
    this.redraw();
    return this;
  }

  setSupersampling(frames: number): this {
    this.supersampling = Math.max(1, Math.floor(frames));
    this.redraw();
    return this;
  }

  setGpuMemoryBudget(bytes: number): this {
    if (this.renderer) this.renderer.store.budgetBytes = bytes;
    this.redraw();
    return this;
  }

  // ---- state -------------------------------------------------------------------------------------

  /** Every chunk the view shows is on the GPU: the map is complete. */
  loaded(): boolean {
    const n = this.needed;
    if (!this.renderer || !n || n.seq !== this.viewSeq || !n.indexComplete || this.pending.length > 0) return false;
    return n.visible.every((f) => this.renderer!.store.has(f));
  }

  /** Resolves at the next idle, or now when the map is idle. */
  whenIdle(): Promise<SliceMapEvents['idle']> {
    if (!this.idleFired) return this.once('idle');
    if (!this.raf) return Promise.resolve({ complete: this.loaded() });
    // Settled, with one more frame due (a late answer, a failed chunk): 'idle' is not fired
    // again for the same view, so look again after that frame (rAF callbacks run in order).
    return new Promise((resolve) => requestAnimationFrame(() => resolve(this.whenIdle())));
  }

  chunkStatuses(): Map<string, ChunkStatus> {
    return this.source.allStatuses();
  }

  /** The chunks the current view needs: on screen and in the prefetch margin. */
  neededChunks(): { visible: string[]; margin: string[]; ahead: string[] } {
    const n = this.needed;
    return { visible: [...this.visibleSet], margin: n ? [...n.margin] : [], ahead: n ? [...n.ahead] : [] };
  }

  stats(): RenderStats {
    return { ...this.lastStats };
  }

  // ---- picking and reading back ----------------------------------------------------------------

  /** The ID buffer of the current view (device pixels, rows from the top). */
  readIds(): IdBuffer | null {
    if (!this.renderer) return null;
    this.renderNowIfDirty();
    return this.renderer.readIds();
  }

  /** The absolute URL of the cube's index.json. */
  getSourceUrl(): string {
    return this.source.url;
  }

  /** Absolute URLs of the cube's files received so far (see VarioMap.getLoadedUrls). */
  getLoadedUrls(): Promise<string[]> {
    return this.source.loadedUrls();
  }

  /** The face under a CSS pixel position in the container, with its class, attributes and steps. */
  async queryFeatures(point: [number, number]): Promise<Feature[]> {
    const meta = this.state.meta;
    if (!this.renderer || !meta) return [];
    this.renderNowIfDirty();
    const r = this.deviceRatio();
    const x = Math.floor(point[0] * r), y = Math.floor(point[1] * r);
    const view = this.getView();
    if (x < 0 || y < 0 || x >= view.width || y >= view.height) return [];
    const px = this.renderer.readIds(x, y, 1, 1);
    if (!px || px.upper[0] === 0) return [];
    const face = px.upper[0]!;
    const [info] = await this.source.features([face]);
    const classIndex = info ? info.classIndex : px.classes[0]! & 0xffff;
    const cls = meta.style.classes[classIndex];
    const si = this.state.scaleInfo!;
    return [
      {
        face,
        lowerFace: px.lower[0]!,
        classIndex,
        classKey: cls?.key ?? String(classIndex),
        classLabel: cls?.label ?? String(classIndex),
        feature: info?.feature ?? -1,
        properties: info?.properties ?? null,
        stepLow: info?.stepLow ?? NaN,
        stepHigh: info?.stepHigh ?? NaN,
        scaleRange: info ? [scaleAtZ(si, info.stepLow), scaleAtZ(si, info.stepHigh)] : [NaN, NaN],
        z: px.z[0]!,
        sliceZ: px.slice[0]!,
      },
    ];
  }

  /** Measures the container again (a ResizeObserver does this by itself where it can). */
  resize(): this {
    this.measure();
    return this;
  }

  /** Renders again (e.g. after a style change). */
  redraw(): void {
    this.accumulated = 0;
    this.idleFired = false;
    this.schedule();
  }

  remove(): void {
    this.removed = true;
    this.frameHooks.clear();
    if (this.raf) cancelAnimationFrame(this.raf);
    this.raf = 0;
    this.resizeObserver.disconnect();
    this.dprQuery?.removeEventListener('change', this.onDprChange);
    this.source.destroy();
    this.renderer?.destroy();
    this.canvas.remove();
  }

  // ---- internals -------------------------------------------------------------------------------------

  private deviceRatio(): number {
    // The canvas is sized to whole device pixels; this is the exact ratio that gives.
    return this.cssWidth > 0 ? this.canvas.width / this.cssWidth : this.pixelRatio;
  }

  private deviceSize(): { width: number; height: number } {
    return { width: Math.max(1, this.canvas.width), height: Math.max(1, this.canvas.height) };
  }

  private measure(): void {
    const rect = this.container.getBoundingClientRect();
    const w = Math.max(1, rect.width), h = Math.max(1, rect.height);
    const dpr = this.pixelRatio;
    const dw = Math.max(1, Math.round(w * dpr)), dh = Math.max(1, Math.round(h * dpr));
    if (w === this.cssWidth && h === this.cssHeight && dw === this.canvas.width && dh === this.canvas.height) return;
    this.cssWidth = w;
    this.cssHeight = h;
    this.canvas.width = dw;
    this.canvas.height = dh;
    this.viewChanged();
  }

  private readonly onDprChange = (): void => {
    this.watchPixelRatio();
    this.measure();
  };

  private watchPixelRatio(): void {
    this.dprQuery?.removeEventListener('change', this.onDprChange);
    if (this.pixelRatioOption !== undefined || typeof matchMedia !== 'function') return;
    this.dprQuery = matchMedia(`(resolution: ${window.devicePixelRatio}dppx)`);
    this.dprQuery.addEventListener('change', this.onDprChange);
  }

  private onMeta(meta: CubeMeta): void {
    const st = this.state;
    st.setMeta(meta);
    const bounds = this.initialBounds ?? meta.extent;
    this.initialBounds = null;
    if (!Number.isFinite(st.centerX) || !Number.isFinite(st.scale)) {
      const { centerX, centerY, scale } = st;
      const g = this.deviceSize();
      st.fit(bounds, g.width, g.height, this.deviceRatio());
      // What the options gave wins over the fitted box.
      if (Number.isFinite(centerX)) [st.centerX, st.centerY] = [centerX, centerY];
      if (Number.isFinite(scale)) st.scale = scale;
    }
    this.renderer?.setMeta(meta);
    this.fire('meta', meta);
    this.viewChanged();
  }

  private viewChanged(): void {
    this.viewSeq++;
    this.accumulated = 0;
    this.idleFired = false;
    if (this.state.meta) this.fire('move', { view: this.getView(), z: this.getZ() });
    this.schedule();
  }

  private onNeeded(n: NeededChunks): void {
    // While the view moves every frame the answer is for a view a frame or two old: close
    // enough to protect chunks from eviction; loaded() waits for the current view's answer.
    // The same view is answered again when its sub-index files have come in.
    if (this.needed && n.seq < this.needed.seq) return;
    this.needed = n;
    this.visibleSet = new Set(n.visible);
    this.keptSet = new Set([...n.margin, ...n.ahead]);
    this.lastStats.queryMs = n.queryMs;
    this.schedule();
  }

  private schedule(): void {
    if (this.raf || this.removed) return;
    this.raf = requestAnimationFrame(() => {
      this.raf = 0;
      this.frame();
    });
  }

  private renderNowIfDirty(): void {
    if (this.raf) {
      cancelAnimationFrame(this.raf);
      this.raf = 0;
      this.frame();
    }
  }

  private frame(): void {
    const r = this.renderer;
    const meta = this.state.meta;
    if (!r || !meta || this.removed) return;
    const now = performance.now();
    for (const hook of [...this.frameHooks]) hook(now);
    const q = this.state.query(this.getView(), this.prefetchMargin);
    if (this.sentSeq !== this.viewSeq || this.aheadChanged) {
      this.sentSeq = this.viewSeq;
      this.aheadChanged = false;
      const ahead = this.ahead.map((v) => this.aheadView(v));
      this.source.setView({ seq: this.viewSeq, visible: q.visible, margin: q.margin, zMin: q.zMin, zMax: q.zMax, centerX: q.view.centerX, centerY: q.view.centerY, z: q.z, ahead });
    }
    if (r.lost) return; // contextrestored schedules the next frame
    this.frameNo++;
    // Draw the chunks on the GPU that meet the view (whatever the worker says is needed: until
    // its answer comes, the map keeps drawing what it has). Only a chunk among those changes
    // the picture; one for the margin or a flight ahead leaves a finished image as it is.
    const qb = { ground: q.visible, zMin: q.zMin, zMax: q.zMax };
    if (this.uploadPending(qb)) this.accumulated = 0;
    const evicted = r.evict(this.visibleSet, this.keptSet);
    this.source.evicted(evicted);

    const chunks = [];
    for (const c of r.store.values()) {
      if (boxMeets(c.bbox, qb)) {
        c.lastUsed = this.frameNo;
        chunks.push(c);
      }
    }
    // The depth test keeps the first of two equal depths: drawn in a fixed order (not the order
    // they arrived in), the same chunks give the same picture after a reload or a lost context.
    chunks.sort((a, b) => (a.file < b.file ? -1 : a.file > b.file ? 1 : 0));
    const moving = now - this.lastSliceMove < MOVING_MS;
    const blendOn = this.blending.mode === 'always' || (this.blending.mode === 'moving' && moving);
    if (blendOn !== this.blendingWasOn) this.accumulated = 0;
    this.blendingWasOn = blendOn;
    // Once the accumulation is complete the finished image stays on screen: a frame asked for
    // without a change (a late answer, a failed or dropped chunk) draws nothing, since one more
    // jittered frame averaged in would blur its edges. Every change resets `accumulated`.
    if (this.accumulated < this.supersampling) {
      const n = this.accumulated;
      const triangles = r.render(
        {
          view: q.view,
          surface: this.getSurface(),
          zMax: meta.zMax,
          jitter: jitter(n),
          colour: colourParams({
            view: q.view,
            ratio: this.deviceRatio(),
            background: meta.style.background,
            boundaries: this.boundaries,
            blendDistance: blendOn ? this.blending.distance : 0,
            weight: weight(n),
          }),
        },
        chunks,
      );
      this.accumulated = n + 1;
      this.lastStats = { frame: this.frameNo, triangles, chunks: chunks.length, queryMs: this.lastStats.queryMs, gpuBytes: r.store.bytes, jittered: n > 0 };
      this.fire('render', this.stats());
    }

    const complete = this.loaded();
    if (complete && !this.loadFired) {
      this.loadFired = true;
      this.firstCompleteAt = performance.now();
      this.fire('load', { timeMs: performance.now() - this.startTime });
    }
    // While the slice moves, blending is on for a moment: keep drawing until it ends, and only
    // then accumulate.
    const blendingToEnd = blendOn && this.blending.mode === 'moving';
    const accumulating = complete && this.accumulated < this.supersampling && !blendingToEnd;
    if (this.pending.length > 0 || accumulating || blendingToEnd) {
      this.schedule();
    } else if (!this.idleFired && this.needed?.seq === this.viewSeq) {
      // Settled: everything is drawn, or what is missing will not come (failed chunks).
      const waiting = this.needed.visible.some((f) => !r.store.has(f) && this.source.status(f) !== 'failed') || !this.needed.indexComplete;
      if (!waiting) {
        this.idleFired = true;
        this.fire('idle', { complete });
      }
    }
  }

  /** What the index is asked for a view to come: its box (with the margin) and z range. */
  private aheadView(v: PrefetchView): AheadView {
    const g = this.deviceSize();
    const st = new ViewState();
    if (this.state.meta) st.setMeta(this.state.meta);
    st.spec = this.state.spec;
    st.zPinned = v.z ?? null;
    [st.centerX, st.centerY] = v.center;
    st.scale = v.scaleDenominator;
    const q = st.query(st.geometry(g.width, g.height, this.deviceRatio()), this.prefetchMargin);
    return { box: q.margin, zMin: q.zMin, zMax: q.zMax, centerX: v.center[0], centerY: v.center[1], z: q.z };
  }

  /** Uploads chunks that arrived, within the per-frame byte budget; true when any that went up meets `drawn`. */
  private uploadPending(drawn: QueryBox): boolean {
    const r = this.renderer!;
    let bytes = 0;
    let changed = false;
    const dropped: string[] = [];
    while (this.pending.length > 0 && bytes < this.uploadBytesPerFrame) {
      const c = this.pending.shift()!;
      // A chunk the view no longer needs is not kept (it is fetched again if it comes back).
      if (this.needed && this.needed.seq === this.viewSeq && !this.visibleSet.has(c.file) && !this.keptSet.has(c.file)) {
        dropped.push(c.file);
        continue;
      }
      r.upload(c, this.frameNo);
      this.source.uploaded(c.file);
      this.fire('data', { file: c.file });
      bytes += c.vertexByteLength + c.indexSize * 3 * c.triangleCount;
      if (boxMeets(c.bbox, drawn)) changed = true;
    }
    this.source.evicted(dropped);
    return changed;
  }

  private contextLost(files: string[]): void {
    this.source.evicted(files);
    this.idleFired = false;
    this.fire('contextlost', {});
  }

  private contextRestored(): void {
    if (this.state.meta) this.renderer?.setMeta(this.state.meta);
    this.accumulated = 0;
    this.idleFired = false;
    this.fire('contextrestored', {});
    this.schedule();
  }
}
