// The GPU side of the map: the WebGL2 context and everything made in it (passes, targets, the
// style and feature state textures, the chunks, the overlay layers' meshes), one frame at a time,
// and reading the ID buffer back. A lost context is given up quietly and rebuilt on restore; the
// chunks then have to be uploaded again (the overlays' meshes are uploaded again as drawn).
import type { CubeMeta } from '../../../format/cube-index.js';
import type { CubeStyle } from '../../../format/style.js';
import type { Surface } from '../../../format/slicing-surface.js';
import type { ViewGeometry } from '../geometry/view.js';
import type { Payload } from '../source/worker-protocol.js';
import { ChunkStore } from './chunk-store.js';
import { ColourPass, type ColourParams, type FrameColourParams } from './colour-pass.js';
import { FaceStateTexture } from './face-state-texture.js';
import type { GpuChunk } from './gpu-chunk.js';
import type { GpuLineChunk } from './gpu-line-chunk.js';
import type { IdBuffer } from './id-buffer.js';
import { IdPass, type DrawLimits } from './id-pass.js';
import { LinePass } from './line-pass.js';
import type { DrawnLines } from './line-paint.js';
import { createLineRuleTexture, drawnLineRules, type LineRule } from './line-rules.js';
import { lineAt, type LineHit } from '../engine/line-hit.js';
import { OverlayPass, type OverlayDrawable } from './overlay-pass.js';
import { PresentPass } from './present-pass.js';
import { patternsMeet } from './pattern-range.js';
import { createStyleTexture, parseColour, type DrawnStyle } from './style-texture.js';
import { SurfacePass } from './surface-pass.js';
import { flatSliceZ } from './surface-params.js';
import { Targets } from './targets.js';

export interface FrameParams {
  view: ViewGeometry;
  surface: Surface;
  zMax: number;
  /** Sub-pixel offset of this frame (device pixels); [0, 0] for the plain image. */
  jitter: [number, number];
  colour: FrameColourParams;
  /** Device pixels per CSS pixel (the overlays' widths are in CSS pixels). */
  pixelRatio: number;
  /** The slicing surface's z range over the view (line segments outside it are skipped). */
  sliceRange: [number, number];
}

interface Gpu {
  surface: SurfacePass;
  id: IdPass;
  colour: ColourPass;
  present: PresentPass;
  overlay: OverlayPass;
  lines: LinePass;
  targets: Targets;
  emptyVao: WebGLVertexArrayObject;
  style: DrawnStyle | null;
  lineRules: WebGLTexture | null;
  faceState: FaceStateTexture | null;
}

export class Renderer {
  readonly store: ChunkStore;
  /** Draw whole chunks, not only the triangles the slice needs (map-engine's setWholeChunks). */
  wholeChunks = false;
  private gpu: Gpu | null = null;
  private meta: CubeMeta | null = null;
  private style: CubeStyle | null = null;
  /** Each face's drawn states (bits): the feature state texture is made again from them after a lost context, and the colour pass leaves states out while there are none. */
  private readonly faceStates = new Map<number, number>();
  private lastFrame: FrameParams | null = null;
  /**
   * The frame whose colour went straight onto the canvas, not into the colour target; its ids
   * (and slicing surface) are still in the targets. A frame of weight 1 (every frame of a
   * moving map) skips the copy to the canvas that way, a tenth of the frame on a software GPU;
   * the first frame that averages into it puts its colour in the target first.
   */
  private canvasOnly: FrameParams | null = null;
  private lastChunks: GpuChunk[] = [];
  private lastLineChunks: GpuLineChunk[] = [];
  /** Whether the line target holds the last frame's lines (painted again by present). */
  private linesDrawn = false;
  /** The line rules drawn (the texture's contents, for picking). */
  private lineRules: LineRule[] = [];
  private idsJittered = false;
  /** The overlay layers drawn over the map, bottom first. */
  private overlays: readonly OverlayDrawable[] = [];
  /** What the overlays target holds: the layers drawn for this view (null: nothing yet). */
  private overlaysDrawn: { layers: readonly OverlayDrawable[]; view: ViewGeometry; ratio: number } | null = null;

  private constructor(
    readonly canvas: HTMLCanvasElement,
    readonly gl: WebGL2RenderingContext,
    budgetBytes: number,
    private readonly onLost: (files: string[]) => void,
    private readonly onRestored: () => void,
  ) {
    this.store = new ChunkStore(budgetBytes);
    canvas.addEventListener('webglcontextlost', this.lostHandler);
    canvas.addEventListener('webglcontextrestored', this.restoredHandler);
    this.build();
  }

  /** GPU memory the frame's targets take, bytes (the chunks' is the store's). */
  get targetBytes(): number {
    return this.gpu?.targets.bytes ?? 0;
  }

