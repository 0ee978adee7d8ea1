// Line pass: the cube's lines over the map on the canvas, after the present pass and under the
// overlays. Every casing first, then every fill, so lines that meet look joined. Lines are
// anti-aliased in the shader and drawn on the canvas, not accumulated with the supersampled
// map: each frame draws them sharp at the unjittered view.
import lineFrag from '../../shaders/line.frag?raw';
import lineVert from '../../shaders/line.vert?raw';
import { PIXEL_SIZE_MM } from '../../../format/pixel-size.js';
import type { ViewGeometry } from '../geometry/view.js';
import type { GpuLineChunk } from './gpu-line-chunk.js';
import { Program } from './program.js';
import type { Targets } from './targets.js';

export class LinePass {
  private readonly program: Program;

  constructor(private readonly gl: WebGL2RenderingContext) {
    this.program = new Program(gl, lineVert, lineFrag, 'line pass');
  }

  /**
   * Draws the chunks' lines over the canvas, `ratio` device px per CSS px (a standard pixel of
   * 0.28 mm is a CSS pixel); `sliceRange` the slicing surface's z range over the view. Returns
   * the segments submitted.
   */
  draw(targets: Targets, view: ViewGeometry, ratio: number, chunks: readonly GpuLineChunk[], rules: WebGLTexture, sliceRange: [number, number]): number {
    if (chunks.length === 0) return 0;
    const gl = this.gl;
    const p = this.program;
    p.use();
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    gl.viewport(0, 0, targets.width, targets.height);
    gl.disable(gl.DEPTH_TEST);
    gl.enable(gl.BLEND);
    gl.blendEquation(gl.FUNC_ADD);
    gl.blendFunc(gl.ONE, gl.ONE_MINUS_SRC_ALPHA);
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
    let segments = 0;
    for (const casing of [1, 0]) {
      gl.uniform1i(uCasing, casing);
      for (const c of chunks) {
        // The origin's offset in float64, rounded once: positions stay small.
        gl.uniform2f(uOffset, c.originX - view.centerX, c.originY - view.centerY);
        c.draw(gl);
        segments += c.segmentCount;
      }
    }
    gl.bindVertexArray(null);
    gl.disable(gl.BLEND);
    gl.blendFunc(gl.ONE, gl.ZERO);
    for (const u of [1, 0]) {
      gl.activeTexture(gl.TEXTURE0 + u);
      gl.bindTexture(gl.TEXTURE_2D, null);
    }
    return segments / 2;
  }

  delete(): void {
    this.program.delete();
  }
}
