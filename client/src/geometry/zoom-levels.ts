// Zoom levels as MapLibre GL JS counts them, so that a zoom (or a URL hash) from another web map
// means the same scale here: 512-px tiles of web mercator, whose ground metres per CSS pixel at
// latitude φ are 40075016.686 * cos φ / (512 * 2^zoom). The map's scale denominator is ground
// units of the cube's CRS per CSS pixel (a pixel being `pixelSizeMm` on paper), so the zoom of a
// scale depends on the latitude. Pure.

/** The equator's length, metres (MapLibre's earthCircumference). */
export const EARTH_CIRCUMFERENCE_M = 40075016.686;
const TILE_SIZE_PX = 512;

/** MapLibre's ground metres per CSS pixel at `zoom` and `latitude` (degrees). */
export function metresPerPixelAtZoom(zoom: number, latitude: number): number {
  return (EARTH_CIRCUMFERENCE_M * Math.cos((latitude * Math.PI) / 180)) / (TILE_SIZE_PX * Math.pow(2, zoom));
}

export function scaleAtZoom(zoom: number, latitude: number, pixelSizeMm: number): number {
  return (metresPerPixelAtZoom(zoom, latitude) * 1000) / pixelSizeMm;
}

export function zoomAtScale(scale: number, latitude: number, pixelSizeMm: number): number {
  const metresPerPixel = (scale * pixelSizeMm) / 1000;
  return Math.log2((EARTH_CIRCUMFERENCE_M * Math.cos((latitude * Math.PI) / 180)) / (TILE_SIZE_PX * metresPerPixel));
}
