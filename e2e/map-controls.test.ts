// The map's controls and behaviour for keyboard, touch and screen-reader users, through the
// demo page (the public API) with real input: the focus ring shows over the canvas, and on a
// touch screen every control button is at least 44 x 44 CSS px, and the scale is announced to
// screen readers once a movement ends; the fullscreen button puts the map on the whole screen.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import type { Page } from 'playwright-core';
import { spokenScale } from '../client/src/geometry/scale-bar-length.js';
import { hexColour, pixel, screenshot } from './helpers/map-page.js';
import { checkAndClose, useTestBed } from './helpers/test-bed.js';
import { camera, openDemo, record, recorded, settle, type PageWindow, type VarioWindow } from './helpers/vario-page.js';

/** A change of the scale's live region: when, its text, and whether the map was moving. */
interface Announcement {
  t: number;
  text: string;
  moving: boolean;
}
interface AnnouncingWindow extends VarioWindow {
  announced: Announcement[];
  document: { querySelector(selector: string): object | null };
  MutationObserver: new (fn: () => void) => { observe(target: object, options: object): void };
}

/** Starts recording every change of the scale bar's live region into window.announced. */
function recordAnnouncements(page: Page): Promise<void> {
  return page.evaluate(() => {
    const w = globalThis as unknown as AnnouncingWindow;
    const region = w.document.querySelector('.vario-map-scale [aria-live="polite"]') as { textContent: string | null } | null;
    if (!region) throw new Error('no polite live region in the scale bar');
    w.announced = [];
    new w.MutationObserver(() => {
      w.announced.push({ t: performance.now(), text: region.textContent ?? '', moving: w.map.isMoving() });
    }).observe(region, { childList: true, characterData: true, subtree: true });
  });
}

/** Whether the map's container is the page's fullscreen element, and the button's label. */
function fullscreenState(page: Page): Promise<{ fullscreen: boolean; label: string | null }> {
  return page.evaluate(() => {
    const w = globalThis as unknown as VarioWindow & { document: { fullscreenElement: object | null; querySelector(s: string): { getAttribute(n: string): string | null } | null } };
    return {
      fullscreen: w.document.fullscreenElement === w.map.getContainer(),
      label: w.document.querySelector('.vario-map-fullscreen-toggle')?.getAttribute('aria-label') ?? null,
    };
  });
}

/** What the size test reads in the page (the Node build has no DOM types). */
interface SizedButton {
  getAttribute(name: string): string | null;
  closest(selector: string): object | null;
  getBoundingClientRect(): { width: number; height: number };
}
interface SizingWindow {
  document: { querySelectorAll(selector: string): Iterable<SizedButton> };
  matchMedia(query: string): { matches: boolean };
}

/** The label and CSS size of every shown button of the library's controls. */
function controlButtons(page: Page): Promise<{ coarse: boolean; buttons: { label: string; width: number; height: number }[] }> {
  return page.evaluate(() => {
    const w = globalThis as unknown as SizingWindow;
    const buttons = [...w.document.querySelectorAll('.vario-map-control-container button')]
      // The demo's info box is the page's own, not a control of the library.
      .filter((b) => b.closest('.demo-info') === null)
      .map((b) => {
        const r = b.getBoundingClientRect(); // a DOMRect's sizes are getters: not spreadable
        return { label: b.getAttribute('aria-label') ?? '', width: r.width, height: r.height };
      })
      .filter((b) => b.width > 0);
    return { coarse: w.matchMedia('(pointer: coarse)').matches, buttons };
  });
}

