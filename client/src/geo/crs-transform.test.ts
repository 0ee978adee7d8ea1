// The conversion between longitude/latitude and a cube's CRS, from its meta.proj4, and the
// errors that say why there is none.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import type { CubeMeta } from '../../../format/cube-index.js';
import { CrsError, CrsTransform } from './crs-transform.js';
import { LngLat } from './lng-lat.js';
import { LngLatBounds } from './lng-lat-bounds.js';

// EPSG:28992 as GDAL writes it.
const RD = '+proj=sterea +lat_0=52.15616055555555 +lon_0=5.38763888888889 +k=0.9999079 +x_0=155000 +y_0=463000 +ellps=bessel +towgs84=565.417,50.3319,465.552,-0.398957,0.343988,-1.8774,4.0725 +units=m +no_defs';
const URL = 'https://example.org/cube/index.json';
const meta = (m: Partial<CubeMeta>): CubeMeta => ({ crs: 'EPSG:28992', ...m }) as CubeMeta;

describe('CrsTransform', () => {
  // First: proj4 is imported by load(), not with the module.
  test('before proj4 has been imported, of() says to wait for the meta event', () => {
    assert.throws(() => CrsTransform.of(meta({ proj4: RD }), URL), (e: unknown) => e instanceof CrsError && /proj4, which is still loading for https:\/\/example\.org\/cube\/index\.json: wait for the map's 'meta' event/.test(e.message));
  });

  test("RD New's origin is the Amersfoort tower, and points go there and back to a millimetre", async () => {
    const t = await CrsTransform.load(meta({ proj4: RD }), URL);
    // x 155000, y 463000 is 52.15517440 N, 5.38720621 E in WGS 84 (RDNAPTRANS), to the
    // definition's metre or so.
    const o = t.toLngLat([155000, 463000]);
    assert.ok(Math.abs(o.lng - 5.38720621) < 1e-5 && Math.abs(o.lat - 52.1551744) < 1e-5, o.toString());
    for (const xy of [[181282.695, 457031.109], [100000, 400000], [250000, 600000]] as [number, number][]) {
      const back = t.toProjected(t.toLngLat(xy));
      assert.ok(Math.hypot(back[0] - xy[0], back[1] - xy[1]) < 1e-3, `${xy.join(', ')} came back as ${back.join(', ')}`);
    }
  });

  test('boxes convert through their outlines: the image of every edge point lies inside', async () => {
    const t = await CrsTransform.load(meta({ proj4: RD }), URL);
    const ll = new LngLatBounds([5.7, 52.0], [5.9, 52.2]);
    const b = t.projectedBox(ll);
    for (let i = 0; i <= 10; i++) {
      for (const p of [[5.7 + 0.02 * i, 52.0], [5.7 + 0.02 * i, 52.2], [5.7, 52.0 + 0.02 * i], [5.9, 52.0 + 0.02 * i]] as [number, number][]) {
        const [x, y] = t.toProjected(new LngLat(p[0], p[1]));
        assert.ok(x >= b[0] - 1e-6 && x <= b[2] + 1e-6 && y >= b[1] - 1e-6 && y <= b[3] + 1e-6, `${p.join(', ')} at ${x}, ${y} is outside ${b.join(', ')}`);
      }
    }
    const back = t.lngLatBox(b);
    assert.ok(back.contains([5.7, 52.0]) && back.contains([5.9, 52.2]), back.toString());
  });

  test('a cube without meta.proj4, or with one proj4 cannot read, gets an error naming the index, the CRS and the projected methods', async () => {
    await assert.rejects(CrsTransform.load(meta({}), URL), (e: unknown) => {
      assert.ok(e instanceof CrsError);
      assert.match(e.message, /index\.json has no proj4 definition of its CRS \(meta\.crs "EPSG:28992"\)/);
      assert.match(e.message, /getCenterProjected\(\)/);
      return true;
    });
    await assert.rejects(CrsTransform.load(meta({ crs: '', proj4: '+proj=nonsense' }), URL), /meta\.proj4 \("\+proj=nonsense"\) is not a proj4 definition/);
  });
});
