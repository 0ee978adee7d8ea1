// Lines over the face colours, the CPU reference for the map's line pass. Each line is drawn by
// its style rule (format/line-style.ts): `width` mm on screen (0.28 mm per pixel,
// format/pixel-size.ts), its colour, and a casing `casing.width` mm beyond each side. The
// casings of all lines go first, then the fills, so that lines meeting at a junction look
// joined; within each pass lines go in rule order, a later rule over an earlier one.
// A pixel shows a line when its centre lies within half the drawn width of a segment (round
// caps and joins, so no gaps at vertices), the slicing surface's z at that pixel lies in the
// segment's z range (lineSegments) and the scale of that z lies in the rule's scale range. The
// width is the style's times the line's share at that z (format/line-ramp.ts): lines grow as
// they appear and shrink as they go; a vertex that simplification takes away glides onto the
// chord of its neighbours before it goes (format/line-glide.ts), so the segment's ends are
// those at the pixel's z. No anti-aliasing: the oracle says which pixels a line covers.
import type { LineRecord } from '../../format/line-record.js';
import { glidingSegments, segmentAt, type GlidingSegment } from '../../format/line-glide.js';
import { lineRamp, lineWidthShare, ruleRamp, type LineRamp } from '../../format/line-ramp.js';
import type { LineRule } from '../../format/line-style.js';
import { PIXEL_SIZE_MM } from '../../format/pixel-size.js';
import type { ScaleInfo } from '../../format/scale.js';
import { pointSegmentDistance } from '../../format/point-segment.js';
import type { View } from './rasterize.js';

/** The surface's z at pixel p, and the cube's scales. */
export interface LineDepth {
  zAt: (p: number) => number;
  info: ScaleInfo;
}

/** What `drawLines` painted at a pixel: 0 nothing, 1 + 2 rule a casing, 2 + 2 rule a fill. */
export type LinePaint = Uint32Array;

/** The colour of a painted pixel (undefined where nothing is). */
export function linePaintColour(rules: readonly LineRule[], paint: number): string | undefined {
  if (paint === 0) return undefined;
  const r = rules[(paint - 1) >> 1]!;
  return paint & 1 ? r.casing!.color : r.color;
}

export interface DrawLinesOptions {
  /**
   * Paint at least this far either side of a line where it is drawn at all (device px): marks
   * where lines narrower than a pixel lie, which a test of pixel centres samples too sparsely
   * to compare an anti-aliased drawing with (default 0: the widths as they are).
   */
  minHalfPx?: number;
}

/** Per pixel (rows from the top), what the lines paint there (see LinePaint). */
export function drawLines(view: View, lines: readonly LineRecord[], rules: readonly LineRule[], depth: LineDepth, opts: DrawLinesOptions = {}): LinePaint {
  const { width: W, height: H } = view;
  const out = new Uint32Array(W * H);
  const ruleRamps = rules.map((r) => ruleRamp(depth.info, r));
  const ruleOf = (l: LineRecord): LineRule => {
    const r = rules[l.rule];
    if (!r) throw new Error(`a line of class ${l.classIndex}, feature #${l.feature} has line rule ${l.rule}; the style has ${rules.length}`);
    return r;
  };
  const order = lines
    .map((l, i) => ({ l, r: ruleOf(l), segs: glidingSegments(l, depth.info), ramps: [lineRamp(depth.info, l.zStart, l.zEnd), ruleRamps[l.rule]!] as const, i }))
    .sort((a, b) => a.l.rule - b.l.rule || a.i - b.i);
  for (const { l, r, segs, ramps } of order) {
    if (r.casing && r.width > 0) paint(view, out, segs, ramps, r.width / 2 + r.casing.width, 1 + 2 * l.rule, depth.zAt, opts.minHalfPx ?? 0);
  }
  for (const { l, r, segs, ramps } of order) {
    if (r.width > 0) paint(view, out, segs, ramps, r.width / 2, 2 + 2 * l.rule, depth.zAt, opts.minHalfPx ?? 0);
  }
  return out;
}

/** Paints `key` where the line (its segments), `halfMm` either side at full width, is drawn. */
function paint(view: View, out: Uint32Array, segs: readonly GlidingSegment[], [line, rule]: readonly [LineRamp, LineRamp], halfMm: number, key: number, zAt: (p: number) => number, minHalfPx: number): void {
  const { width: W, height: H, bbox } = view;
  const px = (bbox[2] - bbox[0]) / W, py = (bbox[3] - bbox[1]) / H;
  const half = (halfMm / PIXEL_SIZE_MM) * px, minHalf = minHalfPx * px, reach = Math.max(half, minHalf);
  for (const s of segs) {
    // Wherever its ends are at some z: at their points or their glides' targets.
    const xs = [s.ax, s.bx, s.atx, s.btx], ys = [s.ay, s.by, s.aty, s.bty];
    const i0 = Math.max(0, Math.ceil((Math.min(...xs) - reach - bbox[0]) / px - 0.5));
    const i1 = Math.min(W - 1, Math.floor((Math.max(...xs) + reach - bbox[0]) / px - 0.5));
    const j0 = Math.max(0, Math.ceil((bbox[3] - Math.max(...ys) - reach) / py - 0.5));
    const j1 = Math.min(H - 1, Math.floor((bbox[3] - Math.min(...ys) + reach) / py - 0.5));
    for (let j = j0; j <= j1; j++) {
      const y = bbox[3] - (j + 0.5) * py;
      for (let i = i0; i <= i1; i++) {
        const x = bbox[0] + (i + 0.5) * px;
        const p = j * W + i, z = zAt(p);
        if (!(s.z0 <= z && z < s.z1)) continue;
        const share = lineWidthShare(line, rule, z);
        if (share <= 0) continue;
        const [ax, ay, bx, by] = segmentAt(s, z);
        if (pointSegmentDistance(x, y, ax, ay, bx, by) <= Math.max(half * share, minHalf)) out[p] = key;
      }
    }
  }
}
