// Cooperative gestures in a page that scrolls (the map inside an article, the built ES module),
// with real input: a plain wheel over the map scrolls the page and shows and announces the hint,
// Ctrl+wheel (⌘ + wheel on a Mac) zooms the map (axe-core finding no violation with the hint shown); on a touch
// screen one finger scrolls the page and two move the map.
import assert from 'node:assert/strict';
import { after, afterEach, before, describe, test } from 'node:test';
import type { CDPSession, Page } from 'playwright-core';
import { TOUCH_HINT, wheelHint } from '../client/src/ui/gesture-hint-text.js';
import { axeViolations } from './helpers/axe.js';
import { openMap, type MapPage } from './helpers/browser.js';
import { startLibSite, type LibSite } from './helpers/lib-site.js';
import { checkAndClose } from './helpers/test-bed.js';
import { camera, idle, resolution, settle } from './helpers/vario-page.js';

const ARTICLE = `<!doctype html>
<html lang="en">
<head>
  <meta charset="utf-8">
  <meta name="viewport" content="width=device-width, initial-scale=1">
  <title>An article with a map</title>
  <link rel="icon" href="data:,">
  <link rel="stylesheet" href="lib/vario-map.css">
  <style>body { margin: 0; } article { width: 640px; } h1 { margin: 0; height: 40px; } p { height: 560px; margin: 0; } #map { height: 360px; }</style>
</head>
<body>
  <main><article>
    <h1>An article with a map</h1>
    <p>Text before the map.</p>
    <div id="map"></div>
    <p>Text after the map.</p>
    <p>More text.</p>
  </article></main>
  <script type="module">
    import { VarioMap } from './lib/vario-map.js';
    window.map = new VarioMap({ container: 'map', source: 'cube/', cooperativeGestures: true });
  </script>
</body>
</html>
`;

type Point = [number, number];

/** The hint's text and whether it is shown (its opacity, after the fade in). */
interface PageHint {
  document: { querySelector(s: string): { textContent: string | null; getAttribute(n: string): string | null; classList: { contains(c: string): boolean } } | null };
  scrollY: number;
  scrollTo(x: number, y: number): void;
}

describe('cooperative gestures in a page that scrolls (bgt_otterlo_400m)', () => {
  let lib: LibSite;
  let mp: MapPage | null = null;

  before(async () => {
    lib = await startLibSite({ 'article.html': ARTICLE });
  });

  afterEach(async () => {
    await checkAndClose(mp);
    mp = null;
  });

  after(async () => {
    await lib?.close();
  });

  /** The article scrolled so the map is at 100..460 px of the 640 x 480 window. */
  async function open(touch: boolean, initScript?: string): Promise<Page> {
    mp = await openMap(lib.browser, lib.server.url, {}, { page: 'article.html', hasTouch: touch, ...(initScript ? { initScript } : {}) });
    const page = mp.page;
    await idle(page);
    await page.evaluate(() => (globalThis as unknown as PageHint).scrollTo(0, 500));
    return page;
  }

  const scrollY = (page: Page): Promise<number> => page.evaluate(() => (globalThis as unknown as PageHint).scrollY);

  function hint(page: Page): Promise<{ text: string; shown: boolean; live: string | null }> {
    return page.evaluate(() => {
      const el = (globalThis as unknown as PageHint).document.querySelector('.vario-map-gesture-hint');
      if (!el) throw new Error('no gesture hint in the map');
      return { text: el.textContent ?? '', shown: el.classList.contains('vario-map-gesture-hint-shown'), live: el.getAttribute('aria-live') };
    });
  }

  test('a plain wheel scrolls the page and shows the hint; Ctrl+wheel zooms the map', async () => {
    const page = await open(false);
    const start = await camera(page);
    assert.equal(await scrollY(page), 500);
    assert.deepEqual(await hint(page), { text: '', shown: false, live: 'polite' });
    await page.mouse.move(320, 280);
    await page.mouse.wheel(0, 100);
    await page.waitForFunction('window.scrollY > 500');
    assert.deepEqual(await hint(page), { text: wheelHint(false), shown: true, live: 'polite' });
    assert.deepEqual(await axeViolations(page), [], 'axe-core finds nothing wrong with the hint shown');
    await page.waitForTimeout(400); // a zoom would have started by now
    assert.deepEqual(await camera(page), start, 'the map did not move');

    const scrolled = await scrollY(page);
    await page.keyboard.down('Control');
    await page.mouse.wheel(0, -100);
    await page.keyboard.up('Control');
    await settle(page, `window.map.getScaleDenominator() < ${start.scale * 0.75}`);
    assert.ok(Math.abs((await camera(page)).scale - start.scale / 2) < 1e-6 * start.scale, 'one zoom step in');
    assert.equal(await scrollY(page), scrolled, 'the page did not scroll');
  });

  test('on a Mac the hint names ⌘, and ⌘ + wheel zooms', async () => {
    const page = await open(false, "Object.defineProperty(Navigator.prototype, 'platform', { get: () => 'MacIntel' });");
    const start = await camera(page);
    await page.mouse.move(320, 280);
    await page.mouse.wheel(0, 100);
    await page.waitForFunction('window.scrollY > 500');
    assert.equal((await hint(page)).text, wheelHint(true));
    assert.match(wheelHint(true), /^Use ⌘ \+ scroll/);
    await page.keyboard.down('Meta');
    await page.mouse.wheel(0, -100);
    await page.keyboard.up('Meta');
    await settle(page, `window.map.getScaleDenominator() < ${start.scale * 0.75}`);
  });

  test('one finger scrolls the page and shows the hint; two fingers move the map', async () => {
    const page = await open(true);
    const cdp: CDPSession = await mp!.context.newCDPSession(page);
    const start = await camera(page);
    /** Fingers from `from` by `dy` px in six moves, then lifted. */
    async function drag(from: Point[], dy: number): Promise<void> {
      const at = (t: number): { x: number; y: number; id: number }[] => from.map((p, id) => ({ x: p[0], y: p[1] + dy * t, id }));
      await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: at(0) });
      for (let i = 1; i <= 6; i++) await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: at(i / 6) });
      await page.waitForTimeout(300); // at rest before lifting: no fling, no glide
      await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
    }

    await drag([[320, 400]], -150);
    await page.waitForFunction('window.scrollY > 600');
    assert.deepEqual(await hint(page), { text: TOUCH_HINT, shown: true, live: 'polite' });
    await settle(page, 'true');
    assert.deepEqual(await camera(page), start, 'one finger did not move the map');

    await page.evaluate(() => (globalThis as unknown as PageHint).scrollTo(0, 500));
    await drag([[280, 300], [380, 300]], -100);
    await settle(page, 'true');
    assert.equal(await scrollY(page), 500, 'two fingers did not scroll the page');
    const end = await camera(page);
    const px = resolution(start.scale, (await page.evaluate(() => (globalThis as unknown as { map: { getMetadata(): { pixelSizeMm: number } } }).map.getMetadata().pixelSizeMm)));
    assert.ok(Math.abs(end.scale - start.scale) < 1e-9 * start.scale, 'the same scale');
    // The content follows the fingers up: the view's centre goes 100 px south.
    assert.ok(Math.abs((end.y - start.y) / px + 100) < 0.5 && Math.abs(end.x - start.x) < 1e-6, `the centre moved ${(start.y - end.y) / px} px south`);
  });
});