  /** Null where WebGL2 is missing. */
  static create(canvas: HTMLCanvasElement, budgetBytes: number, onLost: (files: string[]) => void, onRestored: () => void): Renderer | null {
    const gl = canvas.getContext('webgl2', {
      alpha: false,
      antialias: false,
      depth: false,
      stencil: false,
      premultipliedAlpha: true,
      preserveDrawingBuffer: false,
      powerPreference: 'high-performance',
    });
    if (!gl) return null;
    return new Renderer(canvas, gl, budgetBytes, onLost, onRestored);
  }

  get lost(): boolean {
    return this.gpu === null;
  }

  private build(): void {
    const gl = this.gl;
    if (gl.isContextLost()) return;
    const floatTargets = gl.getExtension('EXT_color_buffer_float') !== null;
    const targets = new Targets(gl, { floatTargets });
    this.overlaysDrawn = null;
    this.canvasOnly = null;
    this.linesDrawn = false;
    this.gpu = {
      surface: new SurfacePass(gl),
      id: new IdPass(gl),
      colour: new ColourPass(gl),
      present: new PresentPass(gl),
      overlay: new OverlayPass(gl),
      lines: new LinePass(gl),
      targets,
      emptyVao: gl.createVertexArray(),
      style: null,
      lineRules: null,
      faceState: null,
    };
    this.makeStyleTextures();
  }

  /** The style and feature state textures, made again for the current meta and style. */
  private makeStyleTextures(): void {
    const g = this.gpu, meta = this.meta;
    if (!g || !meta) return;
    this.makeDrawnStyle(g, this.style ?? meta.style, meta);
    g.faceState?.delete();
    g.faceState = new FaceStateTexture(this.gl, meta.faces.count, this.faceStates);
  }

  /** The class and line rule textures for `style`. */
  private makeDrawnStyle(g: Gpu, style: CubeStyle, meta: CubeMeta): void {
    if (g.style) this.gl.deleteTexture(g.style.texture);
    g.style = createStyleTexture(this.gl, style, meta);
    if (g.lineRules) this.gl.deleteTexture(g.lineRules);
    this.lineRules = drawnLineRules(style, meta);
    g.lineRules = createLineRuleTexture(this.gl, this.lineRules);
  }

  private readonly lostHandler = (ev: Event): void => {
    // Without preventDefault the browser never restores the context.
    ev.preventDefault();
    this.gpu = null;
    this.lastChunks = [];
    this.lastLineChunks = [];
    this.onLost(this.store.clear(null));
  };

  private readonly restoredHandler = (): void => {
    this.build();
    this.onRestored();
  };

  /** The cube, drawn in `style` (its own style unless changed at run time). */
  setMeta(meta: CubeMeta, style: CubeStyle = meta.style): void {
    this.meta = meta;
    this.style = style;
    this.makeStyleTextures();
  }

  /** The style changed: the next frame draws in it. */
  setStyle(style: CubeStyle): void {
    this.style = style;
    const g = this.gpu, meta = this.meta;
    if (!g || !meta) return;
    this.makeDrawnStyle(g, style, meta);
  }

  /** The face's drawn states from the next frame on (bit i: DRAWN_STATES[i]). */
  setFaceState(face: number, bits: number): void {
    if (bits) this.faceStates.set(face, bits);
    else this.faceStates.delete(face);
    this.gpu?.faceState?.set(face, bits);
  }

  /** The overlay layers from the next frame on, bottom first. */
  setOverlays(layers: readonly OverlayDrawable[]): void {
    this.overlays = layers;
    this.gpu?.overlay.keep(layers);
  }

  upload(payload: Payload, frame: number): boolean {
    if (!this.gpu) return false;
    this.store.add(this.gl, payload, frame);
    return true;
  }

  evict(visible: ReadonlySet<string>, margin: ReadonlySet<string>): string[] {
    if (!this.gpu) return [];
    return this.store.evict(this.gl, visible, margin);
  }

