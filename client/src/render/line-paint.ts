// The cube's lines painted over the map by the pass that puts it on the canvas (colour or
// present pass, compiled with LINES): the GLSL they include (line-paint.glsl) and the textures
// it reads, the line pass's coverage and the line rules.
import linePaintGlsl from '../../shaders/line-paint.glsl?raw';
import type { Program } from './program.js';

/** What the line pass left for this frame: its coverage target and the rules' texture. */
export interface DrawnLines {
  cover: WebGLTexture;
  rules: WebGLTexture;
}

/** What a pass that paints them includes (ProgramVariants' includes). */
export const LINE_PAINT_INCLUDE = { 'line-paint.glsl': linePaintGlsl };

/** Binds the lines' textures to `p` on texture units `unit` and `unit + 1`. */
export function bindDrawnLines(gl: WebGL2RenderingContext, p: Program, lines: DrawnLines, unit: number): void {
  gl.activeTexture(gl.TEXTURE0 + unit);
  gl.bindTexture(gl.TEXTURE_2D, lines.cover);
  gl.uniform1i(p.loc('uLineCover'), unit);
  gl.activeTexture(gl.TEXTURE0 + unit + 1);
  gl.bindTexture(gl.TEXTURE_2D, lines.rules);
  gl.uniform1i(p.loc('uLineRules'), unit + 1);
}
