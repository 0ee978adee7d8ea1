// The view as URL hash text in MapLibre GL JS's form, #zoom/lat/lng, so a link from either map
// shows the same place and scale in the other: the latitude and longitude to half a pixel at
// that zoom (MapLibre's precision rule), the zoom to four decimals where MapLibre writes two,
// since two change the scale by up to 0.35 % (1:25,000 back as 1:25,087 after a reload). A bearing and pitch after them
// (MapLibre writes those when not 0) are read and ignored: this map neither rotates nor tilts. Pure.

export interface HashView {
  zoom: number;
  center: [number, number];
}

export function formatHash(zoom: number, center: [number, number]): string {
  const z = Math.round(zoom * 1e4) / 1e4;
  // 512 px * 2^z / 360 degrees / 10^d < 0.5 px
  const precision = Math.max(0, Math.ceil((z * Math.LN2 + Math.log(512 / 360 / 0.5)) / Math.LN10));
  const m = Math.pow(10, precision);
  const lat = Math.round(center[1] * m) / m, lng = Math.round(center[0] * m) / m;
  return `#${z}/${lat}/${lng}`;
}

export function parseHash(hash: string): HashView | null {
  const parts = hash.replace(/^#/, '').split('/');
  if (parts.length < 3 || parts.length > 5 || parts.some((p) => !/^-?\d+(\.\d*)?$/.test(p))) return null;
  const [zoom, lat, lng] = parts.map(Number) as [number, number, number];
  if (Math.abs(lat) > 90) return null;
  return { zoom, center: [lng, lat] };
}