  /** Draws a frame; returns the triangles and line segments submitted. */
  render(f: FrameParams, chunks: GpuChunk[], lineChunks: GpuLineChunk[] = []): { triangles: number; segments: number } {
    const g = this.gpu;
    if (!g || !g.style || !g.faceState || !this.style) return { triangles: 0, segments: 0 };
    const ready = { style: g.style, faceState: g.faceState };
    const gl = this.gl;
    if (g.targets.width !== f.view.width || g.targets.height !== f.view.height) this.canvasOnly = null;
    g.targets.resize(f.view.width, f.view.height);
    gl.bindVertexArray(g.emptyVao);
    if (f.colour.weight < 1 && this.canvasOnly) {
      // The running mean starts from the last frame's colour: from its ids, before they go.
      g.colour.draw(g.targets, this.colourParams(ready, this.style, this.canvasOnly));
      this.canvasOnly = null;
    }
    g.surface.draw(g.targets, f.view, f.surface, f.zMax);
    const triangles = g.id.draw(g.targets, f.view, chunks, f.surface, f.zMax, this.drawLimits(f), f.jitter);
    this.idsJittered = f.jitter[0] !== 0 || f.jitter[1] !== 0;
    const segments = this.drawLines(g, f, lineChunks);
    const lines = this.paintedLines(g);
    gl.bindVertexArray(g.emptyVao);
    const toCanvas = f.colour.weight >= 1;
    g.colour.draw(g.targets, this.colourParams(ready, this.style, f), toCanvas, lines);
    if (toCanvas) this.canvasOnly = f;
    else g.present.draw(g.targets, lines);
    this.drawOverlays(g, f);
    gl.bindVertexArray(null);
    this.lastFrame = f;
    this.lastChunks = chunks;
    this.lastLineChunks = lineChunks;
    return { triangles, segments };
  }

  /** The colour pass's parameters for frame f: the frame's, with the renderer's textures and background. */
  private colourParams(g: { style: DrawnStyle; faceState: FaceStateTexture }, style: CubeStyle, f: FrameParams): ColourParams {
    const patterns = patternsMeet(g.style.patternZ, f.sliceRange[0], f.sliceRange[1]);
    return { ...f.colour, style: g.style.texture, classCount: g.style.classCount, background: parseColour(style.background), faceState: g.faceState, anyState: this.faceStates.size > 0, patterns, flatZ: flatSliceZ(f.surface, f.zMax) };
  }

  /** Shows the last frame's map again with the overlays as they are now (the map's image is kept). */
  present(): void {
    const g = this.gpu, f = this.lastFrame;
    // Nothing drawn since the context came back: the next frame draws everything.
    if (!g || !f || g.targets.width === 0) return;
    const { style, faceState } = g;
    const lines = this.paintedLines(g);
    if (this.canvasOnly && style && faceState && this.style) {
      g.colour.draw(g.targets, this.colourParams({ style, faceState }, this.style, this.canvasOnly), true, lines);
    } else g.present.draw(g.targets, lines);
    this.drawOverlays(g, f);
  }

  /** The cube's lines' coverage for frame f (the map is painted over it next); returns the segments submitted. */
  private drawLines(g: Gpu, f: FrameParams, lineChunks: readonly GpuLineChunk[]): number {
    // A window of 0.5% of the cube's z either side (a few dozen steps): refilled every few
    // frames of a zoom, a pass over the chunk's segments each time.
    const segments = g.lineRules && lineChunks.length > 0 ? g.lines.draw(g.targets, f.view, f.pixelRatio, lineChunks, g.lineRules, f.sliceRange, flatSliceZ(f.surface, f.zMax), 0.005 * f.zMax) : 0;
    this.linesDrawn = segments > 0;
    return segments;
  }

  /** The last frame's lines, to paint over its map (null: it had none). */
  private paintedLines(g: Gpu): DrawnLines | null {
    const cover = g.targets.lineCover;
    return this.linesDrawn && g.lineRules && cover ? { cover, rules: g.lineRules } : null;
  }

  /** The overlays over the canvas, drawn again only if the view or the layers changed. */
  private drawOverlays(g: Gpu, f: FrameParams): void {
    const d = this.overlaysDrawn, v = f.view;
    const same = d !== null && d.layers === this.overlays && d.ratio === f.pixelRatio && d.view.centerX === v.centerX && d.view.centerY === v.centerY && d.view.resolution === v.resolution && d.view.width === v.width && d.view.height === v.height;
    g.overlay.draw(g.targets, v, f.pixelRatio, this.overlays, !same);
    this.overlaysDrawn = { layers: this.overlays, view: v, ratio: f.pixelRatio };
  }

  /**
   * The highest z the id pass draws triangles from, and whether it leaves out the parts of a
   * chunk beside the view (all of every chunk with wholeChunks).
   */
  private drawLimits(f: FrameParams): DrawLimits {
    return this.wholeChunks ? { sliceTop: Infinity, beside: true } : { sliceTop: f.sliceRange[1], beside: false };
  }

  /** The ID targets as drawn without jitter (drawn again if the last frame was jittered); null when lost. */
  private unjittered(): Gpu | null {
    const g = this.gpu;
    const f = this.lastFrame;
    if (!g || !f) return null;
    if (this.idsJittered) {
      // Only chunks still on the GPU (some may have been evicted since).
      const chunks = this.lastChunks.filter((c) => this.store.get(c.file) === c);
      g.id.draw(g.targets, f.view, chunks, f.surface, f.zMax, this.drawLimits(f), [0, 0]);
      this.idsJittered = false;
    }
    return g;
  }

