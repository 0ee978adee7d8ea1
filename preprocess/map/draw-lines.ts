// Lines over the face colours, the CPU reference for the map's line pass: a pixel shows a line
// when its centre lies within half the line's width of a segment (round caps and joins, so no
// gaps at vertices) and the slicing surface's z at that pixel lies in the segment's z range
// (lineSegments). No anti-aliasing: the oracle says which pixels a line covers.
import { lineSegments, type LineRecord } from '../../format/line-chunk.js';
import { pointSegmentDistance } from '../geom/point-segment.js';
import type { View } from './rasterize.js';

/** Line width on screen when the style gives none. */
export const DEFAULT_LINE_WIDTH_PX = 2;

/**
 * Per pixel (rows from the top), 1 + the class of the line drawn there, 0 where none. Lines
 * are drawn in the order given, a later one over an earlier one. `zAt` is the slicing
 * surface's z at pixel p.
 */
export function drawLines(view: View, lines: readonly LineRecord[], zAt: (p: number) => number, widthPx = DEFAULT_LINE_WIDTH_PX): Uint16Array {
  const { width: W, height: H, bbox } = view;
  const px = (bbox[2] - bbox[0]) / W, py = (bbox[3] - bbox[1]) / H;
  const half = (widthPx / 2) * px;
  const out = new Uint16Array(W * H);
  for (const l of lines) {
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
          if (s.z0 <= z && z < s.z1) out[p] = l.classIndex + 1;
        }
      }
    }
  }
  return out;
}
