// Longitude/latitude in the public API, through the demo page in Chromium: what the map takes
// and gives in longitude/latitude agrees to 1 cm with its projected methods and with proj4 run
// in Node on the EPSG's own definition of RD New (helpers/geo.ts); getZoom() is MapLibre's zoom
// at the view's latitude; a real click's lngLat is unproject() of the click point; the URL hash
// is MapLibre's #zoom/lat/lng both ways. A cube without a CRS definition works in its CRS, and
// the longitude/latitude methods say why they cannot.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import type { Page } from 'playwright-core';
import { openMap } from './helpers/browser.js';
import { lngLatToRd, mapLibreZoom, rdToLngLat } from './helpers/geo.js';
import { waitIdle } from './helpers/map-page.js';
import { useTestBed } from './helpers/test-bed.js';
import { openDemo, resolution, settle, type VarioWindow } from './helpers/vario-page.js';

type LngLatJson = { lng: number; lat: number };
type XY = [number, number];
type XY4 = [number, number, number, number];

/** Metres between a place given in longitude/latitude and a point of RD New, through proj4 in Node. */
const metresOff = (ll: LngLatJson, rd: XY): number => {
  const [x, y] = lngLatToRd([ll.lng, ll.lat]);
  return Math.hypot(x - rd[0], y - rd[1]);
};

const CM = 0.01;

function jumpTo(page: Page, o: { center?: XY; centerProjected?: XY; scaleDenominator?: number; zoom?: number }): Promise<void> {
  return page.evaluate(async (c) => {
    const m = (globalThis as unknown as VarioWindow).map;
    m.jumpTo(c);
    await m.whenIdle();
  }, o);
}

