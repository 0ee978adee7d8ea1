// How the line pass draws each line: per rule its fill and casing colours, widths in
// millimetres on screen and the z range (its scale range turned into steps) in which it shows,
// as a texture line.vert looks rules up in (one column per rule).
import type { CubeStyle } from '../../../format/style.js';
import { parseColour, type Rgba } from './style-texture.js';
import { texture2d } from './targets.js';

export interface LineRule {
  fill: Rgba;
  /** Drawn under every fill, `casingWidthMm` wide in all (alpha 0: none). */
  casing: Rgba;
  widthMm: number;
  casingWidthMm: number;
  zMin: number;
  zMax: number;
}

/** Until the style gives line rules: a line of each linear class in its class's colour, 0.56 mm (two standard pixels) wide. */
export function classLineRules(style: CubeStyle): LineRule[] {
  return style.classes.map((c) => ({
    fill: c.linear ? parseColour(c.color) : [0, 0, 0, 0],
    casing: [0, 0, 0, 0],
    widthMm: 0.56,
    casingWidthMm: 0,
    zMin: -Infinity,
    zMax: Infinity,
  }));
}

/** Rows: fill, casing, (width, casing width, zMin, zMax); float32 keeps infinities. */
export function lineRuleData(rules: readonly LineRule[]): { width: number; data: Float32Array } {
  const width = Math.max(1, rules.length);
  const data = new Float32Array(width * 3 * 4);
  rules.forEach((r, i) => {
    data.set(r.fill, 4 * i);
    data.set(r.casing, 4 * (width + i));
    data.set([r.widthMm, r.casingWidthMm, r.zMin, r.zMax], 4 * (2 * width + i));
  });
  return { width, data };
}

export function createLineRuleTexture(gl: WebGL2RenderingContext, rules: readonly LineRule[]): WebGLTexture {
  const { width, data } = lineRuleData(rules);
  const texture = texture2d(gl, gl.RGBA32F, width, 3);
  gl.bindTexture(gl.TEXTURE_2D, texture);
  gl.texSubImage2D(gl.TEXTURE_2D, 0, 0, 0, width, 3, gl.RGBA, gl.FLOAT, data);
  gl.bindTexture(gl.TEXTURE_2D, null);
  return texture;
}
