// What the tests of the built library in plain pages share: a site with dist/lib (as lib/)
// and the test's pages, a real cube of bgt_otterlo_400m at /cube/ behind the test server, and
// Chromium.
import { cp, mkdtemp, rm, writeFile } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { after, afterEach, before } from 'node:test';
import type { Browser } from 'playwright-core';
import { launchChromium, type MapPage } from './browser.js';
import { buildCube, otterlo400, readCube, repoRoot, type BuiltCube, type CubeContents } from './cube.js';
import { checkAndClose } from './test-bed.js';
import { startTestServer, type TestServer } from './test-server.js';

/** A page's start, to its map container (#map, filling the window). */
export const LIB_PAGE_HEAD = `<!doctype html>
<html lang="en">
<head>
  <meta charset="utf-8">
  <meta name="viewport" content="width=device-width, initial-scale=1">
  <title>Map</title>
  <link rel="icon" href="data:,">
  <link rel="stylesheet" href="lib/vario-map.css">
  <style>html, body { margin: 0; height: 100%; } #map { position: absolute; inset: 0; }</style>
</head>
<body>
  <main><div id="map"></div></main>`;

export interface LibSite {
  cube: BuiltCube;
  /** The site's folder, to add files to. */
  dir: string;
  server: TestServer;
  browser: Browser;
  close(): Promise<void>;
}

/** The site with these pages (file name to HTML). */
export async function startLibSite(pages: Record<string, string>): Promise<LibSite> {
  const cube = await buildCube(otterlo400, ['--no-precompress']);
  const dir = await mkdtemp(path.join(tmpdir(), 'ssc-site-'));
  await cp(path.join(repoRoot, 'dist/lib'), path.join(dir, 'lib'), { recursive: true });
  for (const [name, html] of Object.entries(pages)) await writeFile(path.join(dir, name), html);
  const server = await startTestServer({ clientDir: dir, cubeDir: cube.dir });
  const browser = await launchChromium();
  return {
    cube,
    dir,
    server,
    browser,
    async close() {
      await browser.close();
      await server.close();
      await cube.remove();
      await rm(dir, { recursive: true, force: true });
    },
  };
}

export interface LibSiteBed {
  site: LibSite;
  contents: CubeContents;
  /** The running test's page: checked for console errors and closed after the test. */
  page: MapPage | null;
}

/**
 * In a describe(): the site with these pages up before its tests and down after them, and
 * each test's page (bed.page) checked and closed after it. The fields are there from the first
 * test on.
 */
export function useLibSite(pages: Record<string, string>): LibSiteBed {
  const bed = { page: null } as LibSiteBed;
  before(async () => {
    bed.site = await startLibSite(pages);
    bed.contents = await readCube(bed.site.cube.dir);
  });
  afterEach(async () => {
    await checkAndClose(bed.page);
    bed.page = null;
  });
  after(async () => {
    await bed.site?.close();
  });
  return bed;
}
