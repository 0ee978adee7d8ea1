// Line pass: the cube's lines over the map on the canvas, after the map is there and under the
// overlays. Every casing first, then every fill, so lines that meet look joined. Lines are
// anti-aliased in the shader and drawn on the canvas, not accumulated with the supersampled
// map: each frame draws them sharp at the unjittered view.
// Segments overlap where they join, and a line's anti-aliased edge blended twice there would
// bead (a translucent or thin line darker at every vertex). So the segments first write their
// coverage into a target where the depth test keeps, per pixel, the largest (casings in two
// channels, fills in two others), and one full-screen pass then paints each pixel once.
import fullscreenVert from '../../shaders/fullscreen.vert?raw';
import compositeFrag from '../../shaders/line-composite.frag?raw';
import lineFrag from '../../shaders/line.frag?raw';
import lineVert from '../../shaders/line.vert?raw';
import { PIXEL_SIZE_MM } from '../../../format/pixel-size.js';
import type { ViewGeometry } from '../geometry/view.js';
import type { GpuLineChunk } from './gpu-line-chunk.js';
import { Program } from './program.js';
import type { Targets } from './targets.js';

export class LinePass {
  private readonly program: Program;
  private readonly composite: Program;
  private readonly emptyVao: WebGLVertexArrayObject;

  constructor(private readonly gl: WebGL2RenderingContext) {
    this.program = new Program(gl, lineVert, lineFrag, 'line pass');
    this.composite = new Program(gl, fullscreenVert, compositeFrag, 'line composite');
    this.emptyVao = gl.createVertexArray();
  }

  /**
   * Draws the chunks' lines over the canvas, `ratio` device px per CSS px (a standard pixel of
   * 0.28 mm is a CSS pixel); `sliceRange` the slicing surface's z range over the view, and
   * `zWindow` how far beyond it the chunks keep segments ready (gpu-line-chunk.ts). Returns the
   * segments submitted (each drawn twice, casing and fill).
   */
  draw(targets: Targets, view: ViewGeometry, ratio: number, chunks: readonly GpuLineChunk[], rules: WebGLTexture, sliceRange: [number, number], zWindow: number): number {
    if (chunks.length === 0) return 0;
    const gl = this.gl;
    let segments = 0;
    for (const c of chunks) segments += c.prepare(gl, sliceRange[0], sliceRange[1], zWindow);
    // No segment at this slice (the base scale, where roads are areas): no clear, no full-screen pass.
    if (segments === 0) return 0;
    const p = this.program;
    p.use();
    gl.bindFramebuffer(gl.FRAMEBUFFER, targets.linesFb);
    gl.viewport(0, 0, targets.width, targets.height);
    gl.clearBufferfv(gl.COLOR, 0, new Float32Array([0, 0, 0, 0]));
    gl.disable(gl.BLEND);
    gl.enable(gl.DEPTH_TEST);
    gl.depthFunc(gl.LESS);
    gl.depthMask(true);
    gl.activeTexture(gl.TEXTURE0);
    gl.bindTexture(gl.TEXTURE_2D, targets.surface);
    gl.uniform1i(p.loc('uSurface'), 0);
    gl.activeTexture(gl.TEXTURE1);
    gl.bindTexture(gl.TEXTURE_2D, rules);
    gl.uniform1i(p.loc('uRules'), 1);
    gl.uniform1f(p.loc('uPxPerMm'), ratio / PIXEL_SIZE_MM);
    gl.uniform1f(p.loc('uRes'), view.resolution);
    gl.uniform2f(p.loc('uHalfSize'), view.width / 2, view.height / 2);
    gl.uniform2f(p.loc('uSliceRange'), sliceRange[0], sliceRange[1]);
    const uOffset = p.loc('uOffset'), uCasing = p.loc('uCasing');
    for (const casing of [1, 0]) {
      gl.clearBufferfv(gl.DEPTH, 0, [1]);
      gl.colorMask(casing === 1, casing === 1, casing === 0, casing === 0);
      gl.uniform1i(uCasing, casing);
      for (const c of chunks) {
        // The origin's offset in float64, rounded once: positions stay small.
        gl.uniform2f(uOffset, c.originX - view.centerX, c.originY - view.centerY);
        c.draw(gl);
      }
    }
    gl.colorMask(true, true, true, true);
    gl.disable(gl.DEPTH_TEST);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    gl.enable(gl.BLEND);
    gl.blendEquation(gl.FUNC_ADD);
    gl.blendFunc(gl.ONE, gl.ONE_MINUS_SRC_ALPHA);
    const q = this.composite;
    q.use();
    gl.activeTexture(gl.TEXTURE0);
    gl.bindTexture(gl.TEXTURE_2D, targets.coverage);
    gl.uniform1i(q.loc('uCover'), 0);
    gl.uniform1i(q.loc('uRules'), 1);
    gl.bindVertexArray(this.emptyVao);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
    gl.bindVertexArray(null);
    gl.disable(gl.BLEND);
    gl.blendFunc(gl.ONE, gl.ZERO);
    for (const u of [1, 0]) {
      gl.activeTexture(gl.TEXTURE0 + u);
      gl.bindTexture(gl.TEXTURE_2D, null);
    }
    return segments;
  }

  delete(): void {
    this.program.delete();
    this.composite.delete();
    this.gl.deleteVertexArray(this.emptyVao);
  }
}
