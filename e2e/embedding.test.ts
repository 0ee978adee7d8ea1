// The published builds in plain HTML pages, as docs/embedding.md shows them: the script-tag
// (UMD) build with its inlined worker, and the ES module build with its worker file; and
// remove(), which must leave no worker, no GPU context and no listener behind.
import assert from 'node:assert/strict';
import { readdir } from 'node:fs/promises';
import path from 'node:path';
import { describe, test } from 'node:test';
import type { Page } from 'playwright-core';
import { CachePolicy, IMMUTABLE } from '../server/cache-control.js';
import { openMap } from './helpers/browser.js';
import { lngLatToRd, rdToLngLat } from './helpers/geo.js';
import { LIB_PAGE_HEAD, useLibSite } from './helpers/lib-site.js';
import { hexColour, pixel, screenshot } from './helpers/map-page.js';
import { camera, idle, settle, type VarioWindow } from './helpers/vario-page.js';

const PAGES: Record<string, string> = {
  'script-tag.html': `${LIB_PAGE_HEAD}
  <script src="lib/vario-map.umd.js"></script>
  <script>
    var map = new vario.VarioMap({ container: 'map', source: 'cube/index.json' });
    map.addControl(new vario.ZoomControl());
    map.addControl(new vario.ScaleBar(), 'bottom-left');
  </script>
</body>
</html>
`,
  'module.html': `${LIB_PAGE_HEAD}
  <script type="module">
    import { VarioMap, ZoomControl, ScaleBar } from './lib/vario-map.js';
    const map = new VarioMap({ container: 'map', source: 'cube/index.json' });
    map.addControl(new ZoomControl());
    map.addControl(new ScaleBar(), 'bottom-left');
    window.map = map;
  </script>
</body>
</html>
`,
  // The ES build opening where the query says (?center=lng,lat&scale=S; none: the whole cube),
  // noting when its first 'complete', 'meta' and 'load' events come and what it said of
// longitude/latitude then.
  'lazy-proj4.html': `${LIB_PAGE_HEAD}
  <script type="module">
    import { Marker, SettingsPanel, VarioMap } from './lib/vario-map.js';
    const q = new URLSearchParams(location.search);
    const center = q.get('center')?.split(',').map(Number);
    const scale = q.get('scale');
    const map = new VarioMap({ container: 'map', source: 'cube/', supersampling: 1, ...(center ? { center, scaleDenominator: Number(scale) } : {}) });
    window.events = [];
    const note = (type) => {
      let lngLat;
      try {
        lngLat = map.getCenter().toArray();
      } catch (err) {
        lngLat = String(err);
      }
      window.events.push({ type, at: Date.now(), metadata: map.getMetadata() !== null, lngLat });
    };
    map.once('complete').then(() => note('complete'));
    // ?later=lng,lat: jumped to once the first chunk is asked for (the index is in), before the first map.
    const later = q.get('later')?.split(',').map(Number);
    if (later) map.once('dataloading').then(() => map.jumpTo({ center: later }));
    // ?jump=x,y,scale: jumped to in the cube's coordinates at the first map; its view's 'complete' noted.
    const jump = q.get('jump')?.split(',').map(Number);
    if (jump) map.once('complete').then(() => {
      map.jumpTo({ centerProjected: [jump[0], jump[1]], scaleDenominator: jump[2] });
      window.jumped = { center: map.getCenterProjected(), scale: map.getScaleDenominator() };
      return map.once('complete');
    }).then(() => note('jump complete'));
    map.on('load', () => note('load'));
    map.on('meta', () => note('meta'));
    // ?marker=lng,lat: a marker there, added at once.
    const marker = q.get('marker')?.split(',').map(Number);
    if (marker) window.marker = new Marker().setLngLat(marker).addTo(map);
    // ?settings: the settings panel.
    if (q.has('settings')) map.addControl(new SettingsPanel());
    window.map = map;
  </script>
</body>
</html>
`,
  // The map is made and removed on the test's command, with every part that listens to something.
  'remove.html': `${LIB_PAGE_HEAD}
  <script src="lib/vario-map.umd.js"></script>
  <script>
    window.create = function () {
      window.map = new vario.VarioMap({ container: 'map', source: 'cube/', hash: true });
      var settings = new vario.SettingsPanel();
      map.addControl(new vario.ZoomControl()).addControl(settings).addControl(new vario.ScaleBar(), 'bottom-left');
      settings.log.start();
    };
  </script>
</body>
</html>
`,
};

