// The frame loop: at most one frame per animation frame, and only when something asked for one.
// A frame advances the view's animation, reads the view, sends it to the worker, uploads the
// chunks that came, draws (accumulating jittered frames while the view is still) and reports
// when the image on screen shows the whole view ('complete', the first time 'load') and the
// moment nothing more is to come ('idle').
import { boxMeets } from '../../../format/index-query.js';
import type { MapView } from '../camera/map-view.js';
import { colourParams, type BlendingOptions, type BoundaryOptions, type StatePaints } from '../render/colour-options.js';
import type { GpuChunk } from '../render/gpu-chunk.js';
import type { GpuLineChunk } from '../render/gpu-line-chunk.js';
import type { Renderer } from '../render/renderer.js';
import { jitter, weight } from '../render/supersampling.js';
import { queryView, type ChunkResidency, type ViewQuery } from './chunk-residency.js';
import { FramePace } from './frame-pace.js';
import type { MapCanvas } from './map-canvas.js';
import { underView } from '../source/floor-choice.js';

/** Blending in the 'moving' mode stays on this long after the slice last moved (ms). */
const MOVING_MS = 300;

export interface RenderSettings {
  blending: BlendingOptions;
  boundaries: BoundaryOptions;
  /** How faces with `highlight: true` or `hover: true` in their feature state are drawn. */
  paints: StatePaints;
  /** Frames accumulated (jittered) while the view is still; 1: off. */
  supersampling: number;
  /** Draw the cube's lines. */
  lines: boolean;
  /** Chunks are also fetched this fraction of the view's size around it. */
  prefetchMargin: number;
}

/** The stats before any frame. */
export const EMPTY_STATS: RenderStats = { frame: 0, triangles: 0, segments: 0, chunks: 0, queryMs: 0, gpuBytes: 0, targetBytes: 0, jittered: false };

export interface RenderStats {
  frame: number;
  triangles: number;
  /** Line segments submitted (each drawn twice: casing and fill). */
  segments: number;
  chunks: number;
  /** Last index query in the worker. */
  queryMs: number;
  /** GPU memory for chunks, bytes. */
  gpuBytes: number;
  /** GPU memory for the frame's targets, bytes. */
  targetBytes: number;
  jittered: boolean;
}

/** What the loop reports. */
export interface FrameSink {
  render(stats: RenderStats): void;
  load(): void;
  /** The image on screen (frame `frame`) shows every chunk the current view needs. */
  complete(frame: number): void;
  idle(complete: boolean): void;
}

/**
 * Before the map's first complete image, an incomplete one of a view already on screen is drawn
 * at most this often (a view that changed is drawn at once). Each frame costs the GPU (on a
 * software GPU the CPU the worker decodes the first chunks on), and the first chunks come within
 * a second on a fast network: nlcd_zion at 1:50,000 drew 4 to 9 incomplete images before its
 * first complete map. With this, its first complete map came in 981 ms instead of 1,051, and
 * bgt_otterlo_1800m's at 1:1,000 in 456 instead of 526 (against the code before the worker's
 * faster drawing order too); medians of 9 page loads each, alternated, no network throttling.
 * On Slow 4G, where the network sets the pace: 2,924 ms before, 2,919 after (5 loads). 250 ms
 * still shows a slow network's map filling in.
 */
const PARTIAL_FRAME_MS = 250;

