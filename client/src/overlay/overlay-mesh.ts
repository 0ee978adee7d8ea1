// The overlay's geometry as the GPU draws it, made once per setData on the CPU in the cube's
// projected CRS (float64), stored relative to an origin in the middle of the data so that
// float32 keeps it to well under a millimetre per kilometre from there. Polygons are
// triangulated (earcut). Lines, polygon rings and points become quads: one per segment, around
// the segment and reaching past both ends, whose corners the vertex shader places at
// `reach` device pixels (half the line width plus a pixel for anti-aliasing) from it. The
// fragment shader keeps what lies within the half width of the segment: every segment a
// capsule, so consecutive segments join round without a gap, and a point is a segment of
// length 0 (a disc). The view (pan, zoom) is applied on the GPU, so nothing here changes with it.
import earcut from 'earcut';
import type { Parts, XY } from './geojson-read.js';
import { QUAD_FLOATS, QUAD_VERTICES, type OverlayMesh } from './overlay-quads.js';

/** The mesh of the features' parts (in the cube's CRS). */
export function buildMesh(features: readonly Parts[]): OverlayMesh {
  const bbox = boxAround(features);
  const origin: XY = bbox[0] <= bbox[2] ? [(bbox[0] + bbox[2]) / 2, (bbox[1] + bbox[3]) / 2] : [0, 0];
  const lines = new QuadArray(), rings = new QuadArray(), points = new QuadArray();
  const positions: number[] = [], indices: number[] = [];
  for (const f of features) {
    for (const p of f.points) points.push(p, p, origin);
    for (const l of f.lines) pushPolyline(lines, l, false, origin);
    for (const poly of f.polygons) {
      for (const r of poly) pushPolyline(rings, r, true, origin);
      triangulate(poly, origin, positions, indices);
    }
  }
  return { origin, bbox, fill: { positions: new Float32Array(positions), indices: new Uint32Array(indices) }, lines: lines.finish(), rings: rings.finish(), points: points.finish() };
}

/** The quads of a polyline's segments (closed: and from the last position back to the first); repeated positions give none. */
function pushPolyline(out: QuadArray, pts: readonly XY[], closed: boolean, origin: XY): void {
  const n = pts.length;
  const before = out.count;
  for (let i = 0; i < (closed ? n : n - 1); i++) {
    const a = pts[i]!, b = pts[(i + 1) % n]!;
    if (a[0] !== b[0] || a[1] !== b[1]) out.push(a, b, origin);
  }
  // A line whose positions are all one place is drawn as a dot, as the line's round caps would give.
  if (out.count === before && n > 0) out.push(pts[0]!, pts[0]!, origin);
}

/** Quads written straight into a float32 array that grows (a data set's quads run to millions of floats). */
class QuadArray {
  count = 0;
  private data = new Float32Array(QUAD_FLOATS * QUAD_VERTICES * 64);

  push(a: XY, b: XY, origin: XY): void {
    const size = QUAD_FLOATS * QUAD_VERTICES;
    if ((this.count + 1) * size > this.data.length) {
      const bigger = new Float32Array(this.data.length * 2);
      bigger.set(this.data);
      this.data = bigger;
    }
    const dx = b[0] - a[0], dy = b[1] - a[1];
    const len = Math.hypot(dx, dy);
    // Along the segment (any direction for a point) and across it.
    const tx = len > 0 ? dx / len : 1, ty = len > 0 ? dy / len : 0;
    const nx = -ty, ny = tx;
    const ax = a[0] - origin[0], ay = a[1] - origin[1], bx = b[0] - origin[0], by = b[1] - origin[1];
    let o = this.count * size;
    for (const [along, side] of CORNERS) {
      const d = this.data;
      d[o] = ax;
      d[o + 1] = ay;
      d[o + 2] = bx;
      d[o + 3] = by;
      d[o + 4] = along * tx + side * nx;
      d[o + 5] = along * ty + side * ny;
      d[o + 6] = along < 0 ? 0 : 1;
      o += QUAD_FLOATS;
    }
    this.count++;
  }

  finish(): Float32Array {
    return this.data.slice(0, this.count * QUAD_FLOATS * QUAD_VERTICES);
  }
}

/** A quad's corners: back or ahead along the segment, right or left of it. */
const CORNERS = [[-1, -1], [-1, 1], [1, -1], [1, 1]] as const;

/** Appends a polygon's triangles (rings: outer first, then holes). */
function triangulate(rings: readonly XY[][], origin: XY, positions: number[], indices: number[]): void {
  const coords: number[] = [], holes: number[] = [];
  for (const [i, r] of rings.entries()) {
    if (i > 0) holes.push(coords.length / 2);
    for (const p of r) coords.push(p[0] - origin[0], p[1] - origin[1]);
  }
  const first = positions.length / 2;
  for (const t of earcut(coords, holes)) indices.push(first + t);
  for (const c of coords) positions.push(c);
}

function boxAround(features: readonly Parts[]): [number, number, number, number] {
  let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  const add = (p: XY): void => {
    x0 = Math.min(x0, p[0]);
    y0 = Math.min(y0, p[1]);
    x1 = Math.max(x1, p[0]);
    y1 = Math.max(y1, p[1]);
  };
  for (const f of features) {
    f.points.forEach(add);
    for (const l of f.lines) l.forEach(add);
    for (const poly of f.polygons) for (const r of poly) r.forEach(add);
  }
  return [x0, y0, x1, y1];
}
