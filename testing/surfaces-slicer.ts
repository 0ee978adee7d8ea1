// Hand-made or built surfaces sliced as the map would see them: every triangle in one real chunk
// (assembled, encoded and decoded), then the CPU reference slicer at a constant z.
import { decodeChunk } from '../format/chunk.js';
import type { View } from '../preprocess/map/rasterize.js';
import { assembleChunk } from '../preprocess/ssc/assemble-chunk.js';
import { CpuSlicer, sliceChunk } from '../preprocess/ssc/cpu-slicer.js';
import type { Surfaces } from '../preprocess/ssc/surfaces.js';

export async function surfacesSlicer(s: Surfaces, xs: Float64Array, ys: Float64Array, classOf: (face: number) => number, view: View): Promise<(z: number) => CpuSlicer> {
  const all = Uint32Array.from({ length: s.count }, (_, i) => i);
  const chunk = await decodeChunk(assembleChunk(s, all, xs, ys, classOf).bytes);
  return (z) => {
    const sl = new CpuSlicer(view, () => z);
    sliceChunk(sl, chunk);
    return sl;
  };
}
