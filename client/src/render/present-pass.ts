// Copies the colour target to the canvas.
import fullscreenVert from '../../shaders/fullscreen.vert?raw';
import presentFrag from '../../shaders/present.frag?raw';
import { Program } from './program.js';
import type { Targets } from './targets.js';

export class PresentPass {
  private readonly program: Program;

  constructor(private readonly gl: WebGL2RenderingContext) {
    this.program = new Program(gl, fullscreenVert, presentFrag, 'present pass');
  }

  draw(targets: Targets): void {
    const gl = this.gl;
    this.program.use();
    gl.activeTexture(gl.TEXTURE0);
    gl.bindTexture(gl.TEXTURE_2D, targets.colour);
    gl.uniform1i(this.program.loc('uColour'), 0);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    gl.viewport(0, 0, targets.width, targets.height);
    gl.disable(gl.DEPTH_TEST);
    gl.disable(gl.BLEND);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
    gl.bindTexture(gl.TEXTURE_2D, null);
  }

  delete(): void {
    this.program.delete();
  }
}
