// Slices of one cube at a run of z over one ground window, as a zoom shows them: the CPU
// reference slicer through the index and the chunks (preprocess/commands/slice-cube.ts), each
// chunk read and decoded once for the whole run, as the map's cache would keep it.
import type { DecodedChunk } from '../format/chunk.js';
import type { ChunkLeaf } from '../format/cube-index.js';
import { zAtScale, type ScaleInfo } from '../format/scale.js';
import { sliceCube, type ChunkSource } from '../preprocess/commands/slice-cube.js';
import type { View } from '../preprocess/map/rasterize.js';
import type { CpuSlicer } from '../preprocess/ssc/cpu-slicer.js';
import { CubeReader } from '../preprocess/ssc/read-cube.js';

/** Frames of bench:smoothness's zoom. */
export const ZOOM_FRAMES = 120;

/**
 * The z of each of `frames` frames of a geometric zoom on `view` from the base scale to the
 * scale at which the (fitted) extent fills the window: its metres per pixel over the pixel size.
 */
export function zoomZs(info: ScaleInfo, pixelSizeMm: number, view: View, frames = ZOOM_FRAMES): number[] {
  const extentScale = ((view.bbox[2] - view.bbox[0]) / view.width) * (1000 / pixelSizeMm);
  return Array.from({ length: frames }, (_, i) => zAtScale(info, info.baseScale * (extentScale / info.baseScale) ** (i / (frames - 1))));
}

/** The reader's chunks, each read once. */
export function cachedChunks(reader: CubeReader): ChunkSource {
  const decoded = new Map<string, DecodedChunk>();
  return {
    query: (q) => reader.query(q),
    async chunk(leaf: ChunkLeaf) {
      let c = decoded.get(leaf.file);
      if (!c) decoded.set(leaf.file, (c = await reader.chunk(leaf)));
      return c;
    },
  };
}

/** The slice at each z in turn, flat, with the time it took (ms). */
export async function* zoomFrames(reader: CubeReader, view: View, zs: readonly number[]): AsyncGenerator<{ z: number; slicer: CpuSlicer; ms: number }> {
  const source = cachedChunks(reader);
  for (const z of zs) {
    const t0 = performance.now();
    const { slicer } = await sliceCube(source, reader.index.meta.zMax, view, { base: z, spec: { kind: 'flat' } });
    yield { z, slicer, ms: performance.now() - t0 };
  }
}
