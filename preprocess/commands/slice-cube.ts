// One slice of a cube on the CPU reference slicer, read the way the map reads it: the chunks the
// index gives for the view's ground box and the surface's z range, every triangle of each.
// `ssc slice` and bench:smoothness (120 slices of one cube) both slice through here.
import type { DecodedChunk } from '../../format/chunk.js';
import type { ChunkLeaf } from '../../format/cube-index.js';
import type { QueryBox } from '../../format/index-query.js';
import { surfaceRange, surfaceZ, type Surface } from '../../format/slicing-surface.js';
import type { View } from '../map/rasterize.js';
import { CpuSlicer, sliceChunk } from '../ssc/cpu-slicer.js';

/** Where the chunks come from: a CubeReader, or a cache in front of one. */
export interface ChunkSource {
  query(q: QueryBox): Promise<ChunkLeaf[]>;
  chunk(leaf: ChunkLeaf): Promise<DecodedChunk>;
}

export interface CubeSlice {
  slicer: CpuSlicer;
  /** The z range the surface spans over the view (what the index was asked for). */
  zMin: number;
  zMax: number;
  chunks: number;
  triangles: number;
}

/** Slices the cube (top `zTop`) along `surface` over `view`. */
export async function sliceCube(cube: ChunkSource, zTop: number, view: View, surface: Surface): Promise<CubeSlice> {
  const [zMin, zMax] = surfaceRange(surface, view.bbox, zTop);
  const leaves = await cube.query({ ground: view.bbox, zMin, zMax });
  const slicer = new CpuSlicer(view, (x, y) => surfaceZ(surface, x, y, zTop));
  let triangles = 0;
  for (const leaf of leaves) {
    const c = await cube.chunk(leaf);
    sliceChunk(slicer, c);
    triangles += c.triangleCount;
  }
  return { slicer, zMin, zMax, chunks: leaves.length, triangles };
}
