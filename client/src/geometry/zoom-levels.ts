// Zoom levels as web maps count them, for callers who think in zoom rather than scale: level z
// shows scale denominator 559082264.0287178 / 2^z (the OGC well-known scale set of web maps,
// 0.28 mm pixels). Only a familiar name for a scale; the map itself has no levels.

export const ZOOM_0_SCALE = 559082264.0287178;

export function scaleAtZoom(zoom: number): number {
  return ZOOM_0_SCALE / Math.pow(2, zoom);
}

export function zoomAtScale(scale: number): number {
  return Math.log2(ZOOM_0_SCALE / scale);
}
