// The style as a texture the colour pass looks classes up in (one column per class):
// row 0 the fill colour and the pattern's kind (0: none), row 1 the pattern colour, row 2 the z range in which the
// pattern shows (its scale range turned into steps, so the pass compares with the slice's z).
import type { ScaleInfo } from '../../../format/scale.js';
import type { CubeStyle } from '../../../format/style.js';
import { patternZRange, patternZRanges } from './pattern-range.js';
import { texture2d } from './targets.js';

export type Rgba = [number, number, number, number];

const PATTERN_KIND = { hatch: 1, dots: 2, cross: 3 } as const;

/** "#rrggbb", "#rgb" or "#rrggbbaa" as 0..1 components; `what` names it in the error. */
export function parseColour(css: string, what = 'colour'): Rgba {
  let h = css.trim().replace(/^#/, '');
  if (h.length === 3) h = [...h].map((c) => c + c).join('');
  if (!/^[0-9a-fA-F]{6}([0-9a-fA-F]{2})?$/.test(h)) throw new Error(`${what} must be a colour "#rrggbb", not ${JSON.stringify(css)}`);
  const n = (i: number): number => parseInt(h.slice(i, i + 2), 16) / 255;
  return [n(0), n(2), n(4), h.length === 8 ? n(6) : 1];
}

export function styleData(style: CubeStyle, info: ScaleInfo): { width: number; data: Float32Array } {
  const classes = style.classes;
  const width = Math.max(1, classes.length);
  const data = new Float32Array(width * 3 * 4);
  classes.forEach((c, i) => {
    const fill = parseColour(c.color);
    const p = c.pattern;
    data.set([fill[0], fill[1], fill[2], p ? PATTERN_KIND[p.kind] : 0], 4 * i);
    if (p) {
      const pc = parseColour(p.color);
      data.set([pc[0], pc[1], pc[2], 1], 4 * (width + i));
      data.set([...patternZRange(p, info), 0, 0], 4 * (2 * width + i));
    }
  });
  return { width, data };
}

/** The style's texture and the z ranges of its patterns (the colour pass compiles patterns in only where one shows); `info` turns the patterns' scale ranges into z (steps). */
export function createStyleTexture(gl: WebGL2RenderingContext, style: CubeStyle, info: ScaleInfo): DrawnStyle {
  const { width, data } = styleData(style, info);
  const texture = texture2d(gl, gl.RGBA32F, width, 3);
  gl.bindTexture(gl.TEXTURE_2D, texture);
  gl.texSubImage2D(gl.TEXTURE_2D, 0, 0, 0, width, 3, gl.RGBA, gl.FLOAT, data);
  gl.bindTexture(gl.TEXTURE_2D, null);
  return { texture, classCount: style.classes.length, patternZ: patternZRanges(style, info) };
}

export interface DrawnStyle {
  texture: WebGLTexture;
  classCount: number;
  /** The z range of each class's pattern. */
  patternZ: [number, number][];
}
