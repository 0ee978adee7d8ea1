// axe-core (the standard accessibility checker) in Chromium on the demo page and on every page
// template of the docs (docs/*.md's whole HTML pages, served with the built library and a cube;
// a bundler's page with the built module in place of its entry): once the map has loaded, no
// violation of any rule axe runs by default (WCAG A and AA and its best practices, among them
// that all content is inside landmarks), and the map inside <main>.
import assert from 'node:assert/strict';
import { cp, writeFile } from 'node:fs/promises';
import path from 'node:path';
import { after, afterEach, before, describe, test } from 'node:test';
import type { Page } from 'playwright-core';
import { docsPageTemplates } from '../testing/html-code-blocks.js';
import { axeViolations } from './helpers/axe.js';
import { openMap, type MapPage } from './helpers/browser.js';
import { repoRoot } from './helpers/cube.js';
import { startLibSite, type LibSite } from './helpers/lib-site.js';
import { checkAndClose } from './helpers/test-bed.js';
import { openDemo } from './helpers/vario-page.js';

interface PageWindow {
  document: {
    querySelector(s: string): { textContent: string | null; closest(s: string): object | null } | null;
  };
}

/**
 * A bundler's page loads its entry (a .ts file the bundler compiles): here the built ES module
 * does what that entry does (docs/embedding.md's main.ts: the map, its stylesheet, zoom buttons
 * and a scale bar), so the page's own markup is what axe checks.
 */
function servable(html: string): string {
  const entry = /<script type="module" src="[^"]+\.ts"><\/script>/;
  if (!entry.test(html)) return html;
  return html.replace('</head>', '  <link rel="stylesheet" href="lib/vario-map.css">\n</head>').replace(
    entry,
    `<script type="module">
    import { VarioMap, ZoomControl, ScaleBar } from './lib/vario-map.js';
    const map = new VarioMap({ container: 'map', source: 'cube' });
    map.addControl(new ZoomControl());
    map.addControl(new ScaleBar(), 'bottom-left');
  </script>`,
  );
}

/** The docs' page templates, by file name in the site. */
const TEMPLATES = docsPageTemplates();
const pageName = (i: number): string => `template-${i + 1}.html`;

describe('accessibility: axe-core on the demo and the docs page templates (bgt_otterlo_400m)', () => {
  let lib: LibSite;
  let mp: MapPage | null = null;

  before(async () => {
    lib = await startLibSite(Object.fromEntries(TEMPLATES.map(([, html], i) => [pageName(i), servable(html)])));
    // The demo as `npm run build` writes it, beside them.
    await cp(path.join(repoRoot, 'dist/client'), lib.dir, { recursive: true });
    // The templates name no icon: the browser asks for this one.
    await writeFile(path.join(lib.dir, 'favicon.ico'), '');
  });

  afterEach(async () => {
    await checkAndClose(mp);
    mp = null;
  });

  after(async () => {
    await lib?.close();
  });

  /** Whether the map's focusable region is inside the <main> landmark. */
  function mapInMain(page: Page): Promise<boolean> {
    return page.evaluate(() => (globalThis as unknown as PageWindow).document.querySelector('.vario-map-canvas-container')?.closest('main') != null);
  }

  test('the demo page, loaded, and with its settings panel open', async () => {
    mp = await openDemo(lib.browser, lib.server.url, { source: 'cube/' });
    const page = mp.page;
    assert.ok(await mapInMain(page), 'the map inside <main>');
    assert.deepEqual(await axeViolations(page), []);
    await page.click('.vario-map-settings-toggle');
    assert.deepEqual(await axeViolations(page), [], 'with the settings panel open');
  });

  for (const [i, [where]] of TEMPLATES.entries()) {
    test(where, async () => {
      mp = await openMap(lib.browser, lib.server.url, {}, { page: pageName(i) });
      const page = mp.page;
      // Loaded: the scale bar shows a scale once the cube's metadata is in.
      await page.waitForFunction(() => /^1:/.test((globalThis as unknown as PageWindow).document.querySelector('.vario-map-scale-denominator')?.textContent ?? ''));
      assert.ok(await mapInMain(page), 'the map inside <main>');
      assert.deepEqual(await axeViolations(page), []);
    });
  }
});