describe('longitude/latitude and zoom in the API (bgt_otterlo_400m, EPSG:28992)', () => {
  const bed = useTestBed();
  const middle = (): XY => {
    const e = bed.contents.meta.extent;
    return [(e[0] + e[2]) / 2, (e[1] + e[3]) / 2];
  };

  test('ssc build wrote the proj4 definition of EPSG:28992 into index.json', () => {
    assert.equal(bed.contents.meta.crs, 'EPSG:28992');
    assert.match(bed.contents.meta.proj4 ?? '', /^\+proj=sterea .*\+x_0=155000 \+y_0=463000 .*\+ellps=bessel/);
  });

  test('the lon/lat and projected methods agree to 1 cm, with each other and with proj4 in Node', async () => {
    bed.page = await openDemo(bed.browser, bed.server.url);
    const page = bed.page.page;
    // A place given in longitude/latitude lands where proj4 in Node puts it in RD New.
    const target = rdToLngLat([middle()[0] + 37.123, middle()[1] - 21.456]);
    await jumpTo(page, { center: target, scaleDenominator: 1000 });
    const r = await page.evaluate(() => {
      const m = (globalThis as unknown as VarioWindow).map;
      const points: XY[] = [[0, 0], [320, 240], [639, 479], [123.5, 456.25]];
      return {
        center: m.getCenter(),
        centerProjected: m.getCenterProjected(),
        // unproject(p) beside unprojectProjected(p), and project() of the place back to CSS px.
        points: points.map((p) => {
          const ll = m.unproject(p);
          return { p, ll, xy: m.unprojectProjected(p), back: m.project([ll.lng, ll.lat]) };
        }),
        scale: m.getScaleDenominator(),
      };
    });
    assert.ok(metresOff({ lng: target[0], lat: target[1] }, r.centerProjected) < CM, `jumpTo({ center }) put the centre at ${r.centerProjected.join(', ')}`);
    assert.ok(metresOff(r.center, r.centerProjected) < CM, 'getCenter() is getCenterProjected() in longitude/latitude');
    // proj4's inverse of its forward is good to about 5e-9 degrees (half a millimetre).
    assert.ok(Math.abs(r.center.lng - target[0]) < 1e-7 && Math.abs(r.center.lat - target[1]) < 1e-7, `getCenter() gives back the centre given: ${r.center.lng}, ${r.center.lat} for ${target.join(', ')}`);
    const res = resolution(r.scale, bed.contents.meta.pixelSizeMm);
    for (const q of r.points) {
      assert.ok(metresOff(q.ll, q.xy) < CM, `unproject(${q.p.join(', ')}) is unprojectProjected() in longitude/latitude: ${metresOff(q.ll, q.xy)} m`);
      const pxOff = Math.hypot(q.back[0] - q.p[0], q.back[1] - q.p[1]);
      assert.ok(pxOff * res < CM, `project(unproject(${q.p.join(', ')})) comes back to ${q.back.join(', ')}`);
    }

    // getBounds() is the longitude/latitude box of the projected one's corners.
    const b = await page.evaluate(() => {
      const m = (globalThis as unknown as VarioWindow).map;
      const lb = m.getBounds();
      return { w: lb.getWest(), s: lb.getSouth(), e: lb.getEast(), n: lb.getNorth(), projected: m.getBoundsProjected() };
    });
    const [x0, y0, x1, y1] = b.projected;
    const corners = ([[x0, y0], [x1, y0], [x1, y1], [x0, y1]] as XY[]).map(rdToLngLat);
    const degreesPerCm = 1e-7; // a tenth of a microdegree is under 1 cm in either direction
    assert.ok(Math.abs(b.w - Math.min(...corners.map((c) => c[0]))) < degreesPerCm, `west ${b.w}`);
    assert.ok(Math.abs(b.e - Math.max(...corners.map((c) => c[0]))) < degreesPerCm, `east ${b.e}`);
    assert.ok(Math.abs(b.s - Math.min(...corners.map((c) => c[1]))) < degreesPerCm, `south ${b.s}`);
    assert.ok(Math.abs(b.n - Math.max(...corners.map((c) => c[1]))) < degreesPerCm, `north ${b.n}`);

    // fitBounds() of a longitude/latitude box shows the RD New box around its four corners (a
    // rectangle turned by the meridians' convergence, 0.3 degrees here), whole and fitted. Its
    // edges are straight lines in RD New to well under a centimetre over 300 m.
    const [sw, ne] = [rdToLngLat([middle()[0] - 150, middle()[1] - 40]), rdToLngLat([middle()[0] + 150, middle()[1] + 40])];
    const shown = await page.evaluate(async (bx) => {
      const m = (globalThis as unknown as VarioWindow).map;
      await m.fitBounds(bx, { duration: 0 });
      return m.getBoundsProjected();
    }, [sw[0], sw[1], ne[0], ne[1]] as [number, number, number, number]);
    const rd = ([[sw[0], sw[1]], [ne[0], sw[1]], [ne[0], ne[1]], [sw[0], ne[1]]] as XY[]).map(lngLatToRd);
    const want = [Math.min(...rd.map((p) => p[0])), Math.min(...rd.map((p) => p[1])), Math.max(...rd.map((p) => p[0])), Math.max(...rd.map((p) => p[1]))];
    const inside = shown[0] <= want[0]! + CM && shown[1] <= want[1]! + CM && shown[2] >= want[2]! - CM && shown[3] >= want[3]! - CM;
    assert.ok(inside, `the box ${want.join(', ')} is within the view ${shown.join(', ')}`);
    const fitsWidth = Math.abs(shown[0] - want[0]!) < CM && Math.abs(shown[2] - want[2]!) < CM;
    assert.ok(fitsWidth, `the wide box fills the view's width: ${shown.join(', ')} for ${want.join(', ')}`);
  });

  test('setMaxBounds() of a longitude/latitude box limits the view to the RD New box around it', async () => {
    bed.page = await openDemo(bed.browser, bed.server.url);
    const page = bed.page.page;
    const [sw, ne] = [rdToLngLat([middle()[0] - 400, middle()[1] - 300]), rdToLngLat([middle()[0] + 400, middle()[1] + 300])];
    const r = await page.evaluate(async (bx) => {
      const m = (globalThis as unknown as VarioWindow & { map: { setMaxBounds(b: number[]): unknown; getMaxBoundsProjected(): XY4 } }).map;
      m.setMaxBounds(bx);
      // A flight far to the north-east ends in the box's corner.
      await m.flyTo({ centerProjected: [1e9, 1e9], scaleDenominator: 1000, duration: 0 });
      return { limit: m.getMaxBoundsProjected(), view: m.getBoundsProjected() };
    }, [sw[0], sw[1], ne[0], ne[1]]);
    const rd = ([[sw[0], sw[1]], [ne[0], sw[1]], [ne[0], ne[1]], [sw[0], ne[1]]] as XY[]).map(lngLatToRd);
    const want = [Math.min(...rd.map((p) => p[0])), Math.min(...rd.map((p) => p[1])), Math.max(...rd.map((p) => p[0])), Math.max(...rd.map((p) => p[1]))];
    r.limit.forEach((v, i) => assert.ok(Math.abs(v - want[i]!) < CM, `limit ${r.limit.join(', ')} vs ${want.join(', ')}`));
    assert.ok(Math.abs(r.view[2] - want[2]!) < CM && Math.abs(r.view[3] - want[3]!) < CM, `the view ends in the north-east corner: ${r.view.join(', ')}`);
  });

  test("getZoom() is MapLibre's zoom at the view's latitude, and setZoom() and the zoom option mean the same", async () => {
    bed.page = await openDemo(bed.browser, bed.server.url);
    const page = bed.page.page;
    for (const scale of [600, 2500, 17000]) {
      await jumpTo(page, { centerProjected: middle(), scaleDenominator: scale });
      const r = await page.evaluate(() => {
        const m = (globalThis as unknown as VarioWindow).map;
        const a = m.unprojectProjected([100, 240]), b = m.unprojectProjected([500, 240]);
        return { zoom: m.getZoom(), center: m.getCenterProjected(), metresPerPixel: Math.hypot(b[0] - a[0], b[1] - a[1]) / 400 };
      });
      // The ground one CSS pixel covers, measured on the map, and the centre's latitude from proj4 in Node.
      const lat = rdToLngLat(r.center)[1];
      const expected = mapLibreZoom(r.metresPerPixel, lat);
      assert.ok(Math.abs(r.zoom - expected) < 1e-9, `1:${scale}: getZoom() ${r.zoom}, MapLibre's formula ${expected}`);
    }
    // setZoom(z): a CSS pixel covers MapLibre's metres per pixel at z and this latitude.
    const z = 16.5;
    await page.evaluate(async (zz) => {
      const m = (globalThis as unknown as VarioWindow).map;
      m.setZoom(zz);
      await m.whenIdle();
    }, z);
    const after = await page.evaluate(() => {
      const m = (globalThis as unknown as VarioWindow).map;
      return { zoom: m.getZoom(), scale: m.getScaleDenominator(), center: m.getCenterProjected() };
    });
    const lat = rdToLngLat(after.center)[1];
    const mapLibreMetresPerPixel = (40075016.686 * Math.cos((lat * Math.PI) / 180)) / (512 * 2 ** z);
    assert.ok(Math.abs(after.zoom - z) < 1e-9, `getZoom() after setZoom(${z}): ${after.zoom}`);
    assert.ok(Math.abs(resolution(after.scale, bed.contents.meta.pixelSizeMm) / mapLibreMetresPerPixel - 1) < 1e-9, `1:${after.scale} at zoom ${z}`);
  });

  test("a real click's lngLat is unproject() of the click point, and its projected point is the same place", async () => {
    bed.page = await openDemo(bed.browser, bed.server.url);
    const page = bed.page.page;
    await jumpTo(page, { centerProjected: middle(), scaleDenominator: 1500 });
    await page.evaluate(() => {
      const w = globalThis as unknown as VarioWindow & { clicks: unknown[] };
      w.clicks = [];
      w.map.on('click', (ev) => w.clicks.push(ev));
    });
    const at: XY = [211, 307];
    await page.mouse.click(...at);
    await page.waitForFunction(() => (globalThis as unknown as { clicks: unknown[] }).clicks.length > 0);
    const r = await page.evaluate((p) => {
      const w = globalThis as unknown as VarioWindow & { clicks: { point: XY; lngLat: LngLatJson; projected: XY }[] };
      const ev = w.clicks[0]!;
      return { point: ev.point, lngLat: { lng: ev.lngLat.lng, lat: ev.lngLat.lat }, projected: ev.projected, unprojected: w.map.unproject(p), moving: w.map.isMoving() };
    }, at);
    assert.equal(r.moving, false, 'a click does not move the map');
    assert.deepEqual(r.point, at, 'the event is at the click (the map fills the page)');
    assert.deepEqual(r.lngLat, { lng: r.unprojected.lng, lat: r.unprojected.lat }, 'lngLat is unproject(point)');
    assert.ok(metresOff(r.lngLat, r.projected) < CM, 'lngLat and projected are one place');
  });

  test("the URL hash is MapLibre's #zoom/lat/lng: written after a move, and one from MapLibre opens that place and scale", async () => {
    // A MapLibre link: zoom 17.25 at 52.1 N 5.79 E (inside the data).
    const [lng, lat] = rdToLngLat(middle()).map((v) => Math.round(v * 1e4) / 1e4) as XY;
    bed.page = await openDemo(bed.browser, bed.server.url, {}, { hash: `#17.25/${lat}/${lng}` });
    const page = bed.page.page;
    const opened = await page.evaluate(() => {
      const m = (globalThis as unknown as VarioWindow).map;
      return { zoom: m.getZoom(), center: m.getCenterProjected(), scale: m.getScaleDenominator() };
    });
    assert.ok(metresOff({ lng, lat }, opened.center) < CM, `the hash's place is the centre: ${opened.center.join(', ')}`);
    const metresPerPixel = resolution(opened.scale, bed.contents.meta.pixelSizeMm);
    assert.ok(Math.abs(mapLibreZoom(metresPerPixel, lat) - 17.25) < 1e-9, `the hash's zoom at its latitude: 1:${opened.scale}`);

    // A real wheel notch zooms out; at moveend the hash says where the map is now.
    await page.mouse.move(320, 240);
    await page.mouse.wheel(0, 100);
    await settle(page, `window.map.getZoom() < 17`);
    await page.waitForFunction(() => {
      const m = (globalThis as unknown as VarioWindow).map;
      return (globalThis as unknown as { location: { hash: string } }).location.hash.startsWith(`#${Math.round(m.getZoom() * 1e4) / 1e4}/`);
    });
    const now = await page.evaluate(() => {
      const m = (globalThis as unknown as VarioWindow).map;
      const c = m.getCenter();
      return { hash: (globalThis as unknown as { location: { hash: string } }).location.hash, zoom: m.getZoom(), lng: c.lng, lat: c.lat };
    });
    const parts = now.hash.slice(1).split('/').map(Number);
    assert.equal(parts.length, 3, now.hash);
    assert.ok(Math.abs(parts[0]! - now.zoom) <= 5e-5, `zoom first: ${now.hash} for ${now.zoom}`);
    assert.ok(Math.abs(parts[1]! - now.lat) < 1e-6 && Math.abs(parts[2]! - now.lng) < 1e-6, `then latitude and longitude: ${now.hash} for ${now.lat}, ${now.lng}`);
  });
});

