// Markers and popups of the script-tag build in a plain page, with real input in Chromium: a
// marker stays on its place (within 1 px of project(lngLat)) in every animation frame of a wheel
// zoom, and a click opens a popup at the click with the class of the face there, which its
// close button and a click elsewhere on the map close.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import type { Page } from 'playwright-core';
import { openMap } from './helpers/browser.js';
import { LIB_PAGE_HEAD, useLibSite } from './helpers/lib-site.js';
import { hexColour, pixel, screenshot, type Rgba } from './helpers/map-page.js';
import { idle, settle, type VarioWindow } from './helpers/vario-page.js';

// The page docs/embedding.md shows for popups: the face's class at a click.
const PAGES: Record<string, string> = {
  'overlays.html': `${LIB_PAGE_HEAD}
  <script src="lib/vario-map.umd.js"></script>
  <script>
    var map = new vario.VarioMap({ container: 'map', source: 'cube/index.json' });
    map.on('click', function (e) {
      if (!e.feature) return;
      new vario.Popup().setLngLat(e.lngLat).setText(e.feature.classLabel).addTo(map);
    });
    window.map = map;
  </script>
</body>
</html>
`,
};

type XY = [number, number];

/** What the tests use in the page: the map and the library's global. */
interface OverlayWindow extends VarioWindow {
  vario: {
    Marker: new () => { setLngLat(ll: { lng: number; lat: number }): { addTo(m: unknown): PageMarker; setPopup(p: unknown): { addTo(m: unknown): PageMarker } } };
    Popup: new () => { setText(t: string): unknown };
  };
  marker: PageMarker;
  samples: { scale: number; tip: XY; projected: XY }[];
  sampling: boolean;
  clicks: { classLabel: string | null }[];
  requestAnimationFrame(fn: () => void): number;
  MessageChannel: new () => { port1: { onmessage: (() => void) | null }; port2: { postMessage(m: null): void } };
  document: { querySelectorAll(s: string): ArrayLike<PageElement> };
}
interface PageMarker {
  getElement(): PageElement & { focus(): void; getAttribute(n: string): string | null };
  getLngLat(): { lng: number; lat: number };
}
interface PageElement {
  getBoundingClientRect(): { left: number; top: number; width: number; height: number; bottom: number };
  querySelector(s: string): PageElement | null;
  textContent: string | null;
  className: string;
}

