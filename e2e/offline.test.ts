// Offline use through the demo's service worker (workbox), in Chromium against the project's
// server: visit and look around with real input, stop the server, reload, and the map draws the
// same views from the cache with no request failing; then a new build of the cube (other chunk
// names) replaces the old one: the page is told, the old build's files leave the cache, and
// after a reload the map shows only the new build's files.
import assert from 'node:assert/strict';
import { cp, mkdtemp, readdir, rm } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { after, before, describe, test } from 'node:test';
import type { Browser, Page } from 'playwright-core';
import { createSiteServer, type SiteServer } from '../server/site-server.js';
import { launchChromium, openMap, type MapPage } from './helpers/browser.js';
import { buildCube, clientDir, otterlo400, type BuiltCube } from './helpers/cube.js';
import { checkAndClose } from './helpers/test-bed.js';
import { camera, idle, settle, type Camera, type VarioWindow } from './helpers/vario-page.js';

const FILES_CACHE = 'vario-cube-files';

/** The cube file URLs (index excluded) in the service worker's cache. */
function cachedFiles(page: Page): Promise<string[]> {
  return page.evaluate<string[]>(`caches.open(${JSON.stringify(FILES_CACHE)}).then((c) => c.keys()).then((ks) => ks.map((k) => k.url))`);
}

/** The map's loaded file URLs that are not in the cache yet. */
function uncached(page: Page): Promise<string[]> {
  return page.evaluate<string[]>(`(async () => {
    const urls = await window.map.getLoadedUrls();
    const out = [];
    for (const u of urls) if (!(await caches.match(u))) out.push(u);
    return out;
  })()`);
}

const names = (urls: string[]): string[] => urls.map((u) => decodeURIComponent(new URL(u).pathname.split('/').pop()!)).sort();

async function jumpAndShoot(page: Page, cam: Camera): Promise<{ complete: boolean; png: Buffer }> {
  await page.evaluate((c) => (globalThis as unknown as VarioWindow).map.jumpTo({ centerProjected: [c.x, c.y], scaleDenominator: c.scale }), cam);
  const r = await page.evaluate(() => (globalThis as unknown as VarioWindow).map.whenIdle());
  return { complete: r.complete, png: await page.locator('#map canvas').screenshot() };
}

