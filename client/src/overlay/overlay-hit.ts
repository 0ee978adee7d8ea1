// Which of an overlay layer's features are under a point, on the CPU and in the cube's CRS:
// inside a polygon (even-odd over its rings, so holes are not inside), within half the line
// width (plus a tolerance) of a line or of a polygon's outline, within the circle's radius
// (plus the same tolerance) of a point. Sizes are CSS px, turned into ground units at the
// resolution of the moment. A Flatbush index over the parts' boxes finds the candidates. Pure.
import Flatbush from 'flatbush';
import { boxAround } from '../geometry/box-around.js';
import type { Parts, XY } from './geojson-read.js';
import { pointSegmentDistance } from '../../../format/point-segment.js';

export interface HitReach {
  /** Ground units per CSS pixel. */
  resolution: number;
  /** CSS px: half the line width (lines and polygon outlines), the circle's radius with its stroke; 0: not drawn, not hit. */
  lineHalfWidth: number;
  circleRadius: number;
  /** CSS px added to both: thin lines and small circles are hard to hit exactly. */
  tolerance: number;
  /** Polygons' rings are drawn as lines (line width > 0). */
  outlines: boolean;
}

/** Kinds of part in the order drawn from the top: circles over lines over fills. */
const POINT = 0, LINE = 1, POLYGON = 2;

interface Item {
  feature: number;
  kind: number;
  /** The point, the line's positions, or the polygon's rings. */
  geometry: XY | XY[] | XY[][];
}

export class HitIndex {
  private readonly items: Item[] = [];
  private readonly index: Flatbush | null;

  constructor(features: readonly Parts[]) {
    features.forEach((f, i) => {
      for (const p of f.points) this.items.push({ feature: i, kind: POINT, geometry: p });
      for (const l of f.lines) this.items.push({ feature: i, kind: LINE, geometry: l });
      for (const poly of f.polygons) this.items.push({ feature: i, kind: POLYGON, geometry: poly });
    });
    if (this.items.length === 0) {
      this.index = null;
      return;
    }
    const index = new Flatbush(this.items.length);
    for (const it of this.items) {
      const b = box(it);
      index.add(b[0], b[1], b[2], b[3]);
    }
    index.finish();
    this.index = index;
  }

  /** Indices of the features under `p`, topmost first (circles, lines, fills; later features over earlier). */
  at(p: XY, r: HitReach): number[] {
    if (!this.index) return [];
    const lineReach = (r.lineHalfWidth + r.tolerance) * r.resolution;
    const pointReach = (r.circleRadius + r.tolerance) * r.resolution;
    const reach = Math.max(lineReach, pointReach);
    const hits = this.index
      .search(p[0] - reach, p[1] - reach, p[0] + reach, p[1] + reach)
      .map((i) => this.items[i]!)
      .filter((it) => {
        // What is not drawn (a size of 0) is not hit.
        if (it.kind === POINT) return r.circleRadius > 0 && Math.hypot(p[0] - (it.geometry as XY)[0], p[1] - (it.geometry as XY)[1]) <= pointReach;
        if (it.kind === LINE) return r.lineHalfWidth > 0 && distanceToPolyline(p, it.geometry as XY[], false) <= lineReach;
        const rings = it.geometry as XY[][];
        return insideRings(p, rings) || (r.outlines && rings.some((ring) => distanceToPolyline(p, ring, true) <= lineReach));
      })
      .sort((a, b) => a.kind - b.kind || b.feature - a.feature);
    return [...new Set(hits.map((it) => it.feature))];
  }
}

function box(it: Item): [number, number, number, number] {
  return boxAround(it.kind === POINT ? [it.geometry as XY] : it.kind === LINE ? (it.geometry as XY[]) : (it.geometry as XY[][]).flat());
}

/** Distance from p to the segment a-b. */
export function distanceToSegment(p: XY, a: XY, b: XY): number {
  return pointSegmentDistance(p[0], p[1], a[0], a[1], b[0], b[1]);
}

/** Distance from p to a polyline (closed: a ring, with the segment from its last position to its first). */
export function distanceToPolyline(p: XY, pts: readonly XY[], closed: boolean): number {
  const n = pts.length;
  if (n === 1) return Math.hypot(p[0] - pts[0]![0], p[1] - pts[0]![1]);
  let d = Infinity;
  for (let i = 0; i < (closed ? n : n - 1); i++) d = Math.min(d, distanceToSegment(p, pts[i]!, pts[(i + 1) % n]!));
  return d;
}

/** Whether p is inside the rings by the even-odd rule: inside the outer ring and outside its holes. */
export function insideRings(p: XY, rings: readonly XY[][]): boolean {
  let inside = false;
  for (const r of rings) {
    for (let i = 0, j = r.length - 1; i < r.length; j = i++) {
      const [xi, yi] = r[i]!, [xj, yj] = r[j]!;
      if (yi > p[1] !== yj > p[1] && p[0] < ((xj - xi) * (p[1] - yi)) / (yj - yi) + xi) inside = !inside;
    }
  }
  return inside;
}
