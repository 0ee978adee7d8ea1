// The standard screen pixel (OGC WMS 1.3 / WMTS): a scale denominator and a ground size per
// pixel are the same thing through it. Written into index.json as meta.pixelSizeMm.
export const PIXEL_SIZE_MM = 0.28;

/** Ground width and height (metres) a `width` x `height` px view covers per unit of scale denominator. */
export const groundPerScale = (width: number, height: number): [number, number] => [(width * PIXEL_SIZE_MM) / 1000, (height * PIXEL_SIZE_MM) / 1000];
