// Which of the cube's lines is drawn at a pixel: the line pass's rule on the CPU. A segment
// counts where the pixel centre lies within half its drawn width (the casing's, when wider) and
// the slice's z there lies in the segment's z range and its rule's, the width narrowed by the
// line's and the rule's ramps at that z (format/line-ramp.ts), its ends where their glides have
// taken them at that z (format/line-glide.ts). Of several, the one drawn last
// (on top) wins: fills after casings, chunks in the order drawn, segments in order.
import { lineWidthShare } from '../../../format/line-ramp.js';
import { pointSegmentDistance } from '../../../format/point-segment.js';
import { PIXEL_SIZE_MM } from '../../../format/pixel-size.js';
import { pixelToGround, type ViewGeometry } from '../geometry/view.js';
import type { GpuLineChunk } from '../render/gpu-line-chunk.js';
import type { LineRule } from '../render/line-rules.js';

export interface LineHit {
  chunk: GpuLineChunk;
  /** The line's index in its chunk. */
  line: number;
}

/** The line on top at device pixel (x, y) (its centre), where the slice is at z; null: none. */
export function lineAt(chunks: readonly GpuLineChunk[], rules: readonly LineRule[], view: ViewGeometry, ratio: number, x: number, y: number, z: number): LineHit | null {
  const [gx, gy] = pixelToGround(view, x + 0.5, y + 0.5);
  const pxPerMm = ratio / PIXEL_SIZE_MM;
  let best: LineHit | null = null;
  let bestFill = false;
  for (const c of chunks) {
    const px = gx - c.originX, py = gy - c.originY;
    for (let k = 0; k < c.segmentCount; k++) {
      const rule = rules[c.segmentRule[k]!];
      if (!rule || !c.segmentAliveAt(k, z)) continue;
      const share = lineWidthShare(c.lineRamp(c.segmentLine[k]!), rule.ramp, z);
      const fill = rule.fill[3] > 0 ? rule.widthMm * share : 0;
      const casing = rule.casing[3] > 0 ? rule.casingWidthMm * share : 0;
      const half = (Math.max(fill, casing) / 2) * pxPerMm;
      if (half <= 0) continue;
      const [ax, ay, bx, by] = c.segmentAt(k, z);
      const d = pointSegmentDistance(px, py, ax, ay, bx, by) / view.resolution;
      if (d > half) continue;
      // A fill is drawn over every casing; among fills (or among casings), the later on top.
      const isFill = d <= (fill / 2) * pxPerMm;
      if (isFill || !bestFill) {
        best = { chunk: c, line: c.segmentLine[k]! };
        bestFill = isFill;
      }
    }
  }
  return best;
}
