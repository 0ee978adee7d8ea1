// The package as a user gets it: `npm pack` (of what `npm run build` wrote; prepack would
// build the same), installed from the tarball into a fresh project, where a TypeScript page
// that imports VarioMap type-checks, builds with Vite and draws the map in Chromium, and the
// `ssc` command runs (it builds the page's cube, so its run-time dependencies are all there).
import assert from 'node:assert/strict';
import { execFile } from 'node:child_process';
import { existsSync } from 'node:fs';
import { mkdir, mkdtemp, readFile, readdir, rm, writeFile } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { promisify } from 'node:util';
import { after, afterEach, before, describe, test } from 'node:test';
import type { Browser } from 'playwright-core';
import { launchChromium, openMap, type MapPage } from './helpers/browser.js';
import { otterlo400, repoRoot } from './helpers/cube.js';
import { rdToLngLat } from './helpers/geo.js';
import { checkAndClose } from './helpers/test-bed.js';
import { startTestServer, type TestServer } from './helpers/test-server.js';
import { idle, type VarioWindow } from './helpers/vario-page.js';

const run = promisify(execFile);
const tsc = path.join(repoRoot, 'node_modules/typescript/bin/tsc');
const vite = path.join(repoRoot, 'node_modules/vite/bin/vite.js');

const PAGE_TS = `import { VarioMap, ZoomControl, type Feature, type VarioMapOptions } from 'vario-scale-map';
import 'vario-scale-map/vario-map.css';

const options: VarioMapOptions = { container: 'map', source: 'cube/' };
const map = new VarioMap(options);
map.addControl(new ZoomControl());
const page = window as unknown as { map: VarioMap; clicked?: Feature | null; clickedAt?: [number, number] | null };
map.on('click', (e) => {
  page.clicked = e.features.find((f) => f.kind === 'face') ?? null;
  page.clickedAt = e.lngLat ? e.lngLat.toArray() : null;
});
page.map = map;
`;

const INDEX_HTML = `<!doctype html>
<html lang="en">
<head>
  <meta charset="utf-8">
  <meta name="viewport" content="width=device-width, initial-scale=1">
  <title>Map</title>
  <link rel="icon" href="data:,">
  <style>html, body { margin: 0; height: 100%; } #map { position: absolute; inset: 0; }</style>
</head>
<body>
  <main id="map"></main>
  <script type="module" src="./main.ts"></script>
</body>
</html>
`;

const TSCONFIG = {
  compilerOptions: {
    target: 'ES2022',
    module: 'ESNext',
    moduleResolution: 'Bundler',
    lib: ['ES2023', 'DOM', 'DOM.Iterable'],
    types: [],
    strict: true,
    noUncheckedIndexedAccess: true,
    noEmit: true,
  },
  include: ['main.ts'],
};

/** What the tarball may hold: the library, the compiled CLI, styles and docs. */
const SHIPPED = /^(package\.json|README\.md|bin\/ssc\.js|dist\/lib\/.+|dist\/(preprocess|format|server)\/.+\.js|styles\/[\w-]+\.json|docs\/[\w-]+\.md|docs\/img\/[\w-]+\.png)$/;