export class FrameLoop {
  /** performance.now() (ms since the page's navigation) of the first complete map, or null. */
  firstCompleteAt: number | null = null;
  private raf = 0;
  private frameNo = 0;
  private accumulated = 0;
  /** Bumped on every change of the view: the worker's answers and loaded() name the view they are for. */
  private viewSeq = 0;
  private lastSliceMove = -Infinity;
  /** When the last incomplete image before the first complete one was drawn. */
  private lastPartialFrame = -Infinity;
  /** When the first frame with the cube's metadata was asked for. */
  private firstViewAt: number | null = null;
  /** Schedules the next frame once an incomplete image may be drawn again (0: none set). */
  private partialTimer: ReturnType<typeof setTimeout> | 0 = 0;
  private blendingWasOn = false;
  private idleFired = false;
  /** The interim floor the last frame drew under the view (null: none; ChunkResidency.interimChunks). */
  private interimDrawn: ReadonlySet<string> | null = null;
  /** Things still coming that the map waits for before it is idle (holdIdle). */
  private holds = 0;
  /** The chunks the image on screen was drawn from, and the view it shows. */
  private shown: { seq: number; frame: number; files: Set<string> } | null = null;
  /** The last view reported complete. */
  private completeSeq = -1;
  private stopped = false;
  /** A view change waits to go to the worker (at the end of the current task). */
  private viewQueued = false;
  /** A view went to the worker since the last frame, ahead of it. */
  private sentEarly = false;
  /** The overlays changed: the finished map is shown again with them, without drawing it again. */
  private overlaysDue = false;
  /** The device's time per frame, told to the worker with each view. */
  private readonly pace = new FramePace();
  /** The last frame's stats; the targets' bytes are read as they are now (stats). */
  private lastStats: Omit<RenderStats, 'targetBytes'> = EMPTY_STATS;

  constructor(
    private readonly view: MapView,
    private readonly canvas: MapCanvas,
    private readonly renderer: Renderer,
    private readonly residency: ChunkResidency,
    private readonly settings: RenderSettings,
    private readonly sink: FrameSink,
  ) {}

  /** The view changed: a new view for the worker, and the image starts again. */
  viewChanged(sliceMoved: boolean): void {
    this.viewSeq++;
    if (sliceMoved) this.lastSliceMove = performance.now();
    this.redraw();
    // The worker hears of the first change since the last frame now, not at the next frame:
    // its answer (and the first fetches) can then come before that frame, instead of after the
    // frame has been drawn and shown, which may hold the page for as long as the GPU takes.
    // Changes made together (jumpTo's centre and scale) go as one; later ones before the frame
    // (a pinch's pointer moves) wait for it, so a gesture sends at most two views a frame.
    if (this.viewQueued || this.sentEarly) return;
    this.viewQueued = true;
    queueMicrotask(() => {
      this.viewQueued = false;
      if (this.stopped || !this.view.meta) return;
      this.sentEarly = true;
      this.request();
    });
  }

  /** Draws again from the first frame (a setting changed). */
  redraw(): void {
    this.accumulated = 0;
    this.idleFired = false;
    this.schedule();
  }

  /** The overlay layers changed (the map did not). */
  overlaysChanged(): void {
    this.overlaysDue = true;
    this.schedule();
  }

  /** Something the map is to show is still coming (an overlay's geometry): no 'idle' before it has. */
  holdIdle(coming: Promise<void>): void {
    this.holds++;
    this.idleFired = false;
    const done = (): void => {
      this.holds--;
      this.schedule();
    };
    coming.then(done, done);
  }

  /** The GPU lost its chunks (a lost context): the map is not idle until they are back. */
  lost(): void {
    this.idleFired = false;
    // The image is gone with the chunks: the view is complete again only once drawn again.
    this.shown = null;
  }

  schedule(): void {
    if (this.raf || this.stopped) return;
    this.raf = requestAnimationFrame(() => {
      this.raf = 0;
      this.frame();
    });
  }

  /** Draws the frame that is due now, so that what is read back is the current view. */
  renderNowIfDirty(): void {
    if (!this.raf) return;
    cancelAnimationFrame(this.raf);
    this.raf = 0;
    this.frame(true);
  }

  loaded(): boolean {
    return this.residency.loaded(this.viewSeq);
  }

  /**
   * The worker answered: the image on screen may already show everything the view needs (a
   * small move keeps its chunks), known only now. Said at once, without drawing it again.
   */
  answered(): void {
    this.reportComplete();
  }

  /** 'complete' (and the first time 'load') once per view, when the image on screen shows all its chunks. */
  private reportComplete(): void {
    const s = this.shown;
    if (!s || s.seq !== this.viewSeq || this.completeSeq === this.viewSeq || !this.residency.shows(this.viewSeq, s.files)) return;
    this.completeSeq = this.viewSeq;
    if (this.firstCompleteAt === null) {
      this.firstCompleteAt = performance.now();
      this.sink.load();
    }
    this.sink.complete(s.frame);
  }

