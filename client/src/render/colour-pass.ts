// Colour pass: the ID targets to colours (colour.frag), accumulated into the colour target
// with weight 1 / n for the n-th supersampling frame (a running mean), or drawn straight onto
// the canvas (renderer.ts says when), then with the cube's lines painted over it.
import colourFrag from '../../shaders/colour.frag?raw';
import fullscreenVert from '../../shaders/fullscreen.vert?raw';
import { FACE_STATE_SHIFT, type FaceStateTexture } from './face-state-texture.js';
import { bindDrawnLines, LINE_PAINT_INCLUDE, type DrawnLines } from './line-paint.js';
import { ProgramVariants } from './program-variants.js';
import type { Rgba } from './style-texture.js';
import type { Targets } from './targets.js';

export interface ColourParams {
  style: WebGLTexture;
  classCount: number;
  background: Rgba;
  /** c in steps; 0: no blending. */
  blendDistance: number;
  /** Boundary band in device pixels around each id change (both 0: none). */
  boundaryBefore: number;
  boundaryAfter: number;
  boundaryColour: Rgba;
  patternCell: number;
  patternLine: number;
  patternShift: [number, number];
  /** R8UI, one texel per face id (face-state-texture.ts): bit i set where state i is on. */
  faceState: Pick<FaceStateTexture, 'texture' | 'faceCount'>;
  /** Some face has a drawn state (else the pass is compiled without them and reads no state texel). */
  anyState: boolean;
  /** Some class's pattern shows in the slice's z range (else the pass is compiled without patterns). */
  patterns: boolean;
  /** Per drawn state (colour-options.ts, DRAWN_STATES), in the order painted. */
  statePaints: StatePaintParams[];
  /** Weight of this frame in the accumulated colour: 1 for the first. */
  weight: number;
  /** The slice's z when it is flat (surface-params.ts flatSliceZ), else null. */
  flatZ: number | null;
}

/** What a frame chooses (colour-options.ts); the renderer adds its textures, whether any face has a state or any pattern shows, the background and the flat slice's z. */
export type FrameColourParams = Omit<ColourParams, 'style' | 'classCount' | 'background' | 'faceState' | 'anyState' | 'patterns' | 'flatZ'>;

export interface StatePaintParams {
  /** rgb, alpha = opacity. */
  fill: Rgba;
  outline: Rgba;
  /** Device pixels of the outline inside the face (0: none). */
  width: number;
}

export class ColourPass {
  /** colour.frag compiled with the features a frame draws (a few at most). */
  private readonly programs: ProgramVariants;

  constructor(private readonly gl: WebGL2RenderingContext) {
    this.programs = new ProgramVariants(gl, fullscreenVert, colourFrag, 'colour pass', LINE_PAINT_INCLUDE);
    // The plain variant, compiled now so that a shader error shows at once.
    this.programs.get();
  }

  /** Into the colour target, or with `toCanvas` onto the canvas (weight 1 only) with `lines` over it. */
  draw(targets: Targets, c: ColourParams, toCanvas = false, lines: DrawnLines | null = null): void {
    const gl = this.gl;
    const features: string[] = [];
    // Lines are not accumulated: they go over the canvas only, sharp.
    const drawnLines = toCanvas ? lines : null;
    if (drawnLines) features.push('LINES');
    if (c.blendDistance > 0) features.push('BLENDING');
    if (c.boundaryBefore + c.boundaryAfter > 0) features.push('BOUNDARIES');
    if (c.anyState) features.push('STATES');
    if (c.patterns) features.push('PATTERNS');
    if (c.flatZ !== null) features.push('FLAT');
    const p = this.programs.get(features);
    p.use();
    // Only the textures the variant samples: with the ID target bound to a unit its program
    // does not sample (no boundaries or states), Chromium's SwiftShader later gave wrong face
    // ids, in readbacks and in the colours drawn from them (e2e/slice-accuracy.test.ts, among others).
    const bind = (unit: number, tex: WebGLTexture, name: string): void => {
      const loc = p.loc(name);
      if (loc === null) return;
      gl.activeTexture(gl.TEXTURE0 + unit);
      gl.bindTexture(gl.TEXTURE_2D, tex);
      gl.uniform1i(loc, unit);
    };
    bind(0, targets.ids, 'uIds');
    bind(1, targets.aux, 'uAux');
    bind(2, targets.surface, 'uSurface');
    bind(3, c.style, 'uStyle');
    bind(4, c.faceState.texture, 'uFaceState');
    if (drawnLines) bindDrawnLines(gl, p, drawnLines, 5);
    gl.uniform1ui(p.loc('uFaceCount'), c.faceState.faceCount);
    gl.uniform1ui(p.loc('uFaceStateShift'), FACE_STATE_SHIFT);
    gl.uniform1i(p.loc('uClassCount'), c.classCount);
    if (c.flatZ !== null) gl.uniform1f(p.loc('uSliceZ'), c.flatZ);
    gl.uniform4fv(p.loc('uBackground'), c.background);
    gl.uniform1f(p.loc('uBlendDistance'), c.blendDistance);
    gl.uniform1i(p.loc('uBoundaryBefore'), c.boundaryBefore);
    gl.uniform1i(p.loc('uBoundaryAfter'), c.boundaryAfter);
    gl.uniform4fv(p.loc('uBoundaryColour'), c.boundaryColour);
    gl.uniform1f(p.loc('uPatternInvCell'), 1 / c.patternCell);
    gl.uniform1f(p.loc('uPatternLine'), c.patternLine);
    gl.uniform2f(p.loc('uPatternShift'), c.patternShift[0], c.patternShift[1]);
    gl.uniform4fv(p.loc('uStateFill'), c.statePaints.flatMap((s) => s.fill));
    gl.uniform4fv(p.loc('uStateOutline'), c.statePaints.flatMap((s) => s.outline));
    gl.uniform1iv(p.loc('uStateWidth'), c.statePaints.map((s) => s.width));
    gl.bindFramebuffer(gl.FRAMEBUFFER, toCanvas ? null : targets.colourFb);
    gl.viewport(0, 0, targets.width, targets.height);
    gl.disable(gl.DEPTH_TEST);
    if (c.weight >= 1) {
      gl.disable(gl.BLEND);
    } else {
      // acc = weight * colour + (1 - weight) * acc
      gl.enable(gl.BLEND);
      gl.blendColor(0, 0, 0, c.weight);
      gl.blendFunc(gl.CONSTANT_ALPHA, gl.ONE_MINUS_CONSTANT_ALPHA);
    }
    gl.drawArrays(gl.TRIANGLES, 0, 3);
    gl.disable(gl.BLEND);
    for (let u = drawnLines ? 6 : 4; u >= 0; u--) {
      gl.activeTexture(gl.TEXTURE0 + u);
      gl.bindTexture(gl.TEXTURE_2D, null);
    }
  }

  delete(): void {
    this.programs.delete();
  }
}