describe('offline use (bgt_otterlo_400m, service worker)', () => {
  let a: BuiltCube, b: BuiltCube;
  let served: string;
  let site: SiteServer | null = null;
  let port = 0;
  let browser: Browser;
  let mp: MapPage | null = null;

  /** Serves what is in `served` (the client beside it) on the test's one origin. */
  async function start(): Promise<void> {
    site = createSiteServer({ clientDir, cubeDir: served, cubePath: '/cube' });
    port = await site.listen(port, '127.0.0.1');
  }
  async function stop(): Promise<void> {
    await site?.close();
    site = null;
  }
  async function serveBuild(cube: BuiltCube): Promise<void> {
    for (const f of await readdir(served)) await rm(path.join(served, f), { force: true });
    await cp(cube.dir, served, { recursive: true });
  }

  before(async () => {
    // Two builds of the same data whose chunks differ (other sizes, so other names).
    [a, b] = await Promise.all([buildCube(otterlo400, ['--no-precompress', '--chunk-bytes', '65536']), buildCube(otterlo400, ['--no-precompress', '--chunk-bytes', '131072'])]);
    served = await mkdtemp(path.join(tmpdir(), 'ssc-offline-'));
    await serveBuild(a);
    await start();
    browser = await launchChromium();
  });

  after(async () => {
    await mp?.close();
    await browser?.close();
    await stop();
    await a?.remove();
    await b?.remove();
    if (served) await rm(served, { recursive: true, force: true });
  });

  test('after one visit the views seen draw with the server stopped; a new build then replaces the old one', async () => {
    mp = await openMap(browser, `http://127.0.0.1:${port}/`, { source: 'cube/', supersampling: 1 }, { page: 'demo.html' });
    const page = mp.page;
    await idle(page);
    await page.waitForFunction('navigator.serviceWorker.controller !== null', null, { timeout: 30_000 });

    // Look around with real input: zoom out twice about a point, then drag.
    const views: Camera[] = [await camera(page)];
    await page.mouse.move(250, 200);
    for (let i = 0; i < 2; i++) {
      const before = views[views.length - 1]!.scale;
      await page.mouse.wheel(0, 100);
      await settle(page, `window.map.getScaleDenominator() > ${before * 1.5}`);
      await idle(page);
      views.push(await camera(page));
    }
    await page.mouse.move(300, 250);
    await page.mouse.down();
    for (let i = 1; i <= 10; i++) await page.mouse.move(300 - 12 * i, 250 - 8 * i);
    // A rest before the release: no glide, the view stays where the drag left it.
    await page.waitForTimeout(250);
    await page.mouse.up();
    await idle(page);
    views.push(await camera(page));
    assert.ok(views[2]!.scale / views[0]!.scale > 3.9, 'zoomed out two steps');

    // Everything the map loaded, also before the service worker took control, gets cached.
    const deadline = Date.now() + 30_000;
    let missing = await uncached(page);
    while (missing.length > 0 && Date.now() < deadline) {
      await page.waitForTimeout(200);
      missing = await uncached(page);
    }
    assert.deepEqual(missing, [], 'every loaded file is in the cache');
    const online = [];
    for (const v of views) online.push(await jumpAndShoot(page, v));
    assert.ok(online.every((o) => o.complete));

    // Offline: the page itself, the index and the chunks come from the cache.
    await stop();
    await page.reload();
    await idle(page);
    for (let i = 0; i < views.length; i++) {
      const off = await jumpAndShoot(page, views[i]!);
      assert.ok(off.complete, `view ${i} complete offline`);
      assert.ok(off.png.equals(online[i]!.png), `view ${i} offline looks as it did online`);
    }
    // Real input within what was seen: from the second view, zoom in a step about the same point.
    await page.evaluate((c) => (globalThis as unknown as VarioWindow).map.jumpTo({ centerProjected: [c.x, c.y], scaleDenominator: c.scale }), views[2]!);
    await page.mouse.move(250, 200);
    await page.mouse.wheel(0, -100);
    await settle(page, `window.map.getScaleDenominator() < ${views[2]!.scale * 0.75}`);
    const r = await page.evaluate(() => (globalThis as unknown as VarioWindow).map.whenIdle());
    assert.ok(r.complete, 'zoomed in offline');
    const back = await camera(page);
    assert.ok(Math.abs(back.scale - views[1]!.scale) < 1e-6 * back.scale && Math.hypot(back.x - views[1]!.x, back.y - views[1]!.y) < 1e-6 * back.scale, 'back at the view seen before');
    assert.deepEqual(mp.problems, [], 'no errors offline');

    // A new build on the server: the stale index shows the old build once and the page is
    // told; after the reload the old build's files leave the cache.
    const aFiles = (await readdir(a.dir)).filter((f) => f !== 'index.json');
    const bFiles = new Set((await readdir(b.dir)).filter((f) => f !== 'index.json'));
    const onlyA = aFiles.filter((f) => !bFiles.has(f));
    assert.ok(onlyA.length > 10, 'the builds differ');
    assert.ok(names(await cachedFiles(page)).some((f) => onlyA.includes(f)), 'the old build is cached');
    await serveBuild(b);
    await start();
    await page.reload();
    await idle(page);
    await page.waitForSelector('.demo-update', { timeout: 30_000 });
    await page.click('.demo-update button');
    await page.waitForLoadState('load');
    await idle(page);
    let left = names(await cachedFiles(page)).filter((f) => onlyA.includes(f));
    for (let i = 0; i < 50 && left.length > 0; i++) {
      await page.waitForTimeout(100);
      left = names(await cachedFiles(page)).filter((f) => onlyA.includes(f));
    }
    assert.deepEqual(left, [], 'no file only the old build used is left in the cache');
    const loaded = names((await page.evaluate<string[]>('window.map.getLoadedUrls()')).filter((u) => !u.endsWith('/index.json')));
    assert.ok(loaded.length > 0);
    assert.deepEqual(loaded.filter((f) => !bFiles.has(f)), [], 'the reloaded map uses the new build only');
    await checkAndClose(mp);
    mp = null;
  });
});
