// The ground area under the screen: a centre (float64 national grid coordinates), the ground
// size of a device pixel and the size in device pixels. Pure, so the tests compute the same
// boxes and pixel positions the map uses.

export interface ViewGeometry {
  centerX: number;
  centerY: number;
  /** Ground units per device pixel. */
  resolution: number;
  /** Device pixels. */
  width: number;
  height: number;
}

export type Bbox = [number, number, number, number];

export function viewBbox(v: ViewGeometry): Bbox {
  const hw = (v.resolution * v.width) / 2, hh = (v.resolution * v.height) / 2;
  return [v.centerX - hw, v.centerY - hh, v.centerX + hw, v.centerY + hh];
}

/** The box grown by `factor` of its size on every side. */
export function growBbox(b: Bbox, factor: number): Bbox {
  const mx = (b[2] - b[0]) * factor, my = (b[3] - b[1]) * factor;
  return [b[0] - mx, b[1] - my, b[2] + mx, b[3] + my];
}

/** Ground point at device pixel position (px, py), measured from the top left corner. */
export function pixelToGround(v: ViewGeometry, px: number, py: number): [number, number] {
  return [v.centerX + (px - v.width / 2) * v.resolution, v.centerY - (py - v.height / 2) * v.resolution];
}

export function groundToPixel(v: ViewGeometry, x: number, y: number): [number, number] {
  return [(x - v.centerX) / v.resolution + v.width / 2, v.height / 2 - (y - v.centerY) / v.resolution];
}

/** The view of `width` x `height` pixels that shows `bbox` whole, centred, with square pixels. */
export function fitBbox(bbox: Bbox, width: number, height: number): ViewGeometry {
  const res = Math.max((bbox[2] - bbox[0]) / width, (bbox[3] - bbox[1]) / height);
  return { centerX: (bbox[0] + bbox[2]) / 2, centerY: (bbox[1] + bbox[3]) / 2, resolution: res, width, height };
}

/** Ground units per CSS pixel at a scale denominator (a CSS pixel is `pixelSizeMm` on paper). */
export function resolutionAtScale(scaleDenominator: number, pixelSizeMm: number): number {
  return (scaleDenominator * pixelSizeMm) / 1000;
}

export function scaleAtResolution(cssResolution: number, pixelSizeMm: number): number {
  return (cssResolution * 1000) / pixelSizeMm;
}
