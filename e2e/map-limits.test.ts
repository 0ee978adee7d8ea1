// The view's limits through the demo page (the public API) with real input: with maxBounds
// every frame of a mouse drag (and its glide), a wheel zoom out and a flight stays inside the
// box, and the view stops at its edge, also when the map grows; setMinScale and setMaxScale bring the view within them
// at once and hold the wheel there; by default the map zooms out to four times the scale at which it
// opened showing the whole extent (and in to a quarter of the base scale), also when its container was resized
// just before the cube's metadata came.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import type { Page } from 'playwright-core';
import { useTestBed } from './helpers/test-bed.js';
import { openMap } from './helpers/browser.js';
import { camera, idle, openDemo, record, recorded, resolution, settle, type VarioApi, type VarioWindow } from './helpers/vario-page.js';

type Bbox = [number, number, number, number];

/** The limit methods, beside what the other tests use. */
interface LimitsApi extends VarioApi {
  setMaxBounds(b: Bbox | null): unknown;
  setMaxBoundsProjected(b: Bbox | null): unknown;
  getMaxBoundsProjected(): Bbox | null;
  setMinScale(s: number | null): unknown;
  getMinScale(): number;
  setMaxScale(s: number | null): unknown;
  getMaxScale(): number;
}

interface LimitsWindow {
  map: LimitsApi;
}

/** How far (ground units) `inner` reaches outside `outer` at most; 0 when inside. */
function overreach(inner: Bbox, outer: Bbox): number {
  return Math.max(0, outer[0] - inner[0], outer[1] - inner[1], inner[2] - outer[2], inner[3] - outer[3]);
}

