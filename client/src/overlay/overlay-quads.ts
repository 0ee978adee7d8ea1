// The overlay's mesh as the GPU takes it (overlay-mesh.ts makes it, render/gpu-overlay-mesh.ts
// uploads it): a file of its own, so that the map's script holds the layout without the code
// that builds meshes, which is loaded with the first GeoJSON layer (layer-geometry.ts).
import type { XY } from './geojson-read.js';

/** Floats per quad vertex: the segment's ends a and b (relative to the origin), the corner's direction e, and 0 at a's end, 1 at b's. */
export const QUAD_FLOATS = 7;
/** Each quad: 4 vertices, drawn as the triangles 0 1 2 and 2 1 3. */
export const QUAD_VERTICES = 4;

export interface OverlayMesh {
  /** Subtracted from every position (float64). */
  origin: XY;
  /** The box around every position (x0, y0, x1, y1; empty: x0 > x1). */
  bbox: [number, number, number, number];
  /** Polygon triangles: x, y per vertex (relative to the origin) and 3 indices per triangle. */
  fill: { positions: Float32Array; indices: Uint32Array };
  /** Quads of LineStrings' segments. */
  lines: Float32Array;
  /** Quads of polygon rings' segments (the fill's edge, and the polygons' outline). */
  rings: Float32Array;
  /** Quads of points (segments of length 0). */
  points: Float32Array;
}

/** Quads in a quad array. */
export function quadCount(quads: Float32Array): number {
  return quads.length / (QUAD_FLOATS * QUAD_VERTICES);
}