describe('Marker and Popup in the script-tag build (bgt_otterlo_400m)', () => {
  const bed = useLibSite(PAGES);

  async function open(): Promise<Page> {
    bed.page = await openMap(bed.site.browser, bed.site.server.url, {}, { page: 'overlays.html' });
    await idle(bed.page.page);
    return bed.page.page;
  }

  test('a marker stays within 1 px of project(lngLat) in every animation frame of a wheel zoom', async () => {
    const page = await open();
    await page.evaluate(async () => {
      const w = globalThis as unknown as OverlayWindow;
      w.map.jumpTo({ scaleDenominator: 3000 });
      await w.map.whenIdle();
      // A place away from the cursor, so that the zoom about the cursor moves it on screen.
      w.marker = new w.vario.Marker().setLngLat(w.map.unproject([180, 140])).addTo(w.map);
      w.samples = [];
      w.sampling = true;
      // Each animation frame, once all of its callbacks have run (in a task posted from it, so
      // what is read is what that frame painted): where the pin's tip is, and where project()
      // puts its place. A marker placed a frame late differs here in every moving frame.
      const channel = new w.MessageChannel();
      channel.port1.onmessage = (): void => {
        const r = w.marker.getElement().getBoundingClientRect();
        const ll = w.marker.getLngLat();
        w.samples.push({ scale: w.map.getScaleDenominator(), tip: [r.left + r.width / 2, r.bottom], projected: w.map.project([ll.lng, ll.lat]) });
      };
      const frame = (): void => {
        if (!w.sampling) return;
        channel.port2.postMessage(null);
        w.requestAnimationFrame(frame);
      };
      w.requestAnimationFrame(frame);
    });
    await page.mouse.move(420, 300);
    await page.mouse.wheel(0, -100); // a notch away from the user: zoom in
    await settle(page, 'window.map.getScaleDenominator() < 2000');
    await page.mouse.wheel(0, 100); // and out again
    await settle(page, 'window.map.getScaleDenominator() > 2500');
    const samples = await page.evaluate(() => {
      const w = globalThis as unknown as OverlayWindow;
      w.sampling = false;
      return w.samples;
    });
    const scales = new Set(samples.map((s) => s.scale));
    assert.ok(scales.size >= 10, `frames of the animation were sampled: ${scales.size} scales in ${samples.length} frames`);
    const worst = Math.max(...samples.map((s) => Math.hypot(s.tip[0] - s.projected[0], s.tip[1] - s.projected[1])));
    assert.ok(worst <= 1, `the pin's tip is at most 1 px from project(lngLat) in every frame: worst ${worst.toFixed(3)} px`);
    // And it moved: the zoom about the cursor carried it across the screen.
    const xs = samples.map((s) => s.tip[0]);
    assert.ok(Math.max(...xs) - Math.min(...xs) > 100, `the marker moved with the map: x from ${Math.min(...xs)} to ${Math.max(...xs)}`);
  });

  /** A point inside a face (7 x 7 px of one colour) whose colour is exactly one class's, not `not`'s, where `ok` says. */
  function pointInClass(img: Rgba, not: string | null, ok: (p: XY) => boolean = () => true): { at: XY; label: string } {
    const classes = bed.contents.meta.style.classes;
    const near = (a: number[], b: number[]): boolean => a.every((v, i) => Math.abs(v - b[i]!) <= 2);
    for (let j = 160; j < img.height - 60; j += 9) {
      for (let i = 80; i < img.width - 140; i += 9) {
        const c = pixel(img, i, j);
        let uniform = true;
        for (let dj = -3; dj <= 3 && uniform; dj++) for (let di = -3; di <= 3 && uniform; di++) uniform = near(pixel(img, i + di, j + dj), c);
        if (!uniform) continue;
        const matches = classes.filter((k) => near(hexColour(k.color), c));
        if (matches.length === 1 && matches[0]!.label !== not && ok([i, j])) return { at: [i, j], label: matches[0]!.label };
      }
    }
    throw new Error('no point inside a face of one class colour on screen');
  }

  async function popups(page: Page): Promise<{ text: string; tip: XY; anchor: string }[]> {
    return page.evaluate(() => {
      const w = globalThis as unknown as OverlayWindow;
      return Array.from(w.document.querySelectorAll('.vario-map-popup')).map((el) => {
        const tip = el.querySelector('.vario-map-popup-tip')!.getBoundingClientRect();
        const content = el.querySelector('.vario-map-popup-content')!;
        const close = content.querySelector('.vario-map-popup-close-button');
        const text = (content.textContent ?? '').slice(0, (content.textContent ?? '').length - (close?.textContent ?? '').length);
        return { text, tip: [tip.left + tip.width / 2, tip.bottom] as XY, anchor: el.className };
      });
    });
  }

  test("a click opens a popup at the click with the face's class; its close button and a click elsewhere close it", async () => {
    const page = await open();
    await page.evaluate(async () => {
      const w = globalThis as unknown as OverlayWindow;
      w.map.jumpTo({ scaleDenominator: 1200 });
      await w.map.whenIdle();
      w.clicks = [];
      w.map.on('click', (e) => w.clicks.push({ classLabel: (e as { feature: { classLabel: string } | null }).feature?.classLabel ?? null }));
    });
    // The class is read off the screen: the colour under the click is that class's in the style.
    const img = await screenshot(page);
    const first = pointInClass(img, null);
    await page.mouse.click(...first.at);
    await page.waitForFunction(() => (globalThis as unknown as OverlayWindow).document.querySelectorAll('.vario-map-popup').length === 1);
    let shown = await popups(page);
    assert.equal(shown[0]!.text, first.label, `the popup names the class of the colour clicked (${first.label})`);
    assert.deepEqual(await page.evaluate(() => (globalThis as unknown as OverlayWindow).clicks), [{ classLabel: first.label }], "the click event's feature has that class");
    assert.match(shown[0]!.anchor, /vario-map-popup-anchor-bottom\b/, 'above the place, with room there');
    const off = Math.hypot(shown[0]!.tip[0] - first.at[0], shown[0]!.tip[1] - first.at[1]);
    assert.ok(off <= 1, `the tip points at the click: ${shown[0]!.tip.join(', ')} for ${first.at.join(', ')}`);

    // Its close button closes it (a real click, which the map does not take as its own).
    await page.click('.vario-map-popup-close-button');
    assert.equal((await popups(page)).length, 0, 'closed by its button');
    assert.equal(await page.evaluate(() => (globalThis as unknown as OverlayWindow).clicks.length), 1, 'the close button is no click on the map');

    // Open again, then click a face of another class: the first closes, the new one names it.
    await page.mouse.click(...first.at);
    await page.waitForFunction(() => (globalThis as unknown as OverlayWindow).document.querySelectorAll('.vario-map-popup').length === 1);
    // Away from the open popup (above the first point), on the picture without it.
    const second = pointInClass(img, first.label, (p) => Math.abs(p[0] - first.at[0]) > 160 || p[1] > first.at[1] + 20);
    await page.mouse.click(...second.at);
    await page.waitForFunction((label) => {
      const w = globalThis as unknown as OverlayWindow;
      const all = w.document.querySelectorAll('.vario-map-popup-content');
      return all.length === 1 && (all[0]!.textContent ?? '').startsWith(label);
    }, second.label);
    shown = await popups(page);
    assert.equal(shown.length, 1, 'one popup: the click on the map closed the first');
    assert.equal(shown[0]!.text, second.label);
  });

  test("a marker's popup opens and closes by a click on the marker (not the map's) and by Enter on it", async () => {
    const page = await open();
    const pin = await page.evaluate(() => {
      const w = globalThis as unknown as OverlayWindow;
      w.clicks = [];
      w.map.on('click', () => w.clicks.push({ classLabel: null }));
      w.marker = new w.vario.Marker().setLngLat(w.map.unproject([320, 240])).setPopup(new w.vario.Popup().setText('Here')).addTo(w.map);
      const r = w.marker.getElement().getBoundingClientRect();
      return [r.left + r.width / 2, r.top + r.height / 3] as XY;
    });
    const state = (): Promise<{ texts: string[]; expanded: string | null; mapClicks: number }> =>
      page.evaluate(() => {
        const w = globalThis as unknown as OverlayWindow;
        const texts = Array.from(w.document.querySelectorAll('.vario-map-popup-content')).map((c) => c.textContent ?? '');
        return { texts, expanded: w.marker.getElement().getAttribute('aria-expanded'), mapClicks: w.clicks.length };
      });
    await page.mouse.click(...pin);
    assert.deepEqual(await state(), { texts: ['Here×'], expanded: 'true', mapClicks: 0 }, 'a click on the pin opens its popup, and is not a click on the map');
    const tip = (await popups(page))[0]!.tip;
    assert.ok(tip[1] < pin[1] - 10 && Math.abs(tip[0] - 320) <= 1, `the popup is above the pin: tip at ${tip.join(', ')}`);
    await page.mouse.click(...pin);
    assert.deepEqual(await state(), { texts: [], expanded: 'false', mapClicks: 0 }, 'a second click closes it');
    await page.evaluate(() => (globalThis as unknown as OverlayWindow).marker.getElement().focus());
    await page.keyboard.press('Enter');
    assert.deepEqual((await state()).texts, ['Here×'], 'Enter on the focused marker opens it');
    // The map's click events come after a face lookup: one on the map now is heard after any
    // the marker's clicks had caused, and it is the only one.
    await page.mouse.click(100, 400);
    await page.waitForFunction(() => (globalThis as unknown as OverlayWindow).clicks.length > 0);
    const after = await state();
    assert.equal(after.mapClicks, 1, 'the map heard the click on it, and none of those on the marker');
    assert.equal(after.expanded, 'false', "the click on the map closed the marker's popup");
  });
});
