// Overlay pass: GeoJSON layers drawn over the map on the canvas, after the map and its lines, in the
// order they were added. Per layer, its fills, lines and circles first go into a coverage target
// (overlay-quad.frag: one channel each, the largest coverage per pixel kept), which is then
// painted in the layer's colours and opacities (overlay-composite.frag) into the overlays
// target: a translucent line is evenly translucent where its segments overlap at joins, and so
// is a layer of many touching polygons. The overlays target is then shown over the canvas;
// while neither the view nor the layers change (the frames that accumulate a still map) only
// that last step is repeated. Meshes are uploaded the first time they are drawn and kept until
// their layer changes or goes; a layer wholly off screen is skipped. The programs and the
// targets are made when a layer is first drawn: a map that shows no overlay compiles four
// programs fewer before its first frame and keeps no targets for them.
import fullscreenVert from '../../shaders/fullscreen.vert?raw';
import compositeFrag from '../../shaders/overlay-composite.frag?raw';
import showFrag from '../../shaders/overlay-show.frag?raw';
import fillFrag from '../../shaders/overlay-fill.frag?raw';
import fillVert from '../../shaders/overlay-fill.vert?raw';
import quadFrag from '../../shaders/overlay-quad.frag?raw';
import quadVert from '../../shaders/overlay-quad.vert?raw';
import { viewBbox, type ViewGeometry } from '../geometry/view.js';
import type { OverlayMesh } from '../overlay/overlay-quads.js';
import { GpuOverlayMesh, type DrawnPart } from './gpu-overlay-mesh.js';
import { Program } from './program.js';
import type { Rgba } from './style-texture.js';
import type { OverlayTargets, Targets } from './targets.js';

/** A layer's paint as the pass takes it: colours with their opacity as alpha, sizes in CSS px. */
export interface OverlayPaintParams {
  fill: Rgba;
  line: Rgba;
  circle: Rgba;
  circleStroke: Rgba;
  lineWidth: number;
  circleRadius: number;
  circleStrokeWidth: number;
}

export interface OverlayDrawable {
  /** Null: nothing to draw (yet). */
  mesh: OverlayMesh | null;
  paint: OverlayPaintParams;
}

/** Not written: a channel's half width that covers no pixel (overlay-quad.frag). */
const NONE = -1;

interface OverlayPrograms {
  fill: Program;
  quad: Program;
  composite: Program;
  show: Program;
}

export class OverlayPass {
  private made: OverlayPrograms | null = null;
  private readonly emptyVao: WebGLVertexArrayObject;
  private readonly meshes = new Map<OverlayMesh, GpuOverlayMesh>();

  constructor(private readonly gl: WebGL2RenderingContext) {
    this.emptyVao = gl.createVertexArray();
  }

  private programs(): OverlayPrograms {
    const gl = this.gl;
    return (this.made ??= {
      fill: new Program(gl, fillVert, fillFrag, 'overlay fill'),
      quad: new Program(gl, quadVert, quadFrag, 'overlay quads'),
      composite: new Program(gl, fullscreenVert, compositeFrag, 'overlay composite'),
      show: new Program(gl, fullscreenVert, showFrag, 'overlay show'),
    });
  }

  /** Frees the meshes of layers no longer drawn. */
  keep(layers: readonly OverlayDrawable[]): void {
    const live = new Set(layers.map((l) => l.mesh));
    for (const [mesh, gpu] of this.meshes) {
      if (live.has(mesh)) continue;
      gpu.delete();
      this.meshes.delete(mesh);
    }
  }

  /**
   * Draws the layers over the canvas (the default framebuffer), `ratio` device px per CSS px;
   * `redraw` false: as they were last drawn (same view, same layers), from the overlays target.
   */
  draw(targets: Targets, view: ViewGeometry, ratio: number, layers: readonly OverlayDrawable[], redraw: boolean): void {
    if (!layers.some((l) => l.mesh)) return;
    const gl = this.gl;
    const progs = this.programs(), t = targets.overlays();
    gl.disable(gl.DEPTH_TEST);
    gl.enable(gl.BLEND);
    gl.bindVertexArray(this.emptyVao);
    if (redraw) {
      gl.bindFramebuffer(gl.FRAMEBUFFER, t.overlaysFb);
      gl.clearBufferfv(gl.COLOR, 0, new Float32Array([0, 0, 0, 0]));
      for (const layer of layers) {
        if (!layer.mesh || !this.coverage(targets, t, progs, view, ratio, layer.mesh, layer.paint)) continue;
        gl.bindFramebuffer(gl.FRAMEBUFFER, t.overlaysFb);
        this.fullscreen(targets, progs.composite, t.coverage, 'uCoverage', (c) => {
          const p = layer.paint;
          gl.uniform4fv(c.loc('uFill'), p.fill);
          gl.uniform4fv(c.loc('uLine'), p.line);
          gl.uniform4fv(c.loc('uCircle'), p.circle);
          gl.uniform4fv(c.loc('uCircleStroke'), p.circleStroke);
        });
      }
    }
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    this.fullscreen(targets, progs.show, t.overlays, 'uOverlays', () => {});
    gl.bindVertexArray(null);
    gl.blendFunc(gl.ONE, gl.ZERO);
    gl.disable(gl.BLEND);
  }