describe('the library builds in plain pages (bgt_otterlo_400m)', () => {
  const bed = useLibSite(PAGES);

  async function open(name: string): Promise<{ page: Page }> {
    bed.page = await openMap(bed.site.browser, bed.site.server.url, {}, { page: name });
    return { page: bed.page.page };
  }

  /** Share of the screen in one of the style's class colours: a map is drawn. */
  async function mapShare(page: Page): Promise<number> {
    const colours = bed.contents.meta.style.classes.map((c) => hexColour(c.color).join());
    const img = await screenshot(page);
    let n = 0;
    for (let j = 0; j < img.height; j += 4) for (let i = 0; i < img.width; i += 4) if (colours.includes(pixel(img, i, j).join())) n++;
    return n / ((img.width / 4) * (img.height / 4));
  }

  async function wheelZooms(page: Page): Promise<void> {
    const start = await camera(page);
    await page.mouse.move(320, 300);
    await page.mouse.wheel(0, -100);
    await settle(page, `window.map.getScaleDenominator() < ${start.scale * 0.75}`);
    assert.ok(Math.abs((await camera(page)).scale - start.scale / 2) < 1e-6 * start.scale);
  }

  test('the script-tag build: a global, an inlined worker, a drawn map that zooms', async () => {
    const { page } = await open('script-tag.html');
    await idle(page);
    assert.equal(await page.evaluate(() => (globalThis as unknown as VarioWindow).map.whenIdle().then((r) => r.complete)), true);
    const urls = page.workers().map((w) => w.url());
    assert.equal(urls.length, 1, `one worker: ${urls}`);
    assert.match(urls[0]!, /^blob:/, 'the worker is inlined');
    assert.ok((await mapShare(page)) > 0.5, 'the map is drawn');
    assert.match(await page.locator('.vario-map-scale-denominator').innerText(), /^1:/);
    assert.match(await page.locator('.vario-map-attrib').innerText(), /Kadaster/);
    await wheelZooms(page);
  });

  test('the ES module build: its worker a file beside it, a drawn map that zooms', async () => {
    const { page } = await open('module.html');
    await idle(page);
    const urls = page.workers().map((w) => w.url());
    assert.equal(urls.length, 1);
    assert.match(urls[0]!, /\/lib\/assets\/chunk-worker-[\w-]+\.js$/);
    assert.ok((await mapShare(page)) > 0.5, 'the map is drawn');
    await wheelZooms(page);
    // Its files are named by their content in a form the servers know (server/cache-control.ts,
    // nginx.conf.template), so a browser keeps them without asking again.
    const files = (await readdir(path.join(bed.site.dir, 'lib/assets'))).filter((f) => f.endsWith('.js'));
    assert.ok(files.length >= 4, `the worker, proj4, the gzip fallback and the GeoJSON layers' geometry: ${files}`);
    for (const f of files) assert.equal(new CachePolicy().headerFor(f), IMMUTABLE, f);
  });

  test("the ES module build fetches a GeoJSON layer's code with the first layer, and the map is idle only once that layer is drawn", async () => {
    const logStart = bed.site.server.log.length;
    const { page } = await open('module.html');
    await idle(page);
    const geometryFiles = (): string[] => bed.site.server.log.slice(logStart).filter((e) => /^\/lib\/assets\/layer-geometry-[0-9a-f]+\.js$/.test(e.path)).map((e) => e.path);
    assert.deepEqual(geometryFiles(), [], 'a map without layers does not fetch it');
    // The file comes late, so that the map would have drawn and gone idle without the layer.
    bed.site.server.faults.appDelayMs = (file) => (file.includes('/layer-geometry-') ? 500 : 0);
    const magenta = await page.evaluate(async () => {
      const w = globalThis as unknown as VarioWindow & { location: { href: string } };
      const { GeoJsonLayer } = (await import(new URL('lib/vario-map.js', w.location.href).href)) as { GeoJsonLayer: new (o: object) => { addTo(m: unknown): unknown } };
      // A square over the middle of the view.
      const ring = ([[200, 150], [440, 150], [440, 330], [200, 330], [200, 150]] as [number, number][]).map((p) => {
        const ll = w.map.unproject(p);
        return [ll.lng, ll.lat];
      });
      new GeoJsonLayer({ data: { type: 'Polygon', coordinates: [ring] }, paint: { fillColor: '#ff00ff', fillOpacity: 1, lineWidth: 0 } }).addTo(w.map);
      return (await w.map.whenIdle()).complete;
    }).finally(() => (bed.site.server.faults.appDelayMs = () => 0));
    assert.equal(magenta, true);
    assert.deepEqual(pixel(await screenshot(page), 320, 240), hexColour('#ff00ff'), 'drawn by the time the map is idle');
    assert.equal(geometryFiles().length, 1, `fetched once: ${geometryFiles()}`);
  });

  describe('proj4 is fetched once the index is in, not with the library', () => {
    type Noted = { type: 'complete' | 'meta' | 'load' | 'jump complete'; at: number; metadata: boolean; lngLat: [number, number] | string };

    /**
     * The page with proj4's file held back until `release(page)` resolves, open until 'meta' and
     * idle; what it noted, and the server's log of proj4 and the chunks.
     */
    async function openSlowProj4(params: Record<string, string>, release: (page: Page) => Promise<unknown>): Promise<{ page: Page; noted: Noted[]; proj4: { start: number; end: number }; chunks: { start: number }[] }> {
      const site = bed.site;
      const from = site.server.log.length;
      bed.page = await openMap(site.browser, site.server.url, params, {
        page: 'lazy-proj4.html',
        onPage: (p) => void p.route(/\/lib\/assets\/proj4-[\w-]+\.js$/, async (route) => {
          await release(p);
          await route.continue();
        }),
      });
      const page = bed.page.page;
      await page.waitForFunction(() => (globalThis as unknown as { events: Noted[] }).events.some((e) => e.type === 'load'), null, { timeout: 60_000 });
      await idle(page);
      const noted = await page.evaluate(() => (globalThis as unknown as { events: Noted[] }).events);
      const log = site.server.log.slice(from);
      const proj4 = log.filter((e) => /^\/lib\/assets\/proj4-[\w-]+\.js$/.test(e.path));
      assert.equal(proj4.length, 1, `proj4 fetched once: ${log.map((e) => e.path).join(' ')}`);
      const index = log.find((e) => e.path === '/cube/index.json')!;
      assert.ok(proj4[0]!.start >= index.end, 'proj4 is asked for after the index has arrived, not with the library');
      return { page, noted, proj4: proj4[0]!, chunks: log.filter((e) => /^\/cube\/[cb]-/.test(e.path)) };
    }

    test("a page in the cube's own coordinates fetches proj4 after its first map; longitude/latitude work from its meta event on, and 'load' waits for it", async () => {
      const { noted, proj4, chunks } = await openSlowProj4({}, () => Promise.resolve());
      assert.ok(chunks.length > 0 && chunks[0]!.start < proj4.start, 'chunks were asked for before proj4');
      assert.deepEqual(noted.map((e) => e.type), ['complete', 'meta', 'load'], "the first map came before proj4; 'load' waited for 'meta'");
      // The import starts in the same task as the first 'complete', a few ms before the page notes it.
      assert.ok(proj4.start >= noted[0]!.at - 5, `proj4 was asked for after the first map (${proj4.start - noted[0]!.at} ms)`);
      assert.match(String(noted[0]!.lngLat), /CrsError: .*wait for the 'meta' event/, 'before meta, longitude/latitude say why they wait');
      assert.equal(noted[0]!.metadata, false, 'getMetadata() is null until meta');
      for (const at of noted.slice(1)) {
        assert.equal(at.metadata, true);
        if (typeof at.lngLat === 'string') assert.fail(`getCenter() at ${at.type}: ${at.lngLat}`);
      }
      const [lng, lat] = noted[2]!.lngLat as [number, number];
      const e = bed.contents.meta.extent;
      const [x, y] = lngLatToRd([lng, lat]);
      assert.ok(Math.hypot(x - (e[0] + e[2]) / 2, y - (e[1] + e[3]) / 2) < 0.01, `the whole cube's centre, ${lng}, ${lat}, is within 1 cm of its extent's`);
    });

    test("a jump in the cube's own coordinates is carried out while proj4 still loads", async () => {
      const e = bed.contents.meta.extent;
      const to: [number, number, number] = [e[0] + (e[2] - e[0]) * 0.25, e[1] + (e[3] - e[1]) * 0.75, 1500];
      // proj4 held back until the jump's view is complete: a jump that waited for it never would be.
      const done = (p: Page): Promise<unknown> => p.waitForFunction(() => (globalThis as unknown as { events: Noted[] }).events.some((n) => n.type === 'jump complete'), null, { timeout: 60_000 });
      const { page, noted } = await openSlowProj4({ jump: to.join(',') }, done);
      const jumped = await page.evaluate(() => (globalThis as unknown as { jumped: { center: [number, number]; scale: number } }).jumped);
      assert.deepEqual(jumped, { center: [to[0], to[1]], scale: to[2] }, 'the view moved at once');
      assert.deepEqual(noted.map((n) => n.type), ['complete', 'jump complete', 'meta', 'load']);
      assert.equal(noted[1]!.metadata, false, 'before meta');
    });

    test('a marker added with the map shows where it belongs once proj4 has come, though the map had gone idle', async () => {
      const e = bed.contents.meta.extent;
      const at = rdToLngLat([e[0] + (e[2] - e[0]) * 0.4, e[1] + (e[3] - e[1]) * 0.45]);
      // proj4 held back until the first map is drawn and the frames have stopped.
      const idleAfterFirst = async (p: Page): Promise<void> => {
        await p.waitForFunction(() => (globalThis as unknown as { events: Noted[] }).events.some((n) => n.type === 'complete'), null, { timeout: 60_000 });
        await p.evaluate(() => (globalThis as unknown as VarioWindow).map.whenIdle());
      };
      const { page } = await openSlowProj4({ marker: at.join(',') }, idleAfterFirst);
      type PageMarker = { getElement(): { style: { visibility: string }; getBoundingClientRect(): { left: number; width: number; bottom: number } }; getLngLat(): { lng: number; lat: number } };
      const shown = await page.evaluate(() => {
        const w = globalThis as unknown as VarioWindow & { marker: PageMarker };
        const el = w.marker.getElement();
        const r = el.getBoundingClientRect(), ll = w.marker.getLngLat();
        return { visibility: el.style.visibility, tip: [r.left + r.width / 2, r.bottom], point: w.map.project([ll.lng, ll.lat]) };
      });
      assert.equal(shown.visibility, '', 'the marker is shown');
      // The default pin's tip (its bottom centre) is on the place (the map fills the page).
      assert.ok(Math.abs(shown.tip[0]! - shown.point[0]) < 1 && Math.abs(shown.tip[1]! - shown.point[1]) < 1, `the pin's tip at ${shown.tip.join(', ')}, its place at ${shown.point.join(', ')}`);
    });

    test("a slicing surface chosen in the settings panel before 'meta' takes effect when it comes", async () => {
      let before = '';
      // proj4 held back until the surface has been chosen, after the first map.
      const choose = async (p: Page): Promise<void> => {
        await p.waitForFunction(() => (globalThis as unknown as { events: Noted[] }).events.some((n) => n.type === 'complete'), null, { timeout: 60_000 });
        await p.click('.vario-map-settings-toggle');
        await p.selectOption('select[id$="-surface"]', 'sine');
        await p.keyboard.press('Escape');
        before = await p.evaluate(() => (globalThis as unknown as VarioWindow).map.getSlicingSurface().kind);
      };
      const { page, noted } = await openSlowProj4({ settings: '' }, choose);
      assert.equal(before, 'flat', 'before meta the surface cannot be sized to the cube yet');
      assert.deepEqual(noted.map((n) => n.type), ['complete', 'meta', 'load']);
      const surface = await page.evaluate(() => (globalThis as unknown as VarioWindow).map.getSlicingSurface() as { kind: string; amplitude?: number });
      assert.equal(surface.kind, 'sine', 'the choice was kept and carried out at meta');
      assert.equal(surface.amplitude, bed.contents.meta.zMax * 0.05, "sized to the cube's z range");
    });

    test('a jump to a longitude/latitude before the first map fetches proj4 at once, and the map goes there', async () => {
      const e = bed.contents.meta.extent;
      const centre = rdToLngLat([e[0] + (e[2] - e[0]) * 0.7, e[1] + (e[3] - e[1]) * 0.4]);
      // The chunks held back, so that the jump comes well before the first map.
      bed.site.server.faults.delayMs = (file) => (/^[cb]-/.test(file) ? 4000 : 0);
      try {
        const { page, noted, proj4 } = await openSlowProj4({ later: centre.join(',') }, () => Promise.resolve());
        const complete = noted.find((n) => n.type === 'complete')!;
        assert.ok(proj4.end <= complete.at, `proj4 came before the first map (${complete.at - proj4.end} ms)`);
        const got = await page.evaluate(() => (globalThis as unknown as VarioWindow).map.getCenter()).then((c): [number, number] => [c.lng, c.lat]);
        const [gx, gy] = lngLatToRd(got), [cx, cy] = lngLatToRd(centre);
        assert.ok(Math.hypot(gx - cx, gy - cy) < 0.01, `jumped to ${got.join(', ')}, within 1 cm of ${centre.join(', ')}`);
      } finally {
        bed.site.server.faults.delayMs = () => 0;
      }
    });

    test('a page that opens at a longitude/latitude asks for no chunk before proj4 has arrived, then opens there', async () => {
      const e = bed.contents.meta.extent;
      const centre = rdToLngLat([e[0] + (e[2] - e[0]) * 0.3, e[1] + (e[3] - e[1]) * 0.6]);
      const { page, noted, proj4, chunks } = await openSlowProj4({ center: centre.join(','), scale: '2000' }, () => new Promise((r) => setTimeout(r, 1000)));
      assert.ok(chunks.length > 0, 'chunks were fetched');
      assert.ok(chunks.every((c) => c.start >= proj4.end), 'no chunk of the fitted whole cube was fetched in vain while the CRS loaded');
      assert.deepEqual(noted.map((n) => n.type).sort(), ['complete', 'load', 'meta']);
      assert.equal(noted[0]!.type, 'meta', 'nothing was drawn before the CRS was known');
      const got = await page.evaluate(() => (globalThis as unknown as VarioWindow).map.getCenter()).then((c): [number, number] => [c.lng, c.lat]);
      const [gx, gy] = lngLatToRd(got), [cx, cy] = lngLatToRd(centre);
      assert.ok(Math.hypot(gx - cx, gy - cy) < 0.01, `opened at ${got.join(', ')}, within 1 cm of ${centre.join(', ')}`);
      assert.equal(await page.evaluate(() => (globalThis as unknown as VarioWindow).map.getScaleDenominator()), 2000);
    });
  });

  test('remove() ends the worker, gives the GPU context back and leaves no listener', async () => {
    const { page } = await open('remove.html');
    const cdp = await bed.page!.context.newCDPSession(page);
    // Which script added a listener: only the library's count (Playwright's input adds its own).
    const scripts = new Map<string, string>();
    cdp.on('Debugger.scriptParsed', (e: { scriptId: string; url: string }) => scripts.set(e.scriptId, e.url));
    await cdp.send('Debugger.enable');
    const listeners = async (expr: string): Promise<string[]> => {
      const { result } = (await cdp.send('Runtime.evaluate', { expression: expr })) as { result: { objectId?: string } };
      if (!result.objectId) throw new Error(`no object for ${expr}`);
      const r = (await cdp.send('DOMDebugger.getEventListeners', { objectId: result.objectId, depth: -1, pierce: true })) as { listeners: { type: string; scriptId: string }[] };
      return r.listeners.filter((l) => (scripts.get(l.scriptId) ?? '').includes('/lib/vario-map')).map((l) => l.type).sort();
    };
    const targets = ['window', 'document', "document.getElementById('map')"];
    const before = await Promise.all(targets.map(listeners));
    assert.deepEqual(before, [[], [], []]);
    await page.evaluate(() => (globalThis as unknown as { create(): void }).create());
    await idle(page);
    const during = await Promise.all(targets.map(listeners));
    assert.ok(during.flat().length >= 3, `the map listens: ${during.map((l) => l.join(' ')).join(' / ')}`);
    const onCanvas = await listeners('map.getCanvasContainer()');
    for (const type of ['wheel', 'pointerdown', 'keydown', 'dblclick']) assert.ok(onCanvas.includes(type), `${type} on the canvas container: ${onCanvas}`);
    assert.equal(page.workers().length, 1);
    const worker = page.workers()[0]!;
    const closed = new Promise<void>((resolve) => worker.on('close', () => resolve()));
    await page.evaluate(() => {
      const w = globalThis as unknown as { map: { getCanvas(): { getContext(t: string): unknown }; getCanvasContainer(): unknown }; gl: unknown; cc: unknown };
      w.gl = w.map.getCanvas().getContext('webgl2');
      w.cc = w.map.getCanvasContainer();
    });
    await wheelZooms(page);
    const cam = await camera(page);
    await page.evaluate(() => (globalThis as unknown as VarioWindow).map.remove());
    await closed; // the worker is terminated
    assert.equal(page.workers().length, 0);
    assert.equal(await page.evaluate(() => (globalThis as unknown as { gl: { isContextLost(): boolean } }).gl.isContextLost()), true, 'the GPU context is given back');
    const afterRemove = await Promise.all(targets.map(listeners));
    assert.deepEqual(afterRemove, before, 'every listener the map added is gone');
    assert.deepEqual(await listeners('window.cc'), [], 'and none is left on its (detached) canvas container');
    assert.equal(await page.evaluate(() => (globalThis as unknown as { document: { getElementById(id: string): { childElementCount: number } } }).document.getElementById('map').childElementCount), 0);
    // Input now does nothing, and nothing fails.
    await page.mouse.move(320, 240);
    await page.mouse.wheel(0, -100);
    await page.keyboard.press('+');
    await page.waitForTimeout(300);
    assert.deepEqual(await camera(page), cam);
  });
});
