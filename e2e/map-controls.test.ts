// The map's controls and behaviour for keyboard, touch and screen-reader users, through the
// demo page (the public API) with real input: the focus ring shows over the canvas.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import type { Page } from 'playwright-core';
import { hexColour, pixel, screenshot } from './helpers/map-page.js';
import { useTestBed } from './helpers/test-bed.js';
import { openDemo, type PageWindow } from './helpers/vario-page.js';

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
});
