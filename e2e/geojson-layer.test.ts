// The GeoJSON overlay layer of the script-tag build in a plain page, in Chromium, checked against
// the map's own project() and the pixels of the map without the layer: a line given in
// longitude/latitude is drawn where its coordinates project (before and after a real wheel
// zoom, and with its width in CSS px at a device pixel ratio of 2), setPaint recolours it and
// dataProjected draws it the same, a translucent polygon blends over the map inside and leaves
// its hole and the outside alone, a point is a disc of its radius, later layers draw over
// earlier ones, a real click and real moves fire the layer's click, mouseenter and mouseleave
// with the feature, removing the layer gives back the map's pixels exactly, and a layer added
// before the cube is known is drawn, also after a lost context.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import type { Page } from 'playwright-core';
import { openMap } from './helpers/browser.js';
import { LIB_PAGE_HEAD, useLibSite } from './helpers/lib-site.js';
import { GL_ALLOCATION_LOG, glAllocations, hexColour, loseAndRestoreContext, pixel, screenshot, type Rgba } from './helpers/map-page.js';
import { distanceToPolyline, insideRings } from '../client/src/overlay/overlay-hit.js';
import { idle, settle, type VarioWindow } from './helpers/vario-page.js';

const PAGES: Record<string, string> = {
  'geojson.html': `${LIB_PAGE_HEAD}
  <script src="lib/vario-map.umd.js"></script>
  <script>
    window.map = new vario.VarioMap({ container: 'map', source: 'cube/index.json' });
  </script>
</body>
</html>
`,
  // No supersampling: every frame's map goes straight onto the canvas, never into the colour target.
  'single.html': `${LIB_PAGE_HEAD}
  <script src="lib/vario-map.umd.js"></script>
  <script>
    window.map = new vario.VarioMap({ container: 'map', source: 'cube/index.json', supersampling: 1 });
  </script>
</body>
</html>
`,
  // A layer added at once, before the cube (and its CRS) is known: a square around Otterlo.
  'early.html': `${LIB_PAGE_HEAD}
  <script src="lib/vario-map.umd.js"></script>
  <script>
    window.map = new vario.VarioMap({ container: 'map', source: 'cube/index.json' });
    new vario.GeoJsonLayer({
      data: { type: 'Polygon', coordinates: [[[5.6, 52.0], [5.9, 52.0], [5.9, 52.2], [5.6, 52.2], [5.6, 52.0]]] },
      paint: { fillColor: '#0000ff', fillOpacity: 1, lineWidth: 0 },
    }).addTo(window.map);
  </script>
</body>
</html>
`,
};

type XY = [number, number];

interface PageLayer {
  addTo(m: unknown): PageLayer;
  remove(): PageLayer;
  setData(d: unknown): PageLayer;
  setPaint(p: object): PageLayer;
  on(type: string, fn: (e: { type: string; features: { properties: Record<string, unknown> }[]; point: XY; lngLat: object | null }) => void): PageLayer;
}

/** What the tests use in the page: the map, the library's global and what they keep there. */
interface LayerWindow extends VarioWindow {
  vario: { GeoJsonLayer: new (o: object) => PageLayer; Popup: new () => { setLngLat(ll: unknown): { setText(t: string): { addTo(m: unknown): unknown } } } };
  layers: PageLayer[];
  heard: { type: string; names: unknown[]; point: XY }[];
  mapClicks: number;
  document: { querySelector(s: string): object; querySelectorAll(s: string): ArrayLike<{ getBoundingClientRect(): { left: number; top: number; right: number; bottom: number } }> };
  getComputedStyle(el: object): { cursor: string };
}

const LINE_COLOUR = '#ff00ff';
const FILL_COLOUR = '#0000ff';
const CIRCLE_COLOUR = '#ff8000';

