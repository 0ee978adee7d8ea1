// What is under a point of the map: the ID buffer's pixel there (upper and lower face, surface
// and slice z), with the face's class (named by the style drawn), attributes and steps from the
// worker's feature pages, and on request the face's outline on screen, traced in the ID buffer.
import type { CubeMeta } from '../../../format/cube-index.js';
import { scaleAtZ } from '../../../format/scale.js';
import type { CubeStyle } from '../../../format/style.js';
import { pixelOutline } from '../geometry/pixel-outline.js';
import { pixelToGround, type ViewGeometry } from '../geometry/view.js';
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
  /** Scale denominators at stepLow and stepHigh: the face is shown between them. */
  scaleRange: [number, number];
  /** The face that takes its area at stepHigh (-1: it lasts to the top, or is split among its neighbours). */
  mergedInto: number;
  /** z of the surface under the point and of the slice there. */
  z: number;
  sliceZ: number;
  /**
   * With `{ outline: true }`: the face's outline as the map shows it now, in ground coordinates:
   * closed rings along the device pixels' edges, clipped to the view; outer rings
   * counter-clockwise, holes clockwise (GeoJSON's rule).
   */
  outline?: [number, number][][];
}

export interface QueryOptions {
  /** Also trace the face's outline on screen (reads the whole ID buffer back: a few ms). */
  outline?: boolean;
}

export interface PickContext {
  renderer: Renderer;
  source: ChunkSource;
  meta: CubeMeta;
  style: CubeStyle;
  /** The view drawn, in device pixels. */
  view: ViewGeometry;
}

/** The faces at device pixel (x, y) of the image last drawn (none outside it). */
export async function featuresAt(ctx: PickContext, x: number, y: number, options: QueryOptions = {}): Promise<Feature[]> {
  const { renderer, source, meta, style } = ctx;
  const px = renderer.readIds(x, y, 1, 1);
  const face = px?.upper[0] ?? 0;
  if (!px || face === 0) return [];
  // Traced before the worker answers: the picture may change meanwhile.
  const outline = options.outline ? faceOutline(ctx, face) : undefined;
  const [info] = await source.features([face]);
  const classIndex = info ? info.classIndex : (px.classes[0] ?? 0) & 0xffff;
  const cls = style.classes[classIndex];
  const out: Feature = {
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
    mergedInto: info?.mergedInto ?? -1,
    z: px.z[0] ?? NaN,
    sliceZ: px.slice[0] ?? NaN,
  };
  if (outline) out.outline = outline;
  return [out];
}

function faceOutline(ctx: PickContext, face: number): [number, number][][] {
  const ids = ctx.renderer.readUpperFaces();
  if (!ids) return [];
  return pixelOutline(ids.upper, ids.width, ids.height, face).map((ring) => ring.map(([i, j]) => pixelToGround(ctx.view, i, j)));
}