describe('map controls (bgt_otterlo_400m)', () => {
  const bed = useTestBed(['--no-precompress']);

  const mapHasFocus = (page: Page): Promise<boolean> =>
    page.evaluate(() => (globalThis as unknown as PageWindow).document.activeElement?.classList.contains('vario-map-canvas-container') === true);

  test('Tab to the map shows a focus ring over the canvas', async () => {
    bed.page = await openDemo(bed.browser, bed.server.url);
    const page = bed.page.page;
    const unfocused = await screenshot(page);
    for (let i = 0; i < 12 && !(await mapHasFocus(page)); i++) await page.keyboard.press('Tab');
    assert.ok(await mapHasFocus(page), 'Tab reaches the map');
    const focused = await screenshot(page);
    // The map fills the 640 x 480 page; the middles of its left and right edges are clear of
    // controls, so there the ring is all that changed.
    const ring = hexColour('#1a73e8');
    for (const [i, j] of [[1, 240], [638, 240]] as const) {
      const before = pixel(unfocused, i, j);
      const after = pixel(focused, i, j);
      assert.deepEqual(after, ring, `the ring at (${i}, ${j}): ${after}`);
      assert.notDeepEqual(before, ring, `no ring at (${i}, ${j}) without focus`);
    }
  });

  test('a click focuses the map without a ring', async () => {
    bed.page = await openDemo(bed.browser, bed.server.url);
    const page = bed.page.page;
    const unfocused = await screenshot(page);
    await page.mouse.click(320, 240);
    assert.ok(await mapHasFocus(page), 'the click focuses the map (its keys work)');
    const clicked = await screenshot(page);
    for (const [i, j] of [[1, 240], [638, 240]] as const) assert.deepEqual(pixel(clicked, i, j), pixel(unfocused, i, j), `no ring at (${i}, ${j})`);
  });

  test('on a touch screen every control button is at least 44 x 44 px; with a mouse, 30 x 30', async () => {
    bed.page = await openDemo(bed.browser, bed.server.url, {}, { hasTouch: true, isMobile: true });
    let page = bed.page.page;
    await page.tap('.vario-map-settings-toggle'); // its panel's buttons too
    const touch = await controlButtons(page);
    assert.ok(touch.coarse, 'a coarse pointer');
    for (const name of ['Zoom in', 'Zoom out', 'Enter fullscreen', 'Settings', 'Clear the log']) assert.ok(touch.buttons.some((b) => b.label === name), `${name} measured`);
    for (const b of touch.buttons) assert.ok(b.width >= 44 && b.height >= 44, `${b.label}: ${b.width} x ${b.height}`);
    await checkAndClose(bed.page);

    bed.page = await openDemo(bed.browser, bed.server.url);
    page = bed.page.page;
    const mouse = await controlButtons(page);
    assert.ok(!mouse.coarse, 'a fine pointer');
    for (const name of ['Zoom in', 'Zoom out', 'Settings']) {
      const b = mouse.buttons.find((x) => x.label === name);
      assert.deepEqual(b && [b.width, b.height], [30, 30], `${name} keeps its size`);
    }
  });

  test('the scale is announced once when a wheel zoom ends, not during it', async () => {
    bed.page = await openDemo(bed.browser, bed.server.url);
    const page = bed.page.page;
    const start = await camera(page);
    await record(page);
    await recordAnnouncements(page);
    await page.mouse.move(320, 240);
    await page.mouse.wheel(0, 100); // one notch: zoom out a step
    await settle(page, `window.map.getScaleDenominator() > ${start.scale * 1.5}`);
    await page.waitForTimeout(300); // nothing more follows
    const end = await camera(page);
    const announced = await page.evaluate(() => (globalThis as unknown as AnnouncingWindow).announced);
    const rec = await recorded(page);
    const moves = rec.filter((r) => r.type === 'move');
    const moveEnd = rec.find((r) => r.type === 'moveend');
    assert.ok(moves.length >= 5, `an animated zoom: ${moves.length} moves`);
    assert.ok(moveEnd, 'the movement ended');
    assert.equal(announced.length, 1, `announced once: ${JSON.stringify(announced)}`);
    const [a] = announced;
    assert.ok(a && !a.moving && a.t >= moveEnd.t, 'after the movement ended');
    assert.equal(a.text, spokenScale(end.scale));
  });

  test('the fullscreen button puts the map container on the whole screen and takes it back', async () => {
    bed.page = await openDemo(bed.browser, bed.server.url);
    const page = bed.page.page;
    assert.deepEqual(await fullscreenState(page), { fullscreen: false, label: 'Enter fullscreen' });
    await page.click('.vario-map-fullscreen-toggle');
    // The element changes first; fullscreenchange (and so the label) follows a frame later.
    await page.waitForSelector('.vario-map-fullscreen-toggle[aria-label="Exit fullscreen"]');
    assert.deepEqual(await fullscreenState(page), { fullscreen: true, label: 'Exit fullscreen' });
    await page.click('.vario-map-fullscreen-toggle');
    await page.waitForSelector('.vario-map-fullscreen-toggle[aria-label="Enter fullscreen"]');
    assert.deepEqual(await fullscreenState(page), { fullscreen: false, label: 'Enter fullscreen' });
  });
});
