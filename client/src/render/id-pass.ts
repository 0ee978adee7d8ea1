// ID pass: every chunk's triangles into the ID targets; per pixel the nearest surface at or
// below the slicing surface wins (discard above, depth = distance below), its z taken where the
// pixel centre meets the plane through the triangle's vertices (id.vert, id.frag).
import { mat4 } from 'gl-matrix';
import idFrag from '../../shaders/id.frag?raw';
import idVert from '../../shaders/id.vert?raw';
import type { Surface } from '../../../format/slicing-surface.js';
import { viewBbox, type ViewGeometry } from '../geometry/view.js';
import type { GpuChunk } from './gpu-chunk.js';
import { ProgramVariants } from './program-variants.js';
import { flatSliceZ } from './surface-params.js';
import type { Targets } from './targets.js';

/** What the ID pass draws of each chunk. */
export interface DrawLimits {
  /** The slicing surface's highest z over the view: triangles wholly above it are not drawn. */
  sliceTop: number;
  /** Also the ground cells beside the view (to compare with drawing whole chunks). */
  beside: boolean;
}

export class IdPass {
  /** FLAT for a flat slice: its z a uniform, no texture read per fragment (a tenth of a frame on a software GPU). */
  private readonly programs: ProgramVariants;
  // Float64 matrices: the offset of a whole-unit point from the view centre is composed in
  // double precision and only the (small) result is rounded to float32.
  private readonly projection = new Float64Array(16);
  private readonly matrix = new Float64Array(16);
  private readonly matrix32 = new Float32Array(16);
  /** One call for a chunk's ranges (draw-ranges.ts), where the GPU has it. */
  private readonly multiDraw: WEBGL_multi_draw | null;

  constructor(private readonly gl: WebGL2RenderingContext) {
    this.programs = new ProgramVariants(gl, idVert, idFrag, 'id pass');
    this.multiDraw = gl.getExtension('WEBGL_multi_draw');
  }

  /**
   * Draws the chunks sliced by `surface` (whose z per pixel is in the surface target);
   * `jitter` shifts the image by a fraction of a pixel (supersampling); `limits` says what of
   * each chunk is left out (DrawLimits). Returns the triangles submitted.
   */
  draw(targets: Targets, view: ViewGeometry, chunks: Iterable<GpuChunk>, surface: Surface, zMax: number, limits: DrawLimits, jitter: [number, number]): number {
    const gl = this.gl;
    const flat = flatSliceZ(surface, zMax);
    const p = this.programs.get(flat === null ? [] : ['FLAT']);
    const hw = (view.width * view.resolution) / 2, hh = (view.height * view.resolution) / 2;
    mat4.ortho(this.projection, -hw, hw, -hh, hh, -1, 1);
    // Jitter in pixels -> clip space, applied after the projection.
    const jx = (2 * jitter[0]) / view.width, jy = (2 * jitter[1]) / view.height;
    gl.bindFramebuffer(gl.FRAMEBUFFER, targets.idFb);
    gl.viewport(0, 0, targets.width, targets.height);
    gl.clearBufferuiv(gl.COLOR, 0, new Uint32Array([0, 0, 0, 0]));
    gl.clearBufferuiv(gl.COLOR, 1, new Uint32Array([0xffffffff, 0, 0, 0]));
    gl.clearBufferfv(gl.DEPTH, 0, new Float32Array([1]));
    gl.enable(gl.DEPTH_TEST);
    gl.depthFunc(gl.LESS);
    gl.depthMask(true);
    // No face culling: the worker already kept only the upward-facing triangles, exactly (see
    // upward-triangles.ts); culling by the snapped winding would drop flipped slivers.
    gl.disable(gl.CULL_FACE);
    gl.disable(gl.BLEND);
    p.use();
    gl.activeTexture(gl.TEXTURE0);
    gl.bindTexture(gl.TEXTURE_2D, targets.surface);
    gl.uniform1i(p.loc('uSurface'), 0);
    gl.uniform1f(p.loc('uDepthScale'), 1 / (zMax + 1));
    // z is interpolated relative to the surface's base z too (id.frag says why), clamped as
    // surface.frag clamps it: a flat slice less uZRef is then 0 exactly.
    // For a flat slice the float32 this rounds to is flatSliceZ's, which FLAT reads as the slice's z.
    gl.uniform1f(p.loc('uZRef'), Math.min(Math.max(surface.base, 0), zMax));
    // One matrix for every chunk, from a whole-unit point near the centre; each chunk adds its
    // origin's (integer) offset from that point in the shader (id.vert says why).
    const rx = Math.floor(view.centerX), ry = Math.floor(view.centerY);
    mat4.translate(this.matrix, this.projection, [rx - view.centerX, ry - view.centerY, 0]);
    this.matrix[12]! += jx;
    this.matrix[13]! += jy;
    this.matrix32.set(this.matrix);
    gl.uniformMatrix4fv(p.loc('uMatrix'), false, this.matrix32);
    const uOffset = p.loc('uOffset');
    // The ground under the targets, with two pixels to spare on each side for the jitter (under
    // one pixel) and rounding: a chunk's cells wholly outside it cover none of its pixels.
    const ground = limits.beside ? [-Infinity, -Infinity, Infinity, Infinity] : viewBbox({ ...view, width: view.width + 4, height: view.height + 4 });
    let triangles = 0;
    for (const c of chunks) {
      gl.uniform2f(uOffset, c.originX - rx, c.originY - ry);
      triangles += c.draw(gl, limits.sliceTop, ground, this.multiDraw);
    }
    gl.bindVertexArray(null);
    gl.disable(gl.CULL_FACE);
    gl.disable(gl.DEPTH_TEST);
    return triangles;
  }

  delete(): void {
    this.programs.delete();
  }
}
