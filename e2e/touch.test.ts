// Touch input in a Chromium context with a touch screen, through the demo page (the public
// API): a two-finger pinch zooms about the fingers' midpoint, two fingers moved together pan,
// one finger drags, and a double tap zooms in a step about the tap.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import type { CDPSession, Page } from 'playwright-core';
import { useTestBed } from './helpers/test-bed.js';
import { apart, camera, groundAt, openDemo, resolution, settle, type VarioWindow } from './helpers/vario-page.js';

type Point = [number, number];

describe('touch (bgt_otterlo_400m)', () => {
  const bed = useTestBed(['--no-precompress']);

  const px = (scale: number): number => resolution(scale, bed.contents.meta.pixelSizeMm);

  async function open(scale: number): Promise<{ page: Page; cdp: CDPSession }> {
    bed.page = await openDemo(bed.browser, bed.server.url, {}, { hasTouch: true });
    const page = bed.page.page;
    await page.evaluate((s) => (globalThis as unknown as VarioWindow).map.jumpTo({ scaleDenominator: s }), scale);
    await page.evaluate(() => (globalThis as unknown as VarioWindow).map.whenIdle());
    return { page, cdp: await bed.page.context.newCDPSession(page) };
  }

  const pxApart = (a: Point, b: Point, scale: number): number => apart(a, b, scale, bed.contents.meta.pixelSizeMm);

  /** Two fingers from (a0, b0) to (a1, b1) in `steps` moves, then lifted. */
  async function twoFingers(cdp: CDPSession, a0: Point, b0: Point, a1: Point, b1: Point, steps = 6): Promise<void> {
    const at = (p: Point, q: Point, t: number): { x: number; y: number } => ({ x: p[0] + (q[0] - p[0]) * t, y: p[1] + (q[1] - p[1]) * t });
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: [{ ...at(a0, a1, 0), id: 0 }, { ...at(b0, b1, 0), id: 1 }] });
    for (let i = 1; i <= steps; i++) {
      await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: [{ ...at(a0, a1, i / steps), id: 0 }, { ...at(b0, b1, i / steps), id: 1 }] });
    }
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
  }

  test('a pinch zooms about the midpoint of the fingers', async () => {
    const { page, cdp } = await open(3000);
    const start = await camera(page);
    const mid: Point = [380, 300];
    const ground = await groundAt(page, mid);
    // The fingers spread from 100 px apart to 200: twice the detail.
    await twoFingers(cdp, [330, 300], [430, 300], [280, 300], [480, 300]);
    await settle(page, `window.map.getScaleDenominator() < ${start.scale * 0.75}`);
    const end = await camera(page);
    assert.ok(Math.abs(end.scale - start.scale / 2) < 1e-6 * start.scale, `scale ${start.scale} -> ${end.scale}`);
    assert.ok(pxApart(await groundAt(page, mid), ground, end.scale) <= 1, `the ground under the midpoint moved ${pxApart(await groundAt(page, mid), ground, end.scale).toFixed(3)} px`);
  });

  test('two fingers moved together pan; one finger drags', async () => {
    const { page, cdp } = await open(3000);
    const start = await camera(page);
    await twoFingers(cdp, [300, 300], [400, 300], [300, 200], [400, 200]);
    await settle(page, 'true');
    let end = await camera(page);
    assert.ok(Math.abs(end.scale - start.scale) < 1e-9 * start.scale, 'the same scale');
    assert.ok(Math.abs((end.y - start.y) / px(start.scale) + 100) < 0.5 && Math.abs(end.x - start.x) < 1e-6, `moved ${(end.y - start.y) / px(start.scale)} px`);
    const grabbed = await groundAt(page, [350, 350]);
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: [{ x: 350, y: 350, id: 0 }] });
    for (let i = 1; i <= 5; i++) await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: [{ x: 350 + 10 * i, y: 350 - 6 * i, id: 0 }] });
    await page.waitForTimeout(300); // at rest before lifting: no glide
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
    await settle(page, 'true');
    end = await camera(page);
    assert.ok(pxApart(await groundAt(page, [400, 320]), grabbed, end.scale) <= 1, 'the ground point stays under the finger');
  });

  test('a double tap zooms in one step about the tap, once', async () => {
    const { page } = await open(3000);
    const start = await camera(page);
    const p: Point = [420, 320];
    const ground = await groundAt(page, p);
    await page.touchscreen.tap(...p);
    await page.touchscreen.tap(...p);
    await settle(page, `window.map.getScaleDenominator() < ${start.scale * 0.75}`);
    await page.waitForTimeout(500); // nothing more follows (no second zoom from a dblclick)
    await settle(page, 'true');
    const end = await camera(page);
    assert.ok(Math.abs(end.scale - start.scale / 2) < 1e-6 * start.scale, `scale ${start.scale} -> ${end.scale}`);
    assert.ok(pxApart(await groundAt(page, p), ground, end.scale) <= 1);
  });
});
