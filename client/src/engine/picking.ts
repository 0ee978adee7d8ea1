// What is under a point of the map, topmost first: the cube's line drawn there, if any (its class
// and its feature's attributes), then the ID buffer's pixel there (upper and lower face, surface
// and slice z), with the face's class (named by the style drawn), attributes and steps from the
// worker's feature pages, and on request the face's outline on screen, traced in the ID buffer.
import type { CubeMeta } from '../../../format/cube-index.js';
import { scaleAtZ } from '../../../format/scale.js';
import type { CubeStyle } from '../../../format/style.js';
import { pixelOutline } from '../geometry/pixel-outline.js';
import { pixelToGround, type ViewGeometry } from '../geometry/view.js';
import type { Renderer } from '../render/renderer.js';
import type { ChunkSource } from '../source/chunk-source.js';

/** A face of the map under the point. */
export interface FaceFeature {
  kind: 'face';
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

/** A line of the cube (a road or watercourse drawn as a line) under the point. */
export interface LineFeature {
  kind: 'line';
  classIndex: number;
  classKey: string;
  classLabel: string;
  /** The input feature whose centreline the line is (-1: none), and its attributes. */
  feature: number;
  properties: Record<string, unknown> | null;
  /** Scale denominators between which the line is on the map. */
  scaleRange: [number, number];
  /** z of the slice at the point. */
  sliceZ: number;
}

export type Feature = FaceFeature | LineFeature;

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

/** The line and the face at device pixel (x, y) of the image last drawn, topmost first (none outside it). */
export async function featuresAt(ctx: PickContext, x: number, y: number, options: QueryOptions = {}): Promise<Feature[]> {
  const { renderer, source, meta, style } = ctx;
  const px = renderer.readIds(x, y, 1, 1);
  if (!px) return [];
  const out: Feature[] = [];
  const hit = renderer.lineAt(x, y, px.slice[0] ?? NaN);
  if (hit) {
    const { chunk, line } = hit;
    const classIndex = chunk.lineClass[line]!, feature = chunk.lineFeature[line]!;
    const cls = style.classes[classIndex];
    const [properties] = feature >= 0 ? await source.attributes([feature]) : [null];
    const { z0, z1 } = chunk.lineRamp(line);
    out.push({
      kind: 'line',
      classIndex,
      classKey: cls?.key ?? String(classIndex),
      classLabel: cls?.label ?? String(classIndex),
      feature,
      properties: properties ?? null,
      scaleRange: [scaleAtZ(meta, z0), scaleAtZ(meta, z1)],
      sliceZ: px.slice[0] ?? NaN,
    });
  }
  const face = px.upper[0] ?? 0;
  if (face === 0) return out;
  // Traced before the worker answers: the picture may change meanwhile.
  const outline = options.outline ? faceOutline(ctx, face) : undefined;
  const [info] = await source.features([face]);
  const classIndex = info ? info.classIndex : (px.classes[0] ?? 0) & 0xffff;
  const cls = style.classes[classIndex];
  const f: FaceFeature = {
    kind: 'face',
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
  if (outline) f.outline = outline;
  out.push(f);
  return out;
}

function faceOutline(ctx: PickContext, face: number): [number, number][][] {
  const ids = ctx.renderer.readUpperFaces();
  if (!ids) return [];
  return pixelOutline(ids.upper, ids.width, ids.height, face).map((ring) => ring.map(([i, j]) => pixelToGround(ctx.view, i, j)));
}
