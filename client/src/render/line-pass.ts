// Line pass: the cube's lines' coverage for the frame, before the map is coloured; the pass that
// puts the map on the canvas then paints them over it (line-paint.glsl), under the overlays.
// Lines are anti-aliased in the shader and not accumulated with the supersampled map: each
// frame draws them sharp at the unjittered view. Segments overlap where they join, and a line's
// anti-aliased edge blended twice there would bead (a translucent or thin line darker at every
// vertex). So each segment writes its casing's and its fill's coverage (and rule) into a target
// with blend MAX (line.frag), and every pixel is painted once from it, the fill over the casing:
// one draw of each segment, no depth test, and no full-screen pass of its own.
import lineFrag from '../../shaders/line.frag?raw';
import lineVert from '../../shaders/line.vert?raw';
import lineZ from '../../shaders/line-z.glsl?raw';
import { PIXEL_SIZE_MM } from '../../../format/pixel-size.js';
import type { ViewGeometry } from '../geometry/view.js';
import type { GpuLineChunk } from './gpu-line-chunk.js';
import { ProgramVariants } from './program-variants.js';
import type { Targets } from './targets.js';

export class LinePass {
  /** FLAT for a flat slice: each segment's ends and width worked out once, in line.vert, and a quad just around them. */
  private readonly programs: ProgramVariants;

  constructor(private readonly gl: WebGL2RenderingContext) {
    this.programs = new ProgramVariants(gl, lineVert, lineFrag, 'line pass', { 'line-z.glsl': lineZ });
  }

  /**
   * The chunks' lines' coverage, `ratio` device px per CSS px (a standard pixel of 0.28 mm is a
   * CSS pixel); `sliceRange` the slicing surface's z range over the view, `flatZ` its one z when
   * it is flat (surface-params.ts flatSliceZ), and `zWindow` how far beyond it the chunks keep
   * segments ready (gpu-line-chunk.ts). Returns the segments submitted (0: the line target was
   * left as it was, and there is nothing to paint).
   */
  draw(targets: Targets, view: ViewGeometry, ratio: number, chunks: readonly GpuLineChunk[], rules: WebGLTexture, sliceRange: [number, number], flatZ: number | null, zWindow: number): number {
    const gl = this.gl;
    let segments = 0;
    for (const c of chunks) segments += c.prepare(gl, sliceRange[0], sliceRange[1], zWindow);
    // No segment at this slice (the base scale, where roads are areas): no clear, nothing painted.
    if (segments === 0) return 0;
    const p = this.programs.get(flatZ === null ? [] : ['FLAT']);
    p.use();
    gl.bindFramebuffer(gl.FRAMEBUFFER, targets.lines().fb);
    gl.viewport(0, 0, targets.width, targets.height);
    gl.clearBufferfv(gl.COLOR, 0, new Float32Array([0, 0, 0, 0]));
    gl.disable(gl.DEPTH_TEST);
    gl.enable(gl.BLEND);
    gl.blendEquation(gl.MAX);
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
    if (flatZ !== null) gl.uniform1f(p.loc('uSliceZ'), flatZ);
    const uOffset = p.loc('uOffset');
    for (const c of chunks) {
      // The origin's offset in float64, rounded once: positions stay small.
      gl.uniform2f(uOffset, c.originX - view.centerX, c.originY - view.centerY);
      c.draw(gl);
    }
    gl.bindVertexArray(null);
    gl.disable(gl.BLEND);
    gl.blendEquation(gl.FUNC_ADD);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    for (const u of [1, 0]) {
      gl.activeTexture(gl.TEXTURE0 + u);
      gl.bindTexture(gl.TEXTURE_2D, null);
    }
    return segments;
  }

  delete(): void {
    this.programs.delete();
  }
}
