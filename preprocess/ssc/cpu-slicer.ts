// The CPU reference slicer: the renderer's rule, one pixel centre at a time. Of all surface
// triangles over a pixel centre, the nearest one at or below the slicing surface gives the
// pixel its face (the triangle's upper face). The GPU renderer is tested against this.
import { orient } from '../geom/predicates.js';
import type { View } from '../map/rasterize.js';

export class CpuSlicer {
  readonly ids: Uint32Array;
  /** z of the surface each pixel shows (-Infinity: none). */
  readonly depth: Float64Array;
  /** The face below the shown surface (for blending). */
  readonly lower: Uint32Array;
  /** Class of the shown face. */
  readonly classes: Uint16Array;
  /** z of the slicing surface at each pixel centre. */
  readonly zs: Float64Array;
  /**
   * With `countFragments`: per pixel, the triangles over its centre at or below the slicing
   * surface, the fragments the GPU's ID pass keeps there (its overdraw, bench/triangles-in-view.ts).
   */
  readonly fragments: Uint32Array | null;
  private readonly px: number;
  private readonly py: number;

  constructor(readonly view: View, zAt: (x: number, y: number) => number, countFragments = false) {
    const { width: W, height: H, bbox } = view;
    this.fragments = countFragments ? new Uint32Array(W * H) : null;
    this.ids = new Uint32Array(W * H);
    this.lower = new Uint32Array(W * H);
    this.classes = new Uint16Array(W * H);
    this.depth = new Float64Array(W * H).fill(-Infinity);
    this.zs = new Float64Array(W * H);
    this.px = (bbox[2] - bbox[0]) / W;
    this.py = (bbox[3] - bbox[1]) / H;
    for (let j = 0; j < H; j++) {
      for (let i = 0; i < W; i++) this.zs[j * W + i] = zAt(this.cx(i), this.cy(j));
    }
  }

  /** Pixel centre x of column i, y of row j (rows from the top). */
  cx(i: number): number {
    return this.view.bbox[0] + (i + 0.5) * this.px;
  }

  cy(j: number): number {
    return this.view.bbox[3] - (j + 0.5) * this.py;
  }

  /** A counterclockwise triangle with per-vertex z. */
  triangle(
    ax: number, ay: number, az: number, bx: number, by: number, bz: number, cx: number, cy: number, cz: number,
    upper: number, lower: number, cls = 0,
  ): void {
    const { width: W, height: H, bbox } = this.view;
    const area = orient(ax, ay, bx, by, cx, cy);
    if (area <= 0) return; // degenerate, or seen from below
    const i0 = Math.max(0, Math.ceil((Math.min(ax, bx, cx) - bbox[0]) / this.px - 0.5));
    const i1 = Math.min(W - 1, Math.floor((Math.max(ax, bx, cx) - bbox[0]) / this.px - 0.5));
    const j0 = Math.max(0, Math.ceil((bbox[3] - Math.max(ay, by, cy)) / this.py - 0.5));
    const j1 = Math.min(H - 1, Math.floor((bbox[3] - Math.min(ay, by, cy)) / this.py - 0.5));
    if (i0 > i1 || j0 > j1) return;
    const flat = az === bz && bz === cz;
    const fragments = this.fragments;
    for (let j = j0; j <= j1; j++) {
      const y = this.cy(j);
      for (let i = i0; i <= i1; i++) {
        const x = this.cx(i);
        const w0 = orient(bx, by, cx, cy, x, y);
        if (w0 < 0 || (w0 === 0 && !owns(bx, by, cx, cy))) continue;
        const w1 = orient(cx, cy, ax, ay, x, y);
        if (w1 < 0 || (w1 === 0 && !owns(cx, cy, ax, ay))) continue;
        const w2 = orient(ax, ay, bx, by, x, y);
        if (w2 < 0 || (w2 === 0 && !owns(ax, ay, bx, by))) continue;
        const p = j * W + i;
        const z = flat ? az : (w0 * az + w1 * bz + w2 * cz) / area;
        if (!(z <= this.zs[p]!)) continue;
        if (fragments) fragments[p]!++;
        if (z > this.depth[p]!) {
          this.depth[p] = z;
          this.ids[p] = upper;
          this.lower[p] = lower;
          this.classes[p] = cls;
        }
      }
    }
  }
}

/**
 * Of the two triangles sharing an edge (in opposite directions), exactly one owns the points
 * on it: the one in which the edge runs up, or left when level.
 */
function owns(ax: number, ay: number, bx: number, by: number): boolean {
  return by > ay || (by === ay && bx < ax);
}

/** Draws every triangle of a decoded chunk into the slicer. */
export function sliceChunk(
  sl: CpuSlicer,
  c: { originX: number; originY: number; positions: Float32Array; upper: Uint32Array; lower: Uint32Array; upperClass: Uint16Array; indices: ArrayLike<number> },
): void {
  const p = c.positions, ox = c.originX, oy = c.originY;
  for (let t = 0; t < c.indices.length; t += 3) {
    const a = c.indices[t]!, b = c.indices[t + 1]!, d = c.indices[t + 2]!;
    sl.triangle(
      ox + p[3 * a]!, oy + p[3 * a + 1]!, p[3 * a + 2]!,
      ox + p[3 * b]!, oy + p[3 * b + 1]!, p[3 * b + 2]!,
      ox + p[3 * d]!, oy + p[3 * d + 1]!, p[3 * d + 2]!,
      c.upper[a]!, c.lower[a]!, c.upperClass[a],
    );
  }
}
