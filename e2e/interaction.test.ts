// Smooth interaction with real input in Chromium, through the demo page (the public API) on a
// real cube of bgt_otterlo_400m: wheel zoom about the cursor in many small content steps, drag
// with inertia, an animation interrupted by the wheel, double click, keyboard, box zoom and
// reduced motion. Outcomes only (where the map ends up, what it showed), never timings.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import type { Page } from 'playwright-core';
import { scaleAtZ } from '../format/scale.js';
import { useTestBed } from './helpers/test-bed.js';
import { apart, camera, groundAt, openDemo, record, recorded, resolution, settle, type Camera, type PageWindow, type VarioWindow } from './helpers/vario-page.js';

const W = 640, H = 480;

describe('interaction (bgt_otterlo_400m)', () => {
  const bed = useTestBed(['--no-precompress']);

  const info = () => ({ baseScale: bed.contents.meta.baseScale, baseFaces: bed.contents.meta.baseFaces, scaleTable: bed.contents.meta.scaleTable, zMax: bed.contents.meta.zMax });
  const px = (scale: number): number => resolution(scale, bed.contents.meta.pixelSizeMm);
  /** A scale in the middle of the cube's range in log scale: zooming a step either way changes the content. */
  const middleScale = (): number => Math.sqrt(scaleAtZ(info(), 0) * scaleAtZ(info(), bed.contents.meta.zMax));

  async function open(params: Record<string, string | number> = {}, opts = {}): Promise<Page> {
    bed.page = await openDemo(bed.browser, bed.server.url, params, opts);
    return bed.page.page;
  }

  async function startAt(page: Page, cam: { centerProjected?: [number, number]; scaleDenominator: number }): Promise<Camera> {
    await page.evaluate((c) => (globalThis as unknown as VarioWindow).map.jumpTo(c), cam);
    await page.evaluate(() => (globalThis as unknown as VarioWindow).map.whenIdle());
    return camera(page);
  }

  const pxApart = (a: [number, number], b: [number, number], scale: number): number => apart(a, b, scale, bed.contents.meta.pixelSizeMm);

  test('the canvas container is focusable and named; the controls are labelled buttons', async () => {
    const page = await open();
    const a11y = await page.evaluate(() => {
      const cc = (globalThis as unknown as VarioWindow).map.getCanvasContainer();
      const buttons = [...(globalThis as unknown as PageWindow).document.querySelectorAll('.vario-map-ctrl button')].map((b) => b.getAttribute('aria-label') ?? '');
      return { tabIndex: cc.tabIndex, label: cc.getAttribute('aria-label'), buttons };
    });
    assert.equal(a11y.tabIndex, 0);
    assert.ok(a11y.label && a11y.label.length > 0, 'aria-label');
    for (const name of ['Zoom in', 'Zoom out', 'Settings']) assert.ok(a11y.buttons.includes(name), `a button labelled ${name}: ${a11y.buttons}`);
    // Tab reaches the map, and its keys work from there.
    await page.keyboard.press('Tab');
    for (let i = 0; i < 12; i++) {
      if (await page.evaluate(() => (globalThis as unknown as PageWindow).document.activeElement?.classList.contains('vario-map-canvas-container'))) break;
      await page.keyboard.press('Tab');
    }
    assert.equal(await page.evaluate(() => (globalThis as unknown as PageWindow).document.activeElement?.classList.contains('vario-map-canvas-container')), true, 'Tab reaches the map');
    // The zoom button, operated from the keyboard.
    const before = await camera(page);
    await page.focus('.vario-map-zoom-in');
    await page.keyboard.press('Enter');
    await settle(page, `window.map.getScaleDenominator() < ${before.scale * 0.75}`);
    assert.ok(Math.abs((await camera(page)).scale - before.scale / 2) < 1e-6 * before.scale);
  });

  test('a wheel click zooms by the step factor about the cursor, in at least 10 distinct slices', async () => {
    const page = await open();
    const start = await startAt(page, { scaleDenominator: middleScale() });
    const cursor: [number, number] = [420, 330];
    const ground = await groundAt(page, cursor);
    await record(page);
    await page.mouse.move(...cursor);
    await page.mouse.wheel(0, 100); // one notch toward the user: zoom out
    await settle(page, `window.map.getScaleDenominator() > ${start.scale * 1.5}`);
    const end = await camera(page);
    assert.ok(Math.abs(end.scale / start.scale - 2) < 1e-9, `scale ${start.scale} -> ${end.scale}`);
    const after = await groundAt(page, cursor);
    assert.ok(pxApart(after, ground, end.scale) <= 1, `the ground point under the cursor moved ${pxApart(after, ground, end.scale).toFixed(3)} px`);
    // Every frame of the zoom showed the same point under the cursor too.
    const rec = await recorded(page);
    const frames = rec.filter((r) => r.type === 'render');
    const slices = new Set(frames.map((r) => r.z.toFixed(6)));
    assert.ok(slices.size >= 10, `${slices.size} distinct slices drawn during one wheel click`);
    const zs = frames.map((r) => r.z);
    for (let i = 1; i < zs.length; i++) assert.ok(zs[i]! >= zs[i - 1]! - 1e-9, 'zooming out, the slice only rises');
    // Eased in and out: the first and last steps are smaller than the largest.
    const steps = zs.slice(1).map((z, i) => z - zs[i]!).filter((d) => d > 1e-9);
    const largest = Math.max(...steps);
    assert.ok(steps[0]! < largest && steps[steps.length - 1]! < largest, `steps ${steps.map((s) => s.toFixed(2)).join(' ')}`);
  });

  test('drag pans with the ground point under the pointer, and a release in motion glides on, then stops', async () => {
    const page = await open();
    const start = await startAt(page, { scaleDenominator: 2000 });
    const from: [number, number] = [200, 240];
    const grabbed = await groundAt(page, from);
    // A slow drag that stops before the release: no glide, the grabbed point is under the pointer.
    await page.mouse.move(...from);
    await page.mouse.down();
    for (let i = 1; i <= 10; i++) {
      await page.mouse.move(from[0] + 10 * i, from[1] + 5 * i);
      await page.waitForTimeout(20);
    }
    await page.waitForTimeout(300);
    await page.mouse.up();
    await settle(page, 'true');
    const held = await groundAt(page, [from[0] + 100, from[1] + 50]);
    assert.ok(pxApart(held, grabbed, start.scale) <= 1, `the grabbed point is ${pxApart(held, grabbed, start.scale).toFixed(3)} px from the pointer`);

    // A flick: released while moving, the map keeps going the same way, then stops.
    await page.evaluate(() => {
      const w = globalThis as unknown as VarioWindow & { atRelease: [number, number] | null };
      w.atRelease = null;
      (globalThis as unknown as PageWindow).document.addEventListener('pointerup', () => (w.atRelease = w.map.getCenterProjected()), { capture: true, once: true });
    });
    const before = await camera(page);
    // Real mouse events with the times of a real flick (16 ms apart, released in motion): the
    // harness waits for each event's handling, and on a slow software-rendered page those waits
    // would read as the pointer having rested before the release.
    const cdp = await bed.page!.context.newCDPSession(page);
    const t0 = Date.now() / 1000;
    const mouse = (type: 'mouseMoved' | 'mousePressed' | 'mouseReleased', x: number, i: number, buttons: number): Promise<unknown> =>
      cdp.send('Input.dispatchMouseEvent', { type, x, y: 240, button: 'left', buttons, clickCount: 1, timestamp: t0 + 0.016 * i });
    await mouse('mouseMoved', 560, 0, 0);
    await mouse('mousePressed', 560, 1, 1);
    for (let i = 1; i <= 8; i++) await mouse('mouseMoved', 560 - 60 * i, 1 + i, 1);
    await mouse('mouseReleased', 80, 10, 0);
    const atRelease = await page.evaluate(() => (globalThis as unknown as { atRelease: [number, number] }).atRelease);
    await settle(page, 'true');
    const end = await camera(page);
    // Dragging left moves the view east: x grows during the drag and after the release.
    assert.ok(atRelease[0] > before.x, 'the drag moved the view');
    const glide = (end.x - atRelease[0]) / px(end.scale);
    // MapLibre's inertia, computed by hand: 480 px in the 128 ms between the press and the last
    // move, times a linearity of 0.3, is 1125 px/s (under the 1400 cap); decelerating at
    // 2500 * 0.3 px/s^2 it goes on 1125^2 / (2 * 750) = 843.75 px. The page sees event times
    // coarsened to 0.1 ms: 0.2 ms in 128 is 0.3% of the distance (it goes as the speed squared).
    assert.ok(Math.abs(glide - 843.75) < 0.005 * 843.75, `glided ${glide.toFixed(2)} px on after the release, expected 843.75`);
    assert.ok(Math.abs(end.y - atRelease[1]) / px(end.scale) < 1, 'in the direction of the drag');
    await page.waitForTimeout(200);
    const still = await camera(page);
    assert.deepEqual(still, end, 'and then stopped');
  });

  test('a wheel click during an animation interrupts it where it is, without a jump', async () => {
    const page = await open();
    const start = await startAt(page, { scaleDenominator: 2000 });
    const res = px(start.scale);
    const far: [number, number] = [start.x + 2000 * res, start.y];
    await record(page);
    await page.evaluate(
      (c) => {
        const w = globalThis as unknown as VarioWindow & { wheelAt: number };
        (globalThis as unknown as PageWindow).document.addEventListener('wheel', () => (w.wheelAt = performance.now()), { capture: true, once: true });
        void w.map.easeTo({ centerProjected: c, duration: 20_000 });
      },
      far,
    );
    await page.waitForFunction(() => (globalThis as unknown as VarioWindow).rec.filter((r) => r.type === 'move').length >= 4);
    const cursor: [number, number] = [400, 300];
    await page.mouse.move(...cursor);
    await page.mouse.wheel(0, -100);
    await settle(page, `window.map.getScaleDenominator() < ${start.scale * 0.75}`);
    const end = await camera(page);
    const wheelAt = await page.evaluate(() => (globalThis as unknown as { wheelAt: number }).wheelAt);
    const moves = (await recorded(page)).filter((r) => r.type === 'move');
    const k = moves.findIndex((r) => r.t > wheelAt);
    assert.ok(k > 1, 'the pan had moved before the wheel');
    const last = moves[k - 1]!;
    // Interrupted: the pan's target is far off, and the zoom took over from where the pan was.
    assert.ok((far[0] - end.x) / px(end.scale) > 100, 'the pan did not go on to its target');
    assert.ok(Math.abs(end.scale - start.scale / 2) < 1e-6 * start.scale, `scale ${end.scale}`);
    // Measured at the cursor: the zoom moves the centre towards the cursor from its first
    // frame, by however far that frame got (a busy machine's late frame gets further), but keeps
    // the ground under the cursor where it is; the pan moves both alike.
    const underCursor = (r: { x: number; y: number; scale: number }): [number, number] => [r.x + (cursor[0] - W / 2) * px(r.scale), r.y - (cursor[1] - H / 2) * px(r.scale)];
    const steps = moves.slice(1, k).map((r, i) => Math.hypot(r.x - moves[i]!.x, r.y - moves[i]!.y));
    const g = underCursor(last);
    const at = underCursor(moves[k]!);
    const across = Math.hypot(at[0] - g[0], at[1] - g[1]);
    assert.ok(across <= Math.max(...steps) * 1.5 + 0.01 * res, `the step across the interruption at the cursor (${(across / res).toFixed(2)} px) is no larger than the pan's own (${(Math.max(...steps) / res).toFixed(2)} px)`);
    // The ground point that was under the cursor when the wheel came is under it at the end.
    const after = await groundAt(page, cursor);
    assert.ok(pxApart(after, g, end.scale) <= 1, `${pxApart(after, g, end.scale).toFixed(3)} px`);
  });

  test('double click zooms in a step about the point; with shift, out', async () => {
    const page = await open();
    const start = await startAt(page, { scaleDenominator: 3000 });
    const p: [number, number] = [450, 160];
    const ground = await groundAt(page, p);
    await page.mouse.dblclick(...p);
    await settle(page, `window.map.getScaleDenominator() < ${start.scale * 0.75}`);
    let end = await camera(page);
    assert.ok(Math.abs(end.scale - start.scale / 2) < 1e-6 * start.scale, `scale ${end.scale}`);
    assert.ok(pxApart(await groundAt(page, p), ground, end.scale) <= 1);
    await page.keyboard.down('Shift');
    await page.mouse.dblclick(...p);
    await page.keyboard.up('Shift');
    await settle(page, `window.map.getScaleDenominator() > ${start.scale * 0.75}`);
    end = await camera(page);
    assert.ok(Math.abs(end.scale - start.scale) < 1e-6 * start.scale, `scale ${end.scale}`);
    assert.ok(pxApart(await groundAt(page, p), ground, end.scale) <= 1);
  });

  test('keys: + and - zoom a step about the centre, the arrows pan 100 px', async () => {
    const page = await open();
    const start = await startAt(page, { scaleDenominator: 3000 });
    await page.focus('.vario-map-canvas-container');
    await page.keyboard.press('+');
    await settle(page, `window.map.getScaleDenominator() < ${start.scale * 0.75}`);
    let c = await camera(page);
    assert.ok(Math.abs(c.scale - start.scale / 2) < 1e-6 * start.scale);
    assert.ok(Math.hypot(c.x - start.x, c.y - start.y) < 1e-6, 'about the centre');
    await page.keyboard.press('ArrowRight');
    await settle(page, `window.map.getCenterProjected()[0] > ${c.x + 50 * px(c.scale)}`);
    const r = await camera(page);
    assert.ok(Math.abs((r.x - c.x) / px(c.scale) - 100) < 0.5 && Math.abs(r.y - c.y) < 1e-6, `moved ${((r.x - c.x) / px(c.scale)).toFixed(2)} px`);
    await page.keyboard.press('ArrowUp');
    await settle(page, `window.map.getCenterProjected()[1] > ${r.y + 50 * px(c.scale)}`);
    c = await camera(page);
    assert.ok(Math.abs((c.y - r.y) / px(c.scale) - 100) < 0.5, 'up shows what is north');
    await page.keyboard.press('-');
    await settle(page, `window.map.getScaleDenominator() > ${start.scale * 0.75}`);
    assert.ok(Math.abs((await camera(page)).scale - start.scale) < 1e-6 * start.scale);
  });

  test('shift-drag a box: the map zooms to show it', async () => {
    const page = await open();
    const start = await startAt(page, { scaleDenominator: 3000 });
    const a: [number, number] = [300, 250], b: [number, number] = [460, 370];
    const ga = await groundAt(page, a), gb = await groundAt(page, b);
    await page.keyboard.down('Shift');
    await page.mouse.move(...a);
    await page.mouse.down();
    await page.mouse.move(380, 310);
    await page.mouse.move(...b);
    await page.mouse.up();
    await page.keyboard.up('Shift');
    await settle(page, `window.map.getScaleDenominator() < ${start.scale * 0.5}`);
    const end = await camera(page);
    // The box (160 x 120 px) fills the 640 x 480 view: 4 times the detail, centred on it.
    assert.ok(Math.abs(end.scale - start.scale / 4) < 1e-6 * start.scale, `scale ${end.scale}`);
    assert.ok(Math.hypot(end.x - (ga[0] + gb[0]) / 2, end.y - (ga[1] + gb[1]) / 2) / px(end.scale) < 0.5, 'centred on the box');
  });

  test('the comparison mode shows content of a few discrete scales only', async () => {
    const page = await open();
    await startAt(page, { scaleDenominator: middleScale() });
    const zAt = async (scale: number): Promise<number> => {
      await page.evaluate((s) => (globalThis as unknown as VarioWindow).map.jumpTo({ scaleDenominator: s }), scale);
      return page.evaluate(() => (globalThis as unknown as VarioWindow).map.getSliceZ());
    };
    const s0 = middleScale();
    const vario = [await zAt(s0), await zAt(s0 * 1.1), await zAt(s0 * 1.2)];
    assert.equal(new Set(vario).size, 3, 'vario-scale: every scale its own slice');
    // Switched on at run time, from the settings panel.
    await page.click('.vario-map-settings-toggle');
    await page.check('input[id$="-comparison"]');
    assert.equal(await page.evaluate(() => (globalThis as unknown as VarioWindow).map.getSettings().comparisonMode), true);
    const levels = new Set<number>();
    for (let k = 0; k <= 20; k++) levels.add(await zAt(bed.contents.meta.baseScale * Math.pow(2, k / 4)));
    assert.ok(levels.size <= 6 && levels.size >= 3, `${levels.size} distinct slices over 5 doublings of scale`);
  });

  test("the settings panel's lens and control point modes are the LensControl and IdwControl", async () => {
    const page = await open();
    const start = await startAt(page, { scaleDenominator: middleScale() });
    const surface = (): Promise<{ kind: string } & Record<string, unknown>> => page.evaluate(() => (globalThis as unknown as VarioWindow).map.getSlicingSurface());
    const choose = async (mode: string): Promise<void> => {
      await page.click('.vario-map-settings-toggle');
      await page.selectOption('select[id$="-surface"]', mode);
      await page.keyboard.press('Escape');
    };
    const near = (a: number, b: number, what: string): void => assert.ok(Math.abs(a - b) <= 1e-6 * px(start.scale), `${what}: ${a} vs ${b}`);
    // The lens follows the pointer, with the control's radius (120 CSS px) and depth (200 steps).
    await choose('lens');
    await page.mouse.move(300, 400, { steps: 4 });
    const lens = await surface();
    assert.equal(lens.kind, 'lens');
    const [gx, gy] = await groundAt(page, [300, 400]);
    near(lens.cx as number, gx, 'lens centre x');
    near(lens.cy as number, gy, 'lens centre y');
    near(lens.radius as number, 120 * px(start.scale), 'lens radius');
    assert.equal(lens.depth, 200);
    // Control points: the lens goes (flat until a point is placed), a click places a point.
    await choose('idw');
    assert.equal((await surface()).kind, 'flat', 'the lens is off');
    await page.mouse.click(250, 380);
    const idw = await surface();
    assert.equal(idw.kind, 'idw');
    const points = idw.points as { x: number; y: number; z: number }[];
    assert.equal(points.length, 1);
    const [ix, iy] = await groundAt(page, [250, 380]);
    near(points[0]!.x, ix, 'point x');
    near(points[0]!.y, iy, 'point y');
    assert.equal(await page.locator('.ssc-control-point').count(), 1, 'a marker for the point');
    await choose('flat');
    assert.equal((await surface()).kind, 'flat');
    assert.equal(await page.locator('.ssc-control-point').count(), 0, 'the markers go with the tool');
  });

  test('the interaction log records input and views (JSON, CSV); pointermove names the face under the pointer', async () => {
    const page = await open();
    const start = await startAt(page, { scaleDenominator: 3000 });
    const hovered = page.evaluate(
      () =>
        new Promise<{ face: number; point: [number, number] } | null>((resolve) => {
          const m = (globalThis as unknown as VarioWindow).map;
          const fn = (ev: unknown): void => {
            const e = ev as { features: { kind: string; face: number }[]; point: [number, number] };
            const face = e.features.find((f) => f.kind === 'face');
            if (!face) return;
            m.off('pointermove', fn);
            resolve({ face: face.face, point: e.point });
          };
          m.on('pointermove', fn);
        }),
    );
    // Recording is switched on in the settings panel.
    await page.click('.vario-map-settings-toggle');
    await page.check('input[id$="-log-record"]');
    // The open panel covers the right half of this small map: the pointer stays left of it.
    await page.mouse.move(150, 300);
    await page.mouse.move(160, 305);
    const hover = await Promise.race([hovered, new Promise<null>((resolve) => setTimeout(() => resolve(null), 30_000))]);
    assert.ok(hover && hover.face > 0, 'a face under the pointer');
    await page.mouse.wheel(0, 100);
    await settle(page, `window.map.getScaleDenominator() > ${start.scale * 1.5}`);
    const log = await page.evaluate(() => {
      const l = (globalThis as unknown as { settings: { log: { toJSON(): { entries: { t: number; kind: string; scale: number; event: string }[] }; toCSV(): string } } }).settings.log;
      return { json: l.toJSON(), csv: l.toCSV() };
    });
    const entries = log.json.entries;
    const wheel = entries.findIndex((e) => e.kind === 'input' && e.event === 'wheel');
    assert.ok(wheel >= 0, 'the wheel is logged');
    const views = entries.slice(wheel).filter((e) => e.kind === 'view');
    assert.ok(views.length >= 10, `${views.length} views logged after it`);
    assert.ok(Math.abs(views[views.length - 1]!.scale - start.scale * 2) < 1e-6 * start.scale, 'ending at the new scale');
    for (let i = 1; i < entries.length; i++) assert.ok(entries[i]!.t >= entries[i - 1]!.t, 'in time order');
    const lines = log.csv.trim().split('\n');
    assert.equal(lines[0], 't,kind,x,y,scale,z,event,detail');
    assert.equal(lines.length, entries.length + 1);
    assert.match(lines[wheel + 1]!, /,input,.*,wheel,100 mode 0 at 160 305$/);
  });

  test('reduced motion: a wheel click and a flight are jumps', async () => {
    const page = await open({}, { reducedMotion: 'reduce' });
    const start = await startAt(page, { scaleDenominator: middleScale() });
    await record(page);
    await page.mouse.move(320, 240);
    await page.mouse.wheel(0, -100);
    await settle(page, `window.map.getScaleDenominator() < ${start.scale * 0.75}`);
    let moves = (await recorded(page)).filter((r) => r.type === 'move');
    assert.equal(moves.length, 1, 'one move: straight to the new scale');
    assert.ok(Math.abs(moves[0]!.scale - start.scale / 2) < 1e-6 * start.scale);
    await record(page);
    const target: [number, number] = [start.x + 100, start.y - 80];
    await page.evaluate((c) => (globalThis as unknown as VarioWindow).map.flyTo({ centerProjected: c, scaleDenominator: 1500 }), target);
    moves = (await recorded(page)).filter((r) => r.type === 'move');
    assert.equal(moves.length, 1);
    assert.deepEqual([moves[0]!.x, moves[0]!.y, moves[0]!.scale], [...target, 1500]);
  });
});
