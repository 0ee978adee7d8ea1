import assert from 'node:assert/strict';
import { test } from 'node:test';
import { toMapLibreView } from './scale-zoom.js';

// Spherical web mercator as a projected CRS: its units are mercator metres, so at any
// latitude a view of s CRS units per pixel is MapLibre's zoom whose metres per pixel at the
// equator are s: 40075016.686 / (512 * 2^z) = s * 0.28 / 1000.
const WEB_MERCATOR = '+proj=merc +a=6378137 +b=6378137 +lat_ts=0 +lon_0=0 +x_0=0 +y_0=0 +k=1 +units=m +no_defs';
const UTM_12N = '+proj=utm +zone=12 +datum=WGS84 +units=m +no_defs';

test('a web mercator view keeps its zoom at every latitude, and sits where it was', () => {
  const view = toMapLibreView(WEB_MERCATOR, 1280, 0.28);
  const expected = Math.log2(40075016.686 / (512 * ((1000 * 0.28) / 1000)));
  for (const y of [0, 4e6, 8e6]) {
    const v = view({ center: [1e5, y], scale: 1000 });
    assert.ok(Math.abs(v.zoom - expected) < 1e-6, `zoom ${v.zoom} at y ${y}, expected ${expected}`);
    assert.ok(Math.abs(v.center[0] - (1e5 / 6378137) * (180 / Math.PI)) < 1e-9);
  }
});

test('on the central meridian of a UTM zone, a CRS unit is 1 / 0.9996 metres on the ground', () => {
  // At latitude 37 (x 500000, the central meridian 111 W): ground metres per pixel are
  // 0.28 / 0.9996 at 1:1000, and mercator stretches them by 1 / cos(latitude).
  const v = toMapLibreView(UTM_12N, 1280, 0.28)({ center: [500000, 4095000], scale: 1000 });
  assert.ok(Math.abs(v.center[0] + 111) < 1e-9);
  const metresPerPixel = 0.28 / 0.9996;
  const expected = Math.log2((40075016.686 * Math.cos((v.center[1] * Math.PI) / 180)) / (512 * metresPerPixel));
  // The sphere of web mercator against the ellipsoid of UTM: within 0.3 % of a zoom level.
  assert.ok(Math.abs(v.zoom - expected) < 3e-3, `zoom ${v.zoom}, expected ${expected}`);
});