/** Relative files a built script loads: its imports (static and lazy) and its worker's URL. */
function referencedFiles(js: string): string[] {
  const out: string[] = [];
  for (const m of js.matchAll(/(?:\bfrom\s*|\bimport\s*\(\s*)["'`](\.{1,2}\/[^"'`]+)["'`]/g)) if (m[1]) out.push(m[1]);
  for (const m of js.matchAll(/["'`](\/assets\/[^"'`]+)["'`]/g)) if (m[1]) out.push(m[1]);
  return out;
}

describe('the packed package in a fresh project (bgt_otterlo_400m)', () => {
  let tmp: string;
  let app: string;
  let packed: string[] = [];
  let server: TestServer | undefined;
  let browser: Browser | undefined;
  let mp: MapPage | null = null;

  before(async () => {
    tmp = await mkdtemp(path.join(tmpdir(), 'ssc-package-'));
    // dist/ is what `npm test` just built; prepack would only build it again.
    const { stdout } = await run('npm', ['pack', '--ignore-scripts', '--json', '--pack-destination', tmp], { cwd: repoRoot, maxBuffer: 1 << 24 });
    const [info] = JSON.parse(stdout) as { filename: string; files: { path: string }[] }[];
    assert.ok(info, 'npm pack reports the tarball');
    packed = info.files.map((f) => f.path);
    app = path.join(tmp, 'app');
    await mkdir(app);
    await writeFile(path.join(app, 'package.json'), JSON.stringify({ name: 'app', private: true, type: 'module' }));
    await run('npm', ['install', '--prefer-offline', '--no-audit', '--no-fund', path.join(tmp, info.filename)], { cwd: app, maxBuffer: 1 << 24 });
    await writeFile(path.join(app, 'main.ts'), PAGE_TS);
    await writeFile(path.join(app, 'index.html'), INDEX_HTML);
    await writeFile(path.join(app, 'tsconfig.json'), JSON.stringify(TSCONFIG));
  });

  afterEach(async () => {
    await checkAndClose(mp);
    mp = null;
  });

  after(async () => {
    await browser?.close();
    await server?.close();
    if (tmp) await rm(tmp, { recursive: true, force: true });
  });

  test('the tarball holds the library, the CLI, styles and docs, and nothing else', () => {
    const stray = packed.filter((p) => !SHIPPED.test(p) || /\.test\.js$|\/test\//.test(p));
    assert.deepEqual(stray, []);
    for (const p of ['dist/lib/vario-map.js', 'dist/lib/vario-map.umd.js', 'dist/lib/vario-map.css', 'dist/lib/types/client/src/lib/index.d.ts', 'bin/ssc.js', 'dist/preprocess/cli.js', 'styles/bgt.json', 'docs/embedding.md']) {
      assert.ok(packed.includes(p), `${p} is shipped`);
    }
  });

  test('the library imports no package: a page pulls in none of the CLI dependencies', async () => {
    const lib = path.join(app, 'node_modules/vario-scale-map/dist/lib');
    const files = ['vario-map.js', ...(await readdir(path.join(lib, 'assets'))).filter((f) => f.endsWith('.js')).map((f) => `assets/${f}`)];
    for (const f of files) {
      const js = await readFile(path.join(lib, f), 'utf8');
      assert.deepEqual([...js.matchAll(/(?:\bfrom\s*|\bimport\s*\(\s*)["'`]([^."'`][^"'`]*)["'`]/g)].map((m) => m[1]), [], `${f} imports no package`);
    }
  });

  test('npx ssc --help runs from the install', async () => {
    const { stdout } = await run('npx', ['--no', '--', 'ssc', '--help'], { cwd: app });
    assert.match(stdout, /usage: ssc <command>/);
  });

  test('a page importing VarioMap and its types type-checks', async () => {
    await run(process.execPath, [tsc, '-p', app], { cwd: app }).catch((e: { stdout?: string }) => assert.fail(`tsc: ${e.stdout ?? String(e)}`));
  });

  test('Vite builds the page, with the worker and every file the scripts load', async () => {
    await run(process.execPath, [vite, 'build', '--logLevel', 'warn'], { cwd: app });
    const assets = path.join(app, 'dist/assets');
    const scripts = (await readdir(assets)).filter((f) => f.endsWith('.js'));
    assert.ok(scripts.some((f) => f.startsWith('chunk-worker')), `the worker is emitted: ${scripts.join(' ')}`);
    for (const f of scripts) {
      for (const ref of referencedFiles(await readFile(path.join(assets, f), 'utf8'))) {
        const file = ref.startsWith('/') ? path.join(app, 'dist', ref) : path.join(assets, ref);
        assert.ok(existsSync(file), `${f} loads ${ref}, which the build emitted`);
      }
    }
  });

  test('the built page draws the whole map, and a click returns the face under it', async () => {
    const cube = path.join(tmp, 'cube');
    const style = path.join(app, 'node_modules/vario-scale-map/styles/bgt.json');
    await run('npx', ['--no', '--', 'ssc', 'build', otterlo400, '--style', style, '--out', cube, '--quiet', '--no-precompress'], { cwd: app, maxBuffer: 1 << 24 });
    server = await startTestServer({ clientDir: path.join(app, 'dist'), cubeDir: cube });
    browser = await launchChromium();
    mp = await openMap(browser, server.url, {}, { page: 'index.html' });
    const { page } = mp;
    await idle(page);
    assert.equal(await page.evaluate(() => (globalThis as unknown as VarioWindow).map.whenIdle().then((r) => r.complete)), true);
    await page.mouse.click(320, 240);
    await page.waitForFunction(() => (globalThis as unknown as { clicked?: unknown }).clicked !== undefined);
    const clicked = await page.evaluate(() => (globalThis as unknown as { clicked: { face: number; classKey: string } | null }).clicked);
    assert.ok(clicked && clicked.face > 0, `a face: ${JSON.stringify(clicked)}`);
    const classes = (JSON.parse(await readFile(style, 'utf8')) as { classes: Record<string, unknown> }).classes;
    assert.ok(clicked.classKey in classes, `a class of the style: ${clicked.classKey}`);
    // Longitude/latitude come from proj4, which the library imports lazily: the app's bundle
    // carries it as a file of its own, and the page loads it.
    const at = await page.evaluate(() => (globalThis as unknown as { clickedAt: [number, number] | null }).clickedAt);
    const expected = rdToLngLat(await page.evaluate((p) => (globalThis as unknown as VarioWindow).map.unprojectProjected(p), [320, 240] as [number, number]));
    assert.ok(at && Math.abs(at[0] - expected[0]) < 1e-7 && Math.abs(at[1] - expected[1]) < 1e-7, `the click's lngLat ${JSON.stringify(at)} is proj4's ${expected.join(', ')}`);
  });
});
