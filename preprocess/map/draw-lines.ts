// Lines over the face colours, the CPU reference for the map's line pass. Each line is drawn by
// its style rule (format/line-style.ts): `width` mm on screen (0.28 mm per pixel,
// format/pixel-size.ts), its colour, and a casing `casing.width` mm beyond each side. The
// casings of all lines go first, then the fills, so that lines meeting at a junction look
// joined; within each pass lines go in rule order, a later rule over an earlier one.
// A pixel shows a line when its centre lies within half the drawn width of a segment (round
// caps and joins, so no gaps at vertices), the slicing surface's z at that pixel lies in the
// segment's z range (lineSegments) and the scale of that z lies in the rule's scale range. No
// anti-aliasing: the oracle says which pixels a line covers.
import { lineSegments, type LineRecord } from '../../format/line-chunk.js';
import { lineRuleDrawnAt, type LineRule } from '../../format/line-style.js';
import { PIXEL_SIZE_MM } from '../../format/pixel-size.js';
import { pointSegmentDistance } from '../geom/point-segment.js';
import type { View } from './rasterize.js';

/** The surface's z at pixel p and the scale denominator of a z. */
export interface LineDepth {
  zAt: (p: number) => number;
  scaleAt: (z: number) => number;
}

/** What `drawLines` painted at a pixel: 0 nothing, 1 + 2 rule a casing, 2 + 2 rule a fill. */
export type LinePaint = Uint32Array;

/** The colour of a painted pixel (undefined where nothing is). */
export function linePaintColour(rules: readonly LineRule[], paint: number): string | undefined {
  if (paint === 0) return undefined;
  const r = rules[(paint - 1) >> 1]!;
  return paint & 1 ? r.casing!.color : r.color;
}

/** Per pixel (rows from the top), what the lines paint there (see LinePaint). */
export function drawLines(view: View, lines: readonly LineRecord[], rules: readonly LineRule[], depth: LineDepth): LinePaint {
  const { width: W, height: H } = view;
  const out = new Uint32Array(W * H);
  const scales = new Float64Array(W * H).fill(NaN);
  const scaleAtPixel = (p: number, z: number): number => (Number.isNaN(scales[p]!) ? (scales[p] = depth.scaleAt(z)) : scales[p]!);
  const ruleOf = (l: LineRecord): LineRule => {
    const r = rules[l.rule];
    if (!r) throw new Error(`a line of class ${l.classIndex}, feature #${l.feature} has line rule ${l.rule}; the style has ${rules.length}`);
    return r;
  };
  const order = lines.map((l, i) => ({ l, r: ruleOf(l), i })).sort((a, b) => a.l.rule - b.l.rule || a.i - b.i);
  for (const { l, r } of order) {
    if (r.casing && r.width > 0) paint(view, out, l, r, r.width / 2 + r.casing.width, 1 + 2 * l.rule, depth.zAt, scaleAtPixel);
  }
  for (const { l, r } of order) {
    if (r.width > 0) paint(view, out, l, r, r.width / 2, 2 + 2 * l.rule, depth.zAt, scaleAtPixel);
  }
  return out;
}

/** Paints `key` where the line, `halfMm` either side, is drawn. */
function paint(view: View, out: Uint32Array, l: LineRecord, r: LineRule, halfMm: number, key: number, zAt: (p: number) => number, scaleAt: (p: number, z: number) => number): void {
  const { width: W, height: H, bbox } = view;
  const px = (bbox[2] - bbox[0]) / W, py = (bbox[3] - bbox[1]) / H;
  const half = (halfMm / PIXEL_SIZE_MM) * px;
  for (const s of lineSegments(l)) {
    const i0 = Math.max(0, Math.ceil((Math.min(s.ax, s.bx) - half - bbox[0]) / px - 0.5));
    const i1 = Math.min(W - 1, Math.floor((Math.max(s.ax, s.bx) + half - bbox[0]) / px - 0.5));
    const j0 = Math.max(0, Math.ceil((bbox[3] - Math.max(s.ay, s.by) - half) / py - 0.5));
    const j1 = Math.min(H - 1, Math.floor((bbox[3] - Math.min(s.ay, s.by) + half) / py - 0.5));
    for (let j = j0; j <= j1; j++) {
      const y = bbox[3] - (j + 0.5) * py;
      for (let i = i0; i <= i1; i++) {
        const x = bbox[0] + (i + 0.5) * px;
        if (pointSegmentDistance(x, y, s.ax, s.ay, s.bx, s.by) > half) continue;
        const p = j * W + i, z = zAt(p);
        if (s.z0 <= z && z < s.z1 && lineRuleDrawnAt(r, scaleAt(p, z))) out[p] = key;
      }
    }
  }
}
