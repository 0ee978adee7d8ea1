// How the line pass draws each line: per rule of the style (format/line-style.ts, whose index
// each line stores) its fill and casing colours, widths in millimetres on screen and the z range
// (its scale range turned into steps, with the ramps over which lines grow and shrink at its
// ends, format/line-ramp.ts) in which it shows, as a texture line.vert looks rules up in (one
// column per rule).
import { ruleRamp, type LineRamp } from '../../../format/line-ramp.js';
import type { ScaleInfo } from '../../../format/scale.js';
import type { CubeStyle } from '../../../format/style.js';
import { parseColour, type Rgba } from './style-texture.js';
import { texture2d } from './targets.js';

export interface LineRule {
  fill: Rgba;
  /** Drawn under every fill, `casingWidthMm` wide in all (alpha 0: none). */
  casing: Rgba;
  widthMm: number;
  casingWidthMm: number;
  /** The z range it shows in, and where lines are full width in it. */
  ramp: LineRamp;
}

/** The style's line rules as the GPU draws them: the casing's width is the whole band, fill and both sides. */
export function drawnLineRules(style: CubeStyle, info: ScaleInfo): LineRule[] {
  return style.lines.map((r) => ({
    fill: parseColour(r.color),
    casing: r.casing ? parseColour(r.casing.color) : [0, 0, 0, 0],
    widthMm: r.width,
    casingWidthMm: r.casing ? r.width + 2 * r.casing.width : 0,
    ramp: ruleRamp(info, r),
  }));
}

/** Rows: fill, casing, (width, casing width), the ramp (z0, z0Full, z1Full, z1); float32 keeps infinities. */
export function lineRuleData(rules: readonly LineRule[]): { width: number; data: Float32Array } {
  const width = Math.max(1, rules.length);
  const data = new Float32Array(width * ROWS * 4);
  rules.forEach((r, i) => {
    data.set(r.fill, 4 * i);
    data.set(r.casing, 4 * (width + i));
    data.set([r.widthMm, r.casingWidthMm, 0, 0], 4 * (2 * width + i));
    data.set([r.ramp.z0, r.ramp.z0Full, r.ramp.z1Full, r.ramp.z1], 4 * (3 * width + i));
  });
  return { width, data };
}

const ROWS = 4;

export function createLineRuleTexture(gl: WebGL2RenderingContext, rules: readonly LineRule[]): WebGLTexture {
  const { width, data } = lineRuleData(rules);
  const texture = texture2d(gl, gl.RGBA32F, width, ROWS);
  gl.bindTexture(gl.TEXTURE_2D, texture);
  gl.texSubImage2D(gl.TEXTURE_2D, 0, 0, 0, width, ROWS, gl.RGBA, gl.FLOAT, data);
  gl.bindTexture(gl.TEXTURE_2D, null);
  return texture;
}