  /** Resolves at the next idle, or now when the map is idle. */
  whenIdle(once: () => Promise<{ complete: boolean }>): Promise<{ complete: boolean }> {
    if (!this.idleFired) return once();
    if (!this.raf) return Promise.resolve({ complete: this.loaded() });
    // Settled, with one more frame due (a late answer, a failed chunk): 'idle' is not fired
    // again for the same view, so look again after that frame (rAF callbacks run in order).
    return new Promise((resolve) => requestAnimationFrame(() => resolve(this.whenIdle(once))));
  }

  stats(): RenderStats {
    // The targets' bytes as they are now: a frame that only shows new overlays (present) makes theirs.
    return { ...this.lastStats, queryMs: this.residency.queryMs, targetBytes: this.renderer.targetBytes };
  }

  stop(): void {
    this.stopped = true;
    if (this.partialTimer) clearTimeout(this.partialTimer);
    this.partialTimer = 0;
    if (this.raf) cancelAnimationFrame(this.raf);
    this.raf = 0;
  }

  /** Sends the current view to the worker unless it has it; returns its query. */
  private request(): ViewQuery {
    const margin = this.settings.prefetchMargin;
    const q = queryView(this.view, this.canvas.geometry(this.view), margin);
    this.residency.request(this.viewSeq, q, (c) => queryView(this.view, this.canvas.geometry(this.view, c), margin, this.view.zAt(c.scale)), this.pace.ms);
    return q;
  }

