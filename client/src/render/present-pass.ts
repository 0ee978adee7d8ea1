// Copies the colour target to the canvas, with the cube's lines painted over it when given.
import fullscreenVert from '../../shaders/fullscreen.vert?raw';
import presentFrag from '../../shaders/present.frag?raw';
import { bindDrawnLines, LINE_PAINT_INCLUDE, type DrawnLines } from './line-paint.js';
import { ProgramVariants } from './program-variants.js';
import type { Targets } from './targets.js';

export class PresentPass {
  private readonly programs: ProgramVariants;

  constructor(private readonly gl: WebGL2RenderingContext) {
    this.programs = new ProgramVariants(gl, fullscreenVert, presentFrag, 'present pass', LINE_PAINT_INCLUDE);
  }

  draw(targets: Targets, lines: DrawnLines | null = null): void {
    const gl = this.gl;
    const p = this.programs.get(lines ? ['LINES'] : []);
    p.use();
    gl.activeTexture(gl.TEXTURE0);
    gl.bindTexture(gl.TEXTURE_2D, targets.colour);
    gl.uniform1i(p.loc('uColour'), 0);
    if (lines) bindDrawnLines(gl, p, lines, 1);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    gl.viewport(0, 0, targets.width, targets.height);
    gl.disable(gl.DEPTH_TEST);
    gl.disable(gl.BLEND);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
    for (let u = lines ? 2 : 0; u >= 0; u--) {
      gl.activeTexture(gl.TEXTURE0 + u);
      gl.bindTexture(gl.TEXTURE_2D, null);
    }
  }

  delete(): void {
    this.programs.delete();
  }
}