describe('GeoJsonLayer in the script-tag build (bgt_otterlo_400m)', () => {
  const bed = useLibSite(PAGES);

  async function open(deviceScaleFactor = 1, html = 'geojson.html'): Promise<Page> {
    bed.page = await openMap(bed.site.browser, bed.site.server.url, {}, { page: html, deviceScaleFactor });
    const page = bed.page.page;
    await idle(page);
    await page.evaluate(async () => {
      const w = globalThis as unknown as LayerWindow;
      w.map.jumpTo({ scaleDenominator: 3000 });
      await w.map.whenIdle();
      w.layers = [];
    });
    return page;
  }

  /** Longitude/latitude at CSS px of the map. */
  function lngLats(page: Page, points: XY[]): Promise<XY[]> {
    return page.evaluate((pts) => pts.map((p) => {
      const ll = (globalThis as unknown as LayerWindow).map.unproject(p);
      return [ll.lng, ll.lat] as XY;
    }), points);
  }

  /** CSS px of longitude/latitude, by the map's project(). */
  function projected(page: Page, lls: XY[]): Promise<XY[]> {
    return page.evaluate((pts) => pts.map((ll) => (globalThis as unknown as LayerWindow).map.project(ll)), lls);
  }

  function popupTexts(page: Page): Promise<string[]> {
    return page.evaluate(() => Array.from((globalThis as unknown as LayerWindow).document.querySelectorAll('.vario-map-popup-content')).map((el) => (el as unknown as { textContent: string }).textContent));
  }

  /** The boxes of the map's controls (CSS px: x0, y0, x1, y1), which are over the canvas. */
  function controlBoxes(page: Page): Promise<[number, number, number, number][]> {
    return page.evaluate(() => {
      const w = globalThis as unknown as LayerWindow;
      return Array.from(w.document.querySelectorAll('.vario-map-control-container > * > *')).map((el) => {
        const r = el.getBoundingClientRect();
        return [r.left, r.top, r.right, r.bottom] as [number, number, number, number];
      });
    });
  }

  /** Adds a layer (options as JSON) and waits until it is drawn. */
  async function addLayer(page: Page, options: object): Promise<void> {
    await page.evaluate(async (o) => {
      const w = globalThis as unknown as LayerWindow;
      w.layers.push(new w.vario.GeoJsonLayer(o).addTo(w.map));
      await w.map.whenIdle();
    }, options);
  }

  async function removeLayers(page: Page): Promise<void> {
    await page.evaluate(async () => {
      const w = globalThis as unknown as LayerWindow;
      for (const l of w.layers.splice(0)) l.remove();
      await w.map.whenIdle();
    });
  }

  /** No pixel of the map is within `tol` of the colour: pixels of it are the overlay's. */
  function assertAbsent(img: Rgba, hex: string, tol = 40): void {
    const c = hexColour(hex);
    for (let j = 0; j < img.height; j++) for (let i = 0; i < img.width; i++) {
      const p = pixel(img, i, j);
      assert.ok(Math.max(...p.map((v, k) => Math.abs(v - c[k]!))) > tol, `${hex} is not among the map's colours: (${i}, ${j}) is ${p.join(',')}`);
    }
  }

  /** Pixels (their centres, CSS px) that differ between two screenshots. */
  function changed(a: Rgba, b: Rgba): XY[] {
    const out: XY[] = [];
    for (let j = 0; j < a.height; j++) for (let i = 0; i < a.width; i++) {
      if (pixel(a, i, j).some((v, k) => v !== pixel(b, i, j)[k])) out.push([i + 0.5, j + 0.5]);
    }
    return out;
  }

  function near(got: number[], want: number[], tol: number): boolean {
    return got.every((v, k) => Math.abs(v - want[k]!) <= tol);
  }

  test('a map with no layer compiles no overlay program and keeps no overlay target; the first layer adds four programs and two targets of the canvas', async () => {
    bed.page = await openMap(bed.site.browser, bed.site.server.url, {}, { page: 'geojson.html', initScript: GL_ALLOCATION_LOG });
    const page = bed.page.page;
    await idle(page);
    const gl = (): ReturnType<typeof glAllocations> => glAllocations(page);
    const RG32UI = 0x823c, R32F = 0x822e, RGBA8 = 0x8058, RGBA16F = 0x881a, DEPTH32F = 0x8cac;
    const before = await gl();
    // ids and aux with their depth, the slicing surface, the colour (float where it can be
    // drawn to), and the lines' coverage: this cube has lines.
    const colour = before.targets[4]!;
    assert.ok(colour === RGBA16F || colour === RGBA8, `colour target 0x${colour.toString(16)}`);
    assert.deepEqual(before.targets, [RG32UI, RG32UI, DEPTH32F, R32F, colour, RGBA8]);
    const centre = await lngLats(page, [[320, 240], [360, 240], [360, 280], [320, 280]]);
    const shot = await screenshot(page);
    await page.evaluate(async (ring) => {
      const w = globalThis as unknown as LayerWindow;
      w.layers = [new w.vario.GeoJsonLayer({ data: { type: 'Polygon', coordinates: [[...ring, ring[0]!]] }, paint: { fillColor: '#0000ff', fillOpacity: 1, lineWidth: 0 } }).addTo(w.map)];
      await w.map.whenIdle();
    }, centre);
    const after = await gl();
    assert.equal(after.links, before.links + 4, 'fill, quads, composite and show');
    // The layer's coverage, and the layers painted in the colour's format.
    assert.deepEqual(after.targets, [...before.targets, RGBA8, colour]);
    const drawn = await screenshot(page);
    assert.deepEqual(pixel(drawn, 340, 260), hexColour('#0000ff'), 'the square is drawn');
    assert.deepEqual(pixel(drawn, 100, 100), pixel(shot, 100, 100), 'and nothing else');
  });

  test('a line in longitude/latitude is drawn where its coordinates project, also after a wheel zoom; removing it gives the map back exactly', async () => {
    const page = await open();
    const plain = await screenshot(page);
    assertAbsent(plain, LINE_COLOUR);
    // Three places, with a join between them, given in longitude/latitude.
    const coords = await lngLats(page, [[140, 110], [470, 190], [300, 390]]);
    const width = 5;
    await addLayer(page, { data: { type: 'Feature', properties: {}, geometry: { type: 'LineString', coordinates: coords } }, paint: { lineColor: LINE_COLOUR, lineWidth: width } });

    const check = async (label: string): Promise<void> => {
      const drawn = await screenshot(page);
      const line = await projected(page, coords);
      await removeLayers(page);
      const without = await screenshot(page);
      await addLayer(page, { data: { type: 'Feature', properties: {}, geometry: { type: 'LineString', coordinates: coords } }, paint: { lineColor: LINE_COLOUR, lineWidth: width } });
      const diff = changed(drawn, without);
      assert.ok(diff.length > 0, `${label}: the line changed pixels`);
      const worst = Math.max(...diff.map((p) => distanceToPolyline(p, line, false)));
      assert.ok(worst <= width / 2 + 1.5, `${label}: every pixel the layer changed is within width/2 + 1.5 px of the projected line: worst ${worst.toFixed(2)} px`);
      // Along each segment (its ends too: round joins), the line's colour, but under the controls (the attribution).
      const controls = await controlBoxes(page);
      const want = hexColour(LINE_COLOUR);
      for (let s = 0; s + 1 < line.length; s++) {
        for (let t = 0; t <= 1; t += 1 / 32) {
          const x = line[s]![0] + t * (line[s + 1]![0] - line[s]![0]), y = line[s]![1] + t * (line[s + 1]![1] - line[s]![1]);
          if (x < 0 || y < 0 || x >= drawn.width || y >= drawn.height || controls.some((c) => x >= c[0] - 1 && x <= c[2] + 1 && y >= c[1] - 1 && y <= c[3] + 1)) continue;
          const got = pixel(drawn, Math.floor(x), Math.floor(y));
          assert.ok(near(got, want, 2), `${label}: (${x.toFixed(1)}, ${y.toFixed(1)}) on segment ${s} is ${got.join(',')}, not the line's colour`);
        }
      }
    };
    await check('before zooming');

    await page.mouse.move(400, 200);
    await page.mouse.wheel(0, -100);
    await settle(page, 'window.map.getScaleDenominator() < 2000');
    await page.evaluate(() => (globalThis as unknown as LayerWindow).map.whenIdle());
    await check('after a wheel zoom');

  });

  test('without supersampling, a layer added over the finished map changes only its own pixels, and removing it gives the map back exactly', async () => {
    // The map is then not drawn again: the layer goes over the last frame's map, which must be shown as it was.
    const page = await open(1, 'single.html');
    const plain = await screenshot(page);
    const ends: XY[] = [[100, 100], [500, 350]];
    const coords = await lngLats(page, ends);
    await addLayer(page, { data: { type: 'LineString', coordinates: coords }, paint: { lineColor: LINE_COLOUR, lineWidth: 8 } });
    const diff = changed(await screenshot(page), plain);
    assert.ok(diff.length > 1000, 'the layer is drawn');
    const line = await projected(page, coords);
    const worst = Math.max(...diff.map((p) => distanceToPolyline(p, line, false)));
    assert.ok(worst <= 4 + 1.5, `every pixel that changed is within width/2 + 1.5 px of the line: worst ${worst.toFixed(2)} px`);
    await removeLayers(page);
    assert.deepEqual(changed(await screenshot(page), plain), [], 'no pixel differs from the map without the layer');
  });

  test('setPaint recolours the layer; projected data draws as its longitude/latitude does; removing a layer restores the plain map pixels exactly', async () => {
    const page = await open();
    const plain = await screenshot(page);
    const ends: XY[] = [[100, 100], [500, 350]];
    const coords = await lngLats(page, ends);
    await addLayer(page, { data: { type: 'LineString', coordinates: coords }, paint: { lineColor: LINE_COLOUR, lineWidth: 8 } });
    const drawn = await screenshot(page);
    assert.ok(changed(drawn, plain).length > 1000, 'the layer is drawn');
    const mid: XY = [300, 225];
    assert.deepEqual(pixel(drawn, ...mid), hexColour(LINE_COLOUR));
    await page.evaluate(async () => {
      const w = globalThis as unknown as LayerWindow;
      w.layers[0]!.setPaint({ lineColor: '#00ffff' });
      await w.map.whenIdle();
    });
    const recoloured = await screenshot(page);
    assert.deepEqual(pixel(recoloured, ...mid), hexColour('#00ffff'), 'the new colour');
    assert.deepEqual(changed(recoloured, plain), changed(drawn, plain), 'on the same pixels');
    await removeLayers(page);
    assert.deepEqual(changed(await screenshot(page), plain), [], 'no pixel differs from the map without the layer');

    // The same places in the cube's CRS.
    const xy = await page.evaluate((pts) => pts.map((p) => (globalThis as unknown as LayerWindow).map.unprojectProjected(p)), ends);
    await addLayer(page, { dataProjected: { type: 'LineString', coordinates: xy }, paint: { lineColor: LINE_COLOUR, lineWidth: 8 } });
    // Its positions are the same to well under a micrometre (proj4 both ways): an edge pixel may round the other way.
    const same = await screenshot(page);
    const worst = Math.max(...changed(same, drawn).map(([x, y]) => Math.max(...pixel(same, x - 0.5, y - 0.5).map((v, k) => Math.abs(v - pixel(drawn, x - 0.5, y - 0.5)[k]!)))));
    assert.ok(worst <= 2, `dataProjected: the pixels of the same line in longitude/latitude, to 2 levels: worst ${worst}`);
  });

  test('a polygon with a hole at opacity 0.5 blends inside, leaves its hole and the outside alone; a later layer draws over it', async () => {
    const page = await open();
    const plain = await screenshot(page);
    assertAbsent(plain, FILL_COLOUR);
    const outer = await lngLats(page, [[160, 120], [480, 130], [470, 360], [170, 350]]);
    const hole = await lngLats(page, [[260, 200], [380, 200], [380, 280], [260, 280]]);
    await addLayer(page, { data: { type: 'Polygon', coordinates: [[...outer, outer[0]], [...hole, hole[0]]] }, paint: { fillColor: FILL_COLOUR, fillOpacity: 0.5, lineWidth: 0 } });
    const img = await screenshot(page);
    const rings = [await projected(page, outer), await projected(page, hole)];
    const fill = hexColour(FILL_COLOUR);
    let inside = 0, outside = 0;
    for (let j = 0; j < img.height; j++) for (let i = 0; i < img.width; i++) {
      const p: XY = [i + 0.5, j + 0.5];
      const edge = Math.min(...rings.map((r) => distanceToPolyline(p, r, true)));
      if (edge < 1.5) continue; // the anti-aliased edge
      const under = pixel(plain, i, j), got = pixel(img, i, j);
      if (insideRings(p, rings)) {
        const want = under.map((v, k) => 0.5 * fill[k]! + 0.5 * v);
        assert.ok(near(got, want, 1.01), `inside (${i}, ${j}): ${got.join(',')}, blended ${want.join(',')}`);
        inside++;
      } else {
        assert.deepEqual(got, under, `outside or in the hole (${i}, ${j}): the map's pixel`);
        outside++;
      }
    }
    assert.ok(inside > 40000 && outside > 100000, `${inside} pixels inside, ${outside} outside`);

    // An opaque square over part of it, added later: its colour wins where they overlap.
    const square = await lngLats(page, [[180, 140], [240, 140], [240, 200], [180, 200]]);
    await addLayer(page, { data: { type: 'Polygon', coordinates: [[...square, square[0]]] }, paint: { fillColor: LINE_COLOUR, fillOpacity: 1, lineWidth: 0 } });
    const over = await screenshot(page);
    const [cx, cy] = (await projected(page, [square[0]!, square[2]!])).reduce((a, b) => [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2]);
    assert.deepEqual(pixel(over, Math.floor(cx), Math.floor(cy)), hexColour(LINE_COLOUR), 'the layer added last is on top');
  });

  test('a point is a disc of its radius around where it projects', async () => {
    const page = await open();
    const plain = await screenshot(page);
    assertAbsent(plain, CIRCLE_COLOUR);
    const [at] = await lngLats(page, [[321.3, 238.6]]);
    const r = 9;
    await addLayer(page, { data: { type: 'Point', coordinates: at }, paint: { circleColor: CIRCLE_COLOUR, circleRadius: r, circleStrokeWidth: 0 } });
    const img = await screenshot(page);
    const [c] = await projected(page, [at!]);
    const colour = hexColour(CIRCLE_COLOUR);
    let disc = 0;
    for (let j = 200; j < 280; j++) for (let i = 280; i < 360; i++) {
      const d = Math.hypot(i + 0.5 - c![0], j + 0.5 - c![1]);
      if (d <= r - 1) {
        assert.deepEqual(pixel(img, i, j), colour, `(${i}, ${j}), ${d.toFixed(2)} px from the centre, is in the disc`);
        disc++;
      } else if (d >= r + 1) assert.deepEqual(pixel(img, i, j), pixel(plain, i, j), `(${i}, ${j}), ${d.toFixed(2)} px from the centre, is the map's`);
    }
    assert.ok(Math.abs(disc - Math.PI * (r - 1) ** 2) < 2 * Math.PI * (r - 1), `${disc} pixels in the disc of radius ${r - 1}`);
    assert.deepEqual(changed(img, plain).filter((p) => Math.hypot(p[0] - c![0], p[1] - c![1]) > r + 1), [], 'nothing drawn beyond the radius');
  });

  test('a real click on the line fires its click with the feature; moving onto and off it fires mouseenter and mouseleave; the map still hears its clicks', async () => {
    const page = await open();
    const coords = await lngLats(page, [[120, 300], [520, 300]]);
    await page.evaluate(async (c) => {
      const w = globalThis as unknown as LayerWindow;
      w.heard = [];
      w.mapClicks = 0;
      w.map.on('click', () => w.mapClicks++);
      const layer = new w.vario.GeoJsonLayer({
        data: { type: 'FeatureCollection', features: [{ type: 'Feature', id: 1, properties: { name: 'Route 1' }, geometry: { type: 'LineString', coordinates: c } }] },
        paint: { lineColor: '#ff00ff', lineWidth: 6 },
      }).addTo(w.map);
      for (const t of ['click', 'mouseenter', 'mousemove', 'mouseleave']) layer.on(t, (e) => w.heard.push({ type: e.type, names: e.features.map((f) => f.properties.name), point: e.point }));
      // As docs/embedding.md shows: a popup from the layer's click.
      layer.on('click', (e) => new w.vario.Popup().setLngLat(e.lngLat!).setText(String(e.features[0]!.properties.name)).addTo(w.map));
      w.layers.push(layer);
      await w.map.whenIdle();
    }, coords);
    const [a, b] = await projected(page, coords);
    // Whole pixels: the mouse events' coordinates are.
    const mid: XY = [Math.round((a![0] + b![0]) / 2), Math.round((a![1] + b![1]) / 2)];
    const heard = (): Promise<{ type: string; names: unknown[]; point: XY }[]> => page.evaluate(() => (globalThis as unknown as LayerWindow).heard.splice(0));
    const cursor = (): Promise<string> => page.evaluate(() => {
      const w = globalThis as unknown as LayerWindow;
      return w.getComputedStyle(w.document.querySelector('.vario-map-canvas-container canvas')).cursor;
    });

    await page.mouse.move(mid[0], mid[1] - 40);
    assert.deepEqual(await heard(), [], 'nothing 40 px from the line');
    assert.equal(await cursor(), 'grab');
    await page.mouse.move(mid[0], mid[1] + 1);
    const onto = await heard();
    assert.deepEqual(onto.map((e) => [e.type, e.names]), [['mouseenter', ['Route 1']], ['mousemove', ['Route 1']]], 'onto the line: mouseenter, then mousemove');
    assert.equal(await cursor(), 'pointer', 'a pointer over the line');
    await page.mouse.move(mid[0] + 20, mid[1] - 2);
    assert.deepEqual((await heard()).map((e) => e.type), ['mousemove'], 'along it: mousemove only');
    await page.mouse.move(mid[0] + 20, mid[1] + 30);
    assert.deepEqual((await heard()).map((e) => [e.type, e.names]), [['mouseleave', []]], 'off it: mouseleave');
    assert.equal(await cursor(), 'grab', 'the cursor is the map’s again');

    await page.mouse.click(mid[0] - 50, mid[1]);
    const clicked = (await heard()).filter((e) => e.type === 'click');
    assert.deepEqual(clicked.map((e) => e.names), [['Route 1']], "a click on the line fires the layer's click with its feature");
    assert.deepEqual(clicked[0]!.point, [mid[0] - 50, mid[1]], 'at the point clicked');
    // The map's click of the same click comes after the face lookup; the layer's popup stays open through it.
    await page.waitForFunction(() => (globalThis as unknown as LayerWindow).mapClicks === 1);
    assert.deepEqual(await popupTexts(page), ['Route 1×'], "the layer's popup is open after the map's click event");
    await page.mouse.click(mid[0] - 50, mid[1] + 40);
    assert.deepEqual((await heard()).filter((e) => e.type === 'click'), [], 'a click 40 px away is not on the line');
    await page.waitForFunction(() => (globalThis as unknown as LayerWindow).mapClicks === 2);
    assert.deepEqual(await popupTexts(page), [], 'a click elsewhere on the map closes it');
  });

  test('line widths are CSS px: at a device pixel ratio of 2 the line is twice as many device pixels wide', async () => {
    const page = await open(2);
    const coords = await lngLats(page, [[100, 150], [540, 330]]);
    const width = 4;
    const plain = await screenshot(page);
    await addLayer(page, { data: { type: 'LineString', coordinates: coords }, paint: { lineColor: LINE_COLOUR, lineWidth: width } });
    const img = await screenshot(page);
    assert.equal(img.width, 1280, 'the screenshot is in device pixels');
    const line = (await projected(page, coords)).map((p): XY => [2 * p[0], 2 * p[1]]);
    const diff = changed(img, plain);
    const worst = Math.max(...diff.map((p) => distanceToPolyline(p, line, false)));
    assert.ok(worst <= width + 1.5, `changed pixels within ${width} device px (half the width, doubled) + 1.5 of the line: worst ${worst.toFixed(2)}`);
    // Full colour out to 3 device px from the middle: more than half the width in CSS px.
    const full = diff.filter((p) => distanceToPolyline(p, line, false) > 3 && distanceToPolyline(p, line, false) < 3.4);
    assert.ok(full.length > 100 && full.every((p) => near(pixel(img, p[0] - 0.5, p[1] - 0.5), hexColour(LINE_COLOUR), 2)), `pixels 3 device px from the middle are the line's colour (${full.length})`);
  });

  test('a layer added before the cube is known is drawn once it is, and survives a lost context', async () => {
    bed.page = await openMap(bed.site.browser, bed.site.server.url, {}, { page: 'early.html' });
    const page = bed.page.page;
    await idle(page);
    const img = await screenshot(page);
    assert.deepEqual(pixel(img, 320, 240), hexColour(FILL_COLOUR), 'the square covers the map');
    await loseAndRestoreContext(page);
    assert.deepEqual(changed(await screenshot(page), img), [], 'the same picture after the context came back');
  });

  test('invalid GeoJSON is refused with every problem named, and the layer keeps its data', async () => {
    const page = await open();
    const message = await page.evaluate(() => {
      const w = globalThis as unknown as LayerWindow;
      const layer = new w.vario.GeoJsonLayer({ data: { type: 'Point', coordinates: [5.77, 52.1] } }).addTo(w.map);
      w.layers.push(layer);
      try {
        layer.setData({ type: 'FeatureCollection', features: [{ type: 'Feature', properties: {}, geometry: { type: 'Point', coordinates: [5, 100] } }, { type: 'Feature', properties: {}, geometry: { type: 'LineString', coordinates: [[5, 52]] } }] });
        return null;
      } catch (e) {
        return (e as Error).message;
      }
    });
    assert.equal(message, 'GeoJsonLayer setData: 2 problems in the GeoJSON:\n  features[0]: geometry.coordinates: latitude 100 is outside [-90, 90] (longitude/latitude expected; projected coordinates go to setDataProjected)\n  features[1]: geometry.coordinates: a line needs at least two positions, not 1');
  });
});