  /** `force`: draw whatever is due, even an incomplete image that PARTIAL_FRAME_MS would hold back. */
  private frame(force = false): void {
    const r = this.renderer;
    const meta = this.view.meta;
    if (!meta || this.stopped) return;
    const t = performance.now();
    this.view.tick(t);
    const q = this.request();
    this.sentEarly = false;
    if (r.lost) return; // contextrestored schedules the next frame
    this.frameNo++;
    // Draw the chunks on the GPU that meet the view (whatever the worker says is needed: until
    // its answer comes, the map keeps drawing what it has). Only a chunk among those changes
    // the picture; one for the margin or a flight ahead leaves a finished image as it is. Once
    // all that the view shows are here, those alone: not the same floor twice.
    const drawn = { ground: q.visible, zMin: q.zMin, zMax: q.zMax };
    if (this.residency.upload(this.frameNo, this.viewSeq, drawn)) this.accumulated = 0;
    this.residency.evict();
    const shown = this.residency.shownChunks(this.viewSeq);
    // Until then, a first view just above the floor's top draws the floor under itself: its
    // triangles lie at z 0, under the slice, where the view's own chunks cover them as they come.
    const interim = shown ? null : this.residency.interimChunks(this.viewSeq);
    // A picture drawn with another interim floor is not accumulated into.
    if (interim !== this.interimDrawn) this.accumulated = 0;
    this.interimDrawn = interim;
    const under = underView(q.visible);
    const chunks: GpuChunk[] = [];
    const lineChunks: GpuLineChunk[] = [];
    const files = new Set<string>();
    for (const c of r.store.values()) {
      const meets = boxMeets(c.bbox, drawn) || (interim?.has(c.file) === true && boxMeets(c.bbox, under));
      if (!meets || (shown && !shown.has(c.file))) continue;
      files.add(c.file);
      c.lastUsed = this.frameNo;
      if (c.kind !== 'lines') chunks.push(c);
      else if (this.settings.lines) lineChunks.push(c);
    }
    // The depth test keeps the first of two equal depths: drawn in a fixed order (not the order
    // they arrived in), the same chunks give the same picture after a reload or a lost context.
    // Lines too: a later line is drawn over an earlier one.
    const byFile = (a: { file: string }, b: { file: string }): number => (a.file < b.file ? -1 : a.file > b.file ? 1 : 0);
    chunks.sort(byFile);
    lineChunks.sort(byFile);
    const { blending, boundaries, supersampling } = this.settings;
    const blendOn = blending.mode === 'always' || (blending.mode === 'moving' && t - this.lastSliceMove < MOVING_MS);
    if (blendOn !== this.blendingWasOn) this.accumulated = 0;
    this.blendingWasOn = blendOn;
    // The first image, before any of its chunks has come, waits (at most PARTIAL_FRAME_MS from
    // the first view) while the map hands the worker the first view's chunks (ChunkSource's head
    // start): their bodies pass through this thread, which a software GPU holds for 100 ms and
    // more as it draws its first image (it compiles the shaders then). On a fast network they
    // come within that time, and a slow network's come after the image.
    this.firstViewAt ??= t;
    if (!force && this.shown === null && files.size === 0 && this.residency.handingOver) {
      const wait = this.firstViewAt + PARTIAL_FRAME_MS - t;
      if (wait > 0) {
        if (!this.partialTimer) this.partialTimer = setTimeout(() => ((this.partialTimer = 0), this.schedule()), wait);
        return;
      }
    }
    // Until the first complete map, an incomplete image of a view already on screen (only more
    // of its chunks came) at most every PARTIAL_FRAME_MS; a view that changed is drawn at once.
    if (!force && this.firstCompleteAt === null && this.accumulated < supersampling && this.shown?.seq === this.viewSeq && !this.residency.shows(this.viewSeq, files)) {
      const wait = this.lastPartialFrame + PARTIAL_FRAME_MS - t;
      if (wait > 0) {
        // The chunks that came went to the GPU above, up to the frame's budget: the rest next
        // frame. A chunk that comes meanwhile asks for a frame of its own, complete or not.
        if (this.residency.hasPending) this.schedule();
        if (!this.partialTimer) this.partialTimer = setTimeout(() => ((this.partialTimer = 0), this.schedule()), wait);
        return;
      }
    }
    if (this.partialTimer) clearTimeout(this.partialTimer);
    this.partialTimer = 0;
    // Once the accumulation is complete the finished image stays on screen: a frame asked for
    // without a change (a late answer, a failed or dropped chunk) draws nothing, since one more
    // jittered frame averaged in would blur its edges. Every change resets `accumulated`.
    if (this.accumulated < supersampling) {
      this.pace.frameAt(t);
      if (this.firstCompleteAt === null) this.lastPartialFrame = t;
      const n = this.accumulated;
      const colour = colourParams({ view: q.view, ratio: this.canvas.deviceRatio(), boundaries, paints: this.settings.paints, blendDistance: blendOn ? blending.distance : 0, weight: weight(n) });
      const { triangles, segments } = r.render({ view: q.view, surface: this.view.surface(), zMax: meta.zMax, jitter: jitter(n), colour, pixelRatio: this.canvas.deviceRatio(), sliceRange: [q.zMin, q.zMax] }, chunks, lineChunks);
      this.accumulated = n + 1;
      this.lastStats = { frame: this.frameNo, triangles, segments, chunks: chunks.length, queryMs: this.residency.queryMs, gpuBytes: r.store.bytes, jittered: n > 0 };
      // Line chunks count as shown with lines turned off: there is nothing more to fetch for them.
      this.shown = { seq: this.viewSeq, frame: this.frameNo, files };
      this.sink.render(this.stats());
    } else if (this.overlaysDue) {
      r.present();
    }
    this.overlaysDue = false;
    this.settle(blendOn && blending.mode === 'moving');
  }

  /** After a frame: the next one, or 'load' and 'idle' when nothing more is to come. */
  private settle(blendingToEnd: boolean): void {
    this.reportComplete();
    const complete = this.loaded();
    // While the slice moves, blending is on for a moment: keep drawing until it ends, and only
    // then accumulate.
    const accumulating = complete && this.accumulated < this.settings.supersampling && !blendingToEnd;
    if (this.residency.hasPending || accumulating || blendingToEnd) {
      this.schedule();
    } else if (!this.idleFired && this.holds === 0 && this.residency.settled(this.viewSeq)) {
      // Settled: everything is drawn, or what is missing will not come (failed chunks).
      this.idleFired = true;
      this.sink.idle(complete);
    }
  }
}
