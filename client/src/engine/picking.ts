// What is under a point of the map: the ID buffer's pixel there (upper and lower face, surface
// and slice z), with the face's class, attributes and steps from the worker's feature pages.
import type { CubeMeta } from '../../../format/cube-index.js';
import { scaleAtZ } from '../../../format/scale.js';
import type { Renderer } from '../render/renderer.js';
import type { ChunkSource } from '../source/chunk-source.js';

export interface Feature {
  face: number;
  /** The face below the slice at that point (0: none). */
  lowerFace: number;
  classIndex: number;
  classKey: string;
  classLabel: string;
  feature: number;
  properties: Record<string, unknown> | null;
  /** The states the face is alive in: stepLow <= s < stepHigh. */
  stepLow: number;
  stepHigh: number;
  /** Scale denominators at stepLow and stepHigh. */
  scaleRange: [number, number];
  /** z of the surface under the point and of the slice there. */
  z: number;
  sliceZ: number;
}

/** The faces at device pixel (x, y) of the image last drawn (none outside it). */
export async function featuresAt(renderer: Renderer, source: ChunkSource, meta: CubeMeta, x: number, y: number): Promise<Feature[]> {
  const px = renderer.readIds(x, y, 1, 1);
  const face = px?.upper[0] ?? 0;
  if (!px || face === 0) return [];
  const [info] = await source.features([face]);
  const classIndex = info ? info.classIndex : (px.classes[0] ?? 0) & 0xffff;
  const cls = meta.style.classes[classIndex];
  return [
    {
      face,
      lowerFace: px.lower[0] ?? 0,
      classIndex,
      classKey: cls?.key ?? String(classIndex),
      classLabel: cls?.label ?? String(classIndex),
      feature: info?.feature ?? -1,
      properties: info?.properties ?? null,
      stepLow: info?.stepLow ?? NaN,
      stepHigh: info?.stepHigh ?? NaN,
      scaleRange: info ? [scaleAtZ(meta, info.stepLow), scaleAtZ(meta, info.stepHigh)] : [NaN, NaN],
      z: px.z[0] ?? NaN,
      sliceZ: px.slice[0] ?? NaN,
    },
  ];
}