describe('map limits (bgt_otterlo_400m)', () => {
  const bed = useTestBed(['--no-precompress']);
  const px = (scale: number): number => resolution(scale, bed.contents.meta.pixelSizeMm);

  /**
   * Checks that the map, opened with no view, fits the whole extent to its container as it is,
   * and zooms out by default to four times that scale; returns the container's width and that limit.
   */
  async function openedAtExtentFit(page: Page): Promise<{ width: number; maxScale: number }> {
    const opened = await page.evaluate(() => {
      const m = (globalThis as unknown as LimitsWindow).map;
      const r = (m.getContainer() as { getBoundingClientRect(): { width: number; height: number } }).getBoundingClientRect();
      return { scale: m.getScaleDenominator(), maxScale: m.getMaxScale(), width: r.width, height: r.height };
    });
    const [ex0, ey0, ex1, ey1] = bed.contents.meta.extent;
    const fit = (Math.max((ex1 - ex0) / opened.width, (ey1 - ey0) / opened.height) * 1000) / bed.contents.meta.pixelSizeMm;
    assert.ok(Math.abs(opened.scale / fit - 1) < 1e-9, `opened at 1:${opened.scale}, the extent fits ${opened.width} x ${opened.height} px at 1:${fit}`);
    assert.ok(Math.abs(opened.maxScale / (4 * fit) - 1) < 1e-9, `zooms out to 1:${opened.maxScale}, four times the extent's fit 1:${fit}`);
    return { width: opened.width, maxScale: opened.maxScale };
  }

  /** The demo at 1:3000 with maxBounds 1200 x 900 CSS px of that scale around the centre. */
  async function boxed(): Promise<{ page: Page; box: Bbox }> {
    bed.page = await openDemo(bed.browser, bed.server.url);
    const page = bed.page.page;
    await page.evaluate(() => (globalThis as unknown as VarioWindow).map.jumpTo({ scaleDenominator: 3000 }));
    const c = await camera(page);
    const r = px(3000);
    const box: Bbox = [c.x - 600 * r, c.y - 450 * r, c.x + 600 * r, c.y + 450 * r];
    await page.evaluate((b) => (globalThis as unknown as LimitsWindow).map.setMaxBoundsProjected(b), box);
    assert.deepEqual(await page.evaluate(() => (globalThis as unknown as LimitsWindow).map.getMaxBoundsProjected()), box);
    await record(page);
    return { page, box };
  }

  /** Every recorded move's view inside the box (to a micrometre). */
  async function allInside(page: Page, box: Bbox): Promise<number> {
    const moves = (await recorded(page)).filter((r) => r.type === 'move');
    for (const m of moves) assert.ok(overreach(m.bounds, box) < 1e-6, `a frame reached ${overreach(m.bounds, box)} outside: ${m.bounds} vs ${box}`);
    return moves.length;
  }

  test('a drag and its glide stop at the edge of maxBounds', async () => {
    const { page, box } = await boxed();
    // 600 px to the right, released moving: the view would go 600 px and glide on west; the
    // box leaves 280 px on either side of the 640 px view.
    await page.mouse.move(20, 240);
    await page.mouse.down();
    for (let i = 1; i <= 12; i++) await page.mouse.move(20 + 50 * i, 240);
    await page.mouse.up();
    await settle(page, 'true');
    const bounds = await page.evaluate(() => (globalThis as unknown as LimitsWindow).map.getBoundsProjected());
    assert.ok(Math.abs(bounds[0] - box[0]) < 1e-6, `the west edges meet: ${bounds[0]} vs ${box[0]}`);
    assert.ok((await allInside(page, box)) >= 5, 'the drag moved the map');
    // 160 px wider, about the centre: the view would reach 80 px past the west edge.
    await page.setViewportSize({ width: 800, height: 480 });
    await page.waitForFunction(`Math.abs(window.map.getBoundsProjected()[2] - window.map.getBoundsProjected()[0] - ${800 * px(3000)}) < 1e-6`);
    const wider = await page.evaluate(() => (globalThis as unknown as LimitsWindow).map.getBoundsProjected());
    assert.ok(Math.abs(wider[0] - box[0]) < 1e-6, `after a resize the west edges still meet: ${wider[0]} vs ${box[0]}`);
  });

  test('a wheel zoom out stops where the box fills the view; a flight away stays inside', async () => {
    const { page, box } = await boxed();
    await page.mouse.move(420, 330); // off the info box (top left) and the scale bar
    for (let i = 0; i < 4; i++) await page.mouse.wheel(0, 100);
    await settle(page, 'window.map.getScaleDenominator() > 5000');
    // 1200 x 900 px of 1:3000 fill 640 x 480 px at 1:3000 x min(1200/640, 900/480) = 1:5625.
    const end = await camera(page);
    assert.ok(Math.abs(end.scale - 5625) < 1e-6, `scale 1:${end.scale}`);
    await page.evaluate((b) => (globalThis as unknown as LimitsWindow).map.flyTo({ centerProjected: [b[2] + 5000, b[3] + 5000], scaleDenominator: 3000, duration: 400 }), box);
    await settle(page, 'true');
    const bounds = await page.evaluate(() => (globalThis as unknown as LimitsWindow).map.getBoundsProjected());
    assert.ok(Math.abs(bounds[2] - box[2]) < 1e-6 && Math.abs(bounds[3] - box[3]) < 1e-6, `in the north-east corner: ${bounds} vs ${box}`);
    await allInside(page, box);
    await page.evaluate(() => (globalThis as unknown as LimitsWindow).map.setMaxBounds(null));
    await page.evaluate(() => (globalThis as unknown as LimitsWindow).map.jumpTo({ centerProjected: [0, 0] }));
    assert.deepEqual((await camera(page)).x, 0, 'without maxBounds the view goes anywhere');
  });

  test('a container resized before the cube\'s metadata arrive, with its ResizeObserver not yet run, opens fitting its new size', async () => {
    // Every ResizeObserver callback of the page is held back until the test lets it run.
    const initScript = `(() => {
      const held = [];
      window.releaseResizes = () => { for (const f of held.splice(0)) f(); };
      const Native = window.ResizeObserver;
      window.ResizeObserver = class {
        constructor(cb) { this.inner = new Native((...args) => held.push(() => cb(...args))); }
        observe(t, o) { this.inner.observe(t, o); }
        unobserve(t) { this.inner.unobserve(t); }
        disconnect() { this.inner.disconnect(); }
      };
    })();`;
    let release = (): void => undefined;
    const gate = new Promise<void>((r) => (release = r));
    bed.page = await openMap(bed.browser, bed.server.url, { source: 'cube/', supersampling: 1, sw: 0 }, {
      page: 'demo.html',
      initScript,
      onPage: (p) => void p.route('**/cube/index.json', async (route) => {
        await gate;
        await route.continue();
      }),
    });
    const page = bed.page.page;
    // 640 px wide when the map was made, 400 px when its metadata come.
    await page.evaluate(() => {
      (globalThis as unknown as { document: { getElementById(id: string): { style: { right: string } } } }).document.getElementById('map').style.right = '240px';
    });
    release();
    await idle(page);
    assert.equal((await openedAtExtentFit(page)).width, 400);
    await page.evaluate(() => (globalThis as unknown as { releaseResizes(): void }).releaseResizes());
  });

  test('setMinScale and setMaxScale bring the view within them at once and hold the wheel there', async () => {
    bed.page = await openDemo(bed.browser, bed.server.url);
    const page = bed.page.page;
    const opened = await openedAtExtentFit(page);
    await page.evaluate(() => (globalThis as unknown as VarioWindow).map.jumpTo({ scaleDenominator: 3000 }));
    await record(page);
    const scale = await page.evaluate(() => {
      (globalThis as unknown as LimitsWindow).map.setMinScale(6000);
      return (globalThis as unknown as LimitsWindow).map.getScaleDenominator();
    });
    assert.equal(scale, 6000, 'clamped when the call returns');
    assert.equal(await page.evaluate(() => (globalThis as unknown as LimitsWindow).map.getMinScale()), 6000);
    assert.ok((await recorded(page)).some((r) => r.type === 'moveend' && r.scale === 6000), 'a moveend at the new scale');
    await page.mouse.move(320, 240);
    await page.mouse.wheel(0, -100);
    await page.waitForTimeout(400);
    await settle(page, 'true');
    assert.equal((await camera(page)).scale, 6000, 'the wheel does not zoom in past it');

    await page.evaluate(() => (globalThis as unknown as LimitsWindow).map.setMaxScale(9000));
    for (let i = 0; i < 3; i++) await page.mouse.wheel(0, 100);
    await settle(page, `window.map.getScaleDenominator() > 8000`);
    assert.equal((await camera(page)).scale, 9000);

    const refused = await page.evaluate(() => {
      try {
        (globalThis as unknown as LimitsWindow).map.setMinScale(20000);
        return '';
      } catch (e) {
        return (e as Error).message;
      }
    });
    assert.match(refused, /maxScale \(9000\) must be at least minScale \(20000\)/);
    assert.deepEqual(await page.evaluate(() => [(globalThis as unknown as LimitsWindow).map.getMinScale(), (globalThis as unknown as LimitsWindow).map.getMaxScale(), (globalThis as unknown as LimitsWindow).map.getScaleDenominator()]), [6000, 9000, 9000], 'nothing changed');
    // null: the cube's defaults again (a quarter of its base scale; four times the extent's fit).
    await page.evaluate(() => (globalThis as unknown as LimitsWindow).map.setMinScale(null));
    assert.equal(await page.evaluate(() => (globalThis as unknown as LimitsWindow).map.getMinScale()), bed.contents.meta.baseScale / 4);
    await page.evaluate(() => (globalThis as unknown as LimitsWindow).map.setMaxScale(null));
    assert.equal(await page.evaluate(() => (globalThis as unknown as LimitsWindow).map.getMaxScale()), opened.maxScale);
  });
});
