// Slices of one cube at a run of z over one ground window, as a zoom shows them: the CPU
// reference slicer through the index and the chunks (preprocess/commands/slice-cube.ts), each
// chunk read and decoded once for the whole run, as the map's cache would keep it.
import type { DecodedChunk } from '../format/chunk.js';
import type { ChunkLeaf } from '../format/cube-index.js';
import { sliceCube, type ChunkSource } from '../preprocess/commands/slice-cube.js';
import type { View } from '../preprocess/map/rasterize.js';
import type { CpuSlicer } from '../preprocess/ssc/cpu-slicer.js';
import { CubeReader } from '../preprocess/ssc/read-cube.js';

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
