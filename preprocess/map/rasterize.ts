// The 2D map of a tGAP state, drawn straight from its edges: a scanline at each pixel row's
// centre meets the boundary segments; between two crossings lies the face east of the first.
// Every pixel gets exactly one face (or none, outside the domain), and a crossing whose west
// face is not the face we are in is counted: a partition never has one.
import { resolveFace, type Tgap } from '../../format/tgap-model.js';

export interface View {
  width: number;
  height: number;
  /** Ground box [x0, y0, x1, y1] the image covers exactly. */
  bbox: [number, number, number, number];
}

export interface Raster {
  /** Face id per pixel, row by row from the top (0 = outside the domain). */
  ids: Uint32Array;
  /** Crossings where the face on the west side disagreed with the face we came from. */
  inconsistencies: number;
}

/** The box of `size` pixels around `bbox` (default: the extent) with square pixels, centred. */
export function fitView(extent: [number, number, number, number], width: number, height: number, bbox?: [number, number, number, number]): View {
  const [x0, y0, x1, y1] = bbox ?? extent;
  const w = x1 - x0, h = y1 - y0;
  const res = Math.max(w / width, h / height);
  const cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
  return { width, height, bbox: [cx - (res * width) / 2, cy - (res * height) / 2, cx + (res * width) / 2, cy + (res * height) / 2] };
}

interface Seg {
  xa: number;
  ya: number;
  xb: number;
  yb: number;
  east: number;
  west: number;
  end: number; // last row it crosses
}

/** Segments of the boundary at state `step` as (a, b, left face, right face) callbacks. */
export function forEachSegmentAt(
  tgap: Tgap, step: number,
  fn: (ax: number, ay: number, bx: number, by: number, left: number, right: number) => void,
): void {
  const cache = new Map<number, number>();
  const res = (f: number): number => {
    let r = cache.get(f);
    if (r === undefined) {
      r = resolveFace(tgap.faces, f, step);
      cache.set(f, r);
    }
    return r;
  };
  const { xs, ys } = tgap;
  for (const e of tgap.edges) {
    if (e.stepLow > step || e.stepHigh <= step) continue;
    const l = res(e.left), r = res(e.right);
    const v = e.verts;
    for (let i = 0; i + 1 < v.length; i++) fn(xs[v[i]!]!, ys[v[i]!]!, xs[v[i + 1]!]!, ys[v[i + 1]!]!, l, r);
  }
}

export function rasterizeAt(tgap: Tgap, step: number, view: View): Raster {
  const { width: W, height: H } = view;
  const [x0, , x1, y1] = view.bbox;
  const px = (x1 - x0) / W, py = (view.bbox[3] - view.bbox[1]) / H;
  const rowY = (j: number): number => y1 - (j + 0.5) * py;
  const buckets: Seg[][] = Array.from({ length: H }, () => []);
  forEachSegmentAt(tgap, step, (ax, ay, bx, by, left, right) => {
    if (ay === by) return;
    // Rows whose centre line y satisfies min <= y < max (half-open, so a vertex on a row is counted once).
    const lo = Math.min(ay, by), hi = Math.max(ay, by);
    // Row j's centre is y1 - (j + 0.5) py: rows from the one at hi (exclusive) down to lo (inclusive).
    let jFirst = Math.floor((y1 - hi) / py - 0.5) + 1;
    let jLast = Math.floor((y1 - lo) / py - 0.5);
    // The exact test decides, so that every segment through a vertex agrees on its rows.
    if (rowY(jFirst - 1) < hi) jFirst--;
    while (!(rowY(jFirst) < hi)) jFirst++;
    if (rowY(jLast + 1) >= lo) jLast++;
    while (jLast >= jFirst && !(rowY(jLast) >= lo)) jLast--;
    if (jFirst > jLast || jLast < 0 || jFirst >= H) return;
    // Going up (north), the right face lies east.
    const up = by > ay;
    buckets[Math.max(0, jFirst)]!.push({ xa: ax, ya: ay, xb: bx, yb: by, east: up ? right : left, west: up ? left : right, end: Math.min(H - 1, jLast) });
  });
  const ids = new Uint32Array(W * H);
  let inconsistencies = 0;
  let active: Seg[] = [];
  const xsCross: number[] = [];
  const order: number[] = [];
  for (let j = 0; j < H; j++) {
    active = active.filter((s) => s.end >= j);
    for (const s of buckets[j]!) active.push(s);
    const yc = rowY(j);
    xsCross.length = 0;
    order.length = 0;
    for (let k = 0; k < active.length; k++) {
      const s = active[k]!;
      xsCross.push(s.xa + ((yc - s.ya) * (s.xb - s.xa)) / (s.yb - s.ya));
      order.push(k);
    }
    // West to east; at a shared vertex, by the direction the segments leave it northwards.
    const slope = (s: Seg): number => (s.xb - s.xa) / (s.yb - s.ya);
    order.sort((a, b) => xsCross[a]! - xsCross[b]! || slope(active[a]!) - slope(active[b]!));
    let face = 0;
    let i = 0;
    const row = j * W;
    for (const k of order) {
      const s = active[k]!;
      if (s.west !== face) inconsistencies++;
      const iEast = Math.min(W, Math.max(0, Math.ceil((xsCross[k]! - x0) / px - 0.5)));
      if (face !== 0) ids.fill(face, row + i, row + Math.max(i, iEast));
      i = Math.max(i, iEast);
      face = s.east;
    }
    if (face !== 0) {
      ids.fill(face, row + i, row + W);
      inconsistencies++; // the domain must be closed: east of the last crossing is outside
    }
  }
  return { ids, inconsistencies };
}