  /** A premultiplied full-screen pass over the bound framebuffer, reading `texture`. */
  private fullscreen(targets: Targets, prog: Program, texture: WebGLTexture, name: string, uniforms: (p: Program) => void): void {
    const gl = this.gl;
    gl.viewport(0, 0, targets.width, targets.height);
    gl.blendEquation(gl.FUNC_ADD);
    gl.blendFunc(gl.ONE, gl.ONE_MINUS_SRC_ALPHA);
    prog.use();
    gl.activeTexture(gl.TEXTURE0);
    gl.bindTexture(gl.TEXTURE_2D, texture);
    gl.uniform1i(prog.loc(name), 0);
    uniforms(prog);
    gl.bindVertexArray(this.emptyVao);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
    gl.bindTexture(gl.TEXTURE_2D, null);
  }

  delete(): void {
    for (const m of this.meshes.values()) m.delete();
    this.meshes.clear();
    if (this.made) for (const p of Object.values(this.made)) p.delete();
    this.made = null;
    this.gl.deleteVertexArray(this.emptyVao);
  }

  /**
   * The layer's coverage of each pixel into the coverage target: fill (r), line (g), circle (b),
   * circle with stroke (a). False when none of it is on screen (nothing drawn).
   */
  private coverage(targets: Targets, t: OverlayTargets, progs: OverlayPrograms, view: ViewGeometry, ratio: number, mesh: OverlayMesh, p: OverlayPaintParams): boolean {
    const halfWidth = (p.lineWidth * ratio) / 2;
    const r = p.circleRadius * ratio, stroke = p.circleStrokeWidth * ratio;
    // How far past its positions the layer draws, in ground units.
    const out = (Math.max(halfWidth, r + stroke) + 1) * view.resolution;
    const [x0, y0, x1, y1] = viewBbox(view);
    const b = mesh.bbox;
    if (b[0] - out > x1 || b[2] + out < x0 || b[1] - out > y1 || b[3] + out < y0) return false;
    const gl = this.gl;
    let gpu = this.meshes.get(mesh);
    if (!gpu) this.meshes.set(mesh, (gpu = new GpuOverlayMesh(gl, mesh)));
    gl.bindFramebuffer(gl.FRAMEBUFFER, t.coverageFb);
    gl.viewport(0, 0, targets.width, targets.height);
    gl.clearBufferfv(gl.COLOR, 0, new Float32Array([0, 0, 0, 0]));
    gl.blendEquation(gl.MAX);
    // In float64 here: the origin's offset from the view centre (small near the view).
    const offset = [mesh.origin[0] - view.centerX, mesh.origin[1] - view.centerY] as const;
    const common = (prog: Program): void => {
      prog.use();
      gl.uniform2f(prog.loc('uOffset'), offset[0], offset[1]);
      gl.uniform1f(prog.loc('uRes'), view.resolution);
      gl.uniform2f(prog.loc('uHalfSize'), view.width / 2, view.height / 2);
    };
    const fillShown = p.fill[3] > 0;
    if (fillShown) {
      common(progs.fill);
      drawPart(gl, gpu.fill);
    }
    common(progs.quad);
    const quads = (parts: DrawnPart[], radii: [number, number, number, number]): void => {
      gl.uniform4fv(progs.quad.loc('uRadii'), radii);
      gl.uniform1f(progs.quad.loc('uReach'), Math.max(...radii) + 1);
      for (const part of parts) drawPart(gl, part);
    };
    // The fill's edge, anti-aliased: half a pixel either side of the rings.
    if (fillShown) quads([gpu.rings], [0, NONE, NONE, NONE]);
    if (p.lineWidth > 0 && p.line[3] > 0) quads([gpu.lines, gpu.rings], [NONE, halfWidth, NONE, NONE]);
    if (r + stroke > 0) quads([gpu.points], [NONE, NONE, r, r + stroke]);
    return true;
  }
}

function drawPart(gl: WebGL2RenderingContext, part: DrawnPart): void {
  if (part.count === 0) return;
  gl.bindVertexArray(part.vao);
  gl.drawElements(gl.TRIANGLES, part.count, gl.UNSIGNED_INT, 0);
}
