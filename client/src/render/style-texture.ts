// The style as a texture the colour pass looks classes up in (one column per class):
// row 0 the fill colour, row 1 the pattern colour and kind, row 2 the z range in which the
// pattern shows (its scale range turned into steps, so the pass compares with the slice's z).
import type { CubeMeta } from '../../../format/cube-index.js';
import { zAtScale } from '../../../format/scale.js';
import { texture2d } from './targets.js';

export type Rgba = [number, number, number, number];

const PATTERN_KIND = { hatch: 1, dots: 2, cross: 3 } as const;

/** "#rrggbb", "#rgb" or "#rrggbbaa" as 0..1 components. */
export function parseColour(css: string): Rgba {
  let h = css.trim().replace(/^#/, '');
  if (h.length === 3) h = [...h].map((c) => c + c).join('');
  if (!/^[0-9a-fA-F]{6}([0-9a-fA-F]{2})?$/.test(h)) throw new Error(`bad colour ${JSON.stringify(css)} (expected #rrggbb)`);
  const n = (i: number): number => parseInt(h.slice(i, i + 2), 16) / 255;
  return [n(0), n(2), n(4), h.length === 8 ? n(6) : 1];
}

export function styleData(meta: CubeMeta): { width: number; data: Float32Array } {
  const classes = meta.style.classes;
  const width = Math.max(1, classes.length);
  const data = new Float32Array(width * 3 * 4);
  const info = { baseScale: meta.baseScale, baseFaces: meta.baseFaces, scaleTable: meta.scaleTable, zMax: meta.zMax };
  classes.forEach((c, i) => {
    const fill = parseColour(c.color);
    data.set([fill[0], fill[1], fill[2], 1], 4 * i);
    const p = c.pattern;
    if (p) {
      const pc = parseColour(p.color);
      data.set([pc[0], pc[1], pc[2], PATTERN_KIND[p.kind]], 4 * (width + i));
      const zLo = p.minScale !== undefined ? zAtScale(info, p.minScale) : -1;
      const zHi = p.maxScale !== undefined ? zAtScale(info, p.maxScale) : 1e30;
      data.set([zLo, zHi, 0, 0], 4 * (2 * width + i));
    }
  });
  return { width, data };
}

export function createStyleTexture(gl: WebGL2RenderingContext, meta: CubeMeta): { texture: WebGLTexture; classCount: number } {
  const { width, data } = styleData(meta);
  const texture = texture2d(gl, gl.RGBA32F, width, 3);
  gl.bindTexture(gl.TEXTURE_2D, texture);
  gl.texSubImage2D(gl.TEXTURE_2D, 0, 0, 0, width, 3, gl.RGBA, gl.FLOAT, data);
  gl.bindTexture(gl.TEXTURE_2D, null);
  return { texture, classCount: meta.style.classes.length };
}
