// Fills the surface target with the slicing surface's z per pixel: on the GPU (surface.frag),
// or, where float targets cannot be rendered to, on the CPU with the shared definitions.
import fullscreenVert from '../../shaders/fullscreen.vert?raw';
import surfaceFrag from '../../shaders/surface.frag?raw';
import { flatSliceZ, surfaceParams, MAX_IDW_POINTS } from './surface-params.js';
import { surfaceZ, type Surface } from '../../../format/slicing-surface.js';
import type { ViewGeometry } from '../geometry/view.js';
import { Program } from './program.js';
import type { Targets } from './targets.js';

export class SurfacePass {
  private readonly program: Program;
  /** The surface computed on the CPU (rows from the bottom), when float targets are missing. */
  cpu: Float32Array | null = null;
  private readonly flatZ = new Float32Array(4);

  constructor(private readonly gl: WebGL2RenderingContext) {
    this.program = new Program(gl, fullscreenVert, surfaceFrag, 'surface pass');
  }

  draw(targets: Targets, view: ViewGeometry, surface: Surface, zMax: number): void {
    const gl = this.gl;
    if (!targets.surfaceFb) {
      this.drawOnCpu(targets, view, surface, zMax);
      return;
    }
    const flat = flatSliceZ(surface, zMax);
    if (flat !== null) {
      // One z everywhere: a clear writes what surface.frag would (clamp in float32), without
      // running a shader per pixel, which on a software GPU cost a tenth of the frame.
      this.flatZ[0] = flat;
      gl.bindFramebuffer(gl.FRAMEBUFFER, targets.surfaceFb);
      gl.clearBufferfv(gl.COLOR, 0, this.flatZ);
      return;
    }
    const sp = surfaceParams(surface, view.centerX, view.centerY);
    const p = this.program;
    p.use();
    gl.uniform1i(p.loc('uKind'), sp.kind);
    gl.uniform1f(p.loc('uBase'), sp.base);
    gl.uniform1f(p.loc('uZMax'), zMax);
    gl.uniform2f(p.loc('uHalfSize'), view.width / 2, view.height / 2);
    gl.uniform1f(p.loc('uRes'), view.resolution);
    gl.uniform4f(p.loc('uP'), sp.p[0], sp.p[1], sp.p[2], sp.p[3]);
    gl.uniform1i(p.loc('uCount'), Math.min(sp.count, MAX_IDW_POINTS));
    gl.uniform1f(p.loc('uPower'), sp.power);
    if (sp.count > 0) gl.uniform3fv(p.loc('uPoints'), sp.points);
    gl.bindFramebuffer(gl.FRAMEBUFFER, targets.surfaceFb);
    gl.viewport(0, 0, targets.width, targets.height);
    gl.disable(gl.DEPTH_TEST);
    gl.disable(gl.BLEND);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
  }

  private drawOnCpu(targets: Targets, view: ViewGeometry, surface: Surface, zMax: number): void {
    const gl = this.gl;
    const { width: W, height: H } = targets;
    if (!this.cpu || this.cpu.length !== W * H) this.cpu = new Float32Array(W * H);
    const z = this.cpu;
    const x0 = view.centerX - (W / 2) * view.resolution;
    const y0 = view.centerY - (H / 2) * view.resolution;
    // Rows from the bottom, as textures are stored.
    for (let r = 0; r < H; r++) {
      const y = y0 + (r + 0.5) * view.resolution;
      for (let i = 0; i < W; i++) z[r * W + i] = surfaceZ(surface, x0 + (i + 0.5) * view.resolution, y, zMax);
    }
    gl.bindTexture(gl.TEXTURE_2D, targets.surface);
    gl.texSubImage2D(gl.TEXTURE_2D, 0, 0, 0, W, H, gl.RED, gl.FLOAT, z);
    gl.bindTexture(gl.TEXTURE_2D, null);
  }

  delete(): void {
    this.program.delete();
  }
}