describe('a cube whose CRS has no proj4 definition (bgt_otterlo_400m built with --crs EPSG:999999)', () => {
  const bed = useTestBed(['--crs', 'EPSG:999999']);

  test('the projected methods work; the longitude/latitude ones say why they cannot, and a click has no lngLat', async () => {
    assert.equal(bed.contents.meta.crs, 'EPSG:999999');
    assert.equal(bed.contents.meta.proj4, undefined, 'ssc build wrote no definition it does not have');
    bed.page = await openMap(bed.browser, bed.server.url, { source: 'cube/', supersampling: 1 });
    const page = bed.page.page;
    await waitIdle(page);
    const r = await page.evaluate(() => {
      const m = (globalThis as unknown as VarioWindow).map;
      const error = (f: () => unknown): string => {
        try {
          f();
          return 'no error';
        } catch (e) {
          return `${(e as Error).name}: ${(e as Error).message}`;
        }
      };
      return {
        projected: m.getCenterProjected(),
        getCenter: error(() => m.getCenter()),
        jumpTo: error(() => m.jumpTo({ center: [5.77, 52.1] })),
        project: error(() => m.project([5.77, 52.1])),
      };
    });
    const e = bed.contents.meta.extent;
    assert.deepEqual(r.projected, [(e[0] + e[2]) / 2, (e[1] + e[3]) / 2], 'the map shows the extent, its centre in the CRS');
    for (const [what, message] of Object.entries({ getCenter: r.getCenter, jumpTo: r.jumpTo, project: r.project })) {
      assert.match(message, /^CrsError: .*index\.json has no proj4 definition of its CRS \(meta\.crs "EPSG:999999"\).*getCenterProjected\(\)/, what);
    }
    await page.evaluate(() => {
      const w = globalThis as unknown as VarioWindow & { clicks: unknown[] };
      w.clicks = [];
      w.map.on('click', (ev) => w.clicks.push(ev));
    });
    await page.mouse.click(200, 150);
    await page.waitForFunction(() => (globalThis as unknown as { clicks: unknown[] }).clicks.length > 0);
    const click = await page.evaluate(() => {
      const ev = (globalThis as unknown as { clicks: { lngLat: unknown; projected: XY }[] }).clicks[0]!;
      return { lngLat: ev.lngLat, projected: ev.projected, unprojected: (globalThis as unknown as VarioWindow).map.unprojectProjected([200, 150]) };
    });
    assert.equal(click.lngLat, null);
    assert.deepEqual(click.projected, click.unprojected);
  });
});