  /** The line drawn on top at device pixel (x, y) of the last frame, where the slice is at z. */
  lineAt(x: number, y: number, z: number): LineHit | null {
    const f = this.lastFrame;
    if (!f || !this.gpu) return null;
    const chunks = this.lastLineChunks.filter((c) => this.store.get(c.file) === c);
    return lineAt(chunks, this.lineRules, f.view, f.pixelRatio, x, y, z);
  }

  /** W x H pixels of a target's attachment from GL row glY up (4 values a pixel, rows from the bottom). */
  private readRect(fb: WebGLFramebuffer, attachment: number, integer: boolean, x: number, glY: number, W: number, H: number): Uint32Array | Float32Array {
    const gl = this.gl;
    gl.bindFramebuffer(gl.READ_FRAMEBUFFER, fb);
    gl.readBuffer(gl.COLOR_ATTACHMENT0 + attachment);
    const out = integer ? new Uint32Array(W * H * 4) : new Float32Array(W * H * 4);
    gl.readPixels(x, glY, W, H, integer ? gl.RGBA_INTEGER : gl.RGBA, integer ? gl.UNSIGNED_INT : gl.FLOAT, out);
    gl.bindFramebuffer(gl.READ_FRAMEBUFFER, null);
    return out;
  }

  /** The upper face of every pixel of the last frame, without jitter (rows from the top): a third of readIds' reading. */
  readUpperFaces(): { width: number; height: number; upper: Uint32Array } | null {
    const g = this.unjittered();
    if (!g) return null;
    const T = g.targets;
    const W = T.width, H = T.height;
    const ids = this.readRect(T.idFb, 0, true, 0, 0, W, H);
    const upper = new Uint32Array(W * H);
    for (let r = 0; r < H; r++) {
      const src = (H - 1 - r) * W;
      for (let i = 0; i < W; i++) upper[r * W + i] = ids[4 * (src + i)]!;
    }
    return { width: W, height: H, upper };
  }

  /** The ID buffer of the last frame, without jitter. Null before the first frame or when lost. */
  readIds(x = 0, y = 0, w?: number, h?: number): IdBuffer | null {
    const g = this.unjittered();
    if (!g) return null;
    const T = g.targets;
    const W = w ?? T.width - x, H = h ?? T.height - y;
    // Rows from the top in the result; GL counts them from the bottom.
    const glY = T.height - y - H;
    const read = (fb: WebGLFramebuffer, attachment: number, integer: boolean): Uint32Array | Float32Array => this.readRect(fb, attachment, integer, x, glY, W, H);
    const ids = read(T.idFb, 0, true) as Uint32Array;
    const aux = read(T.idFb, 1, true) as Uint32Array;
    let slice: Float32Array;
    if (T.surfaceFb) slice = read(T.surfaceFb, 0, false) as Float32Array;
    else {
      // Computed on the CPU: the same layout as a readback (4 per pixel, rows from the bottom).
      slice = new Float32Array(W * H * 4);
      const cpu = g.surface.cpu!;
      for (let r = 0; r < H; r++) for (let i = 0; i < W; i++) slice[4 * (r * W + i)] = cpu[(glY + r) * T.width + x + i]!;
    }
    const n = W * H;
    const out: IdBuffer = { width: W, height: H, upper: new Uint32Array(n), lower: new Uint32Array(n), classes: new Uint32Array(n), z: new Float32Array(n), slice: new Float32Array(n) };
    const zBits = new Float32Array(1);
    const zWord = new Uint32Array(zBits.buffer);
    for (let r = 0; r < H; r++) {
      const src = (H - 1 - r) * W;
      for (let i = 0; i < W; i++) {
        const s = 4 * (src + i), d = r * W + i;
        out.upper[d] = ids[s]!;
        out.lower[d] = ids[s + 1]!;
        out.classes[d] = aux[s]!;
        zWord[0] = aux[s + 1]!;
        out.z[d] = zBits[0]!;
        out.slice[d] = slice[s]!;
      }
    }
    return out;
  }

  destroy(): void {
    this.canvas.removeEventListener('webglcontextlost', this.lostHandler);
    this.canvas.removeEventListener('webglcontextrestored', this.restoredHandler);
    const g = this.gpu;
    if (g) {
      this.store.clear(this.gl);
      g.surface.delete();
      g.id.delete();
      g.colour.delete();
      g.present.delete();
      g.overlay.delete();
      g.lines.delete();
      g.targets.delete();
      this.gl.deleteVertexArray(g.emptyVao);
      if (g.style) this.gl.deleteTexture(g.style.texture);
      if (g.lineRules) this.gl.deleteTexture(g.lineRules);
      g.faceState?.delete();
    }
    this.gpu = null;
    // Gives the context itself back now rather than whenever the canvas is collected.
    this.gl.getExtension('WEBGL_lose_context')?.loseContext();
  }
}
