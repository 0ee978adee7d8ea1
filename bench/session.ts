// npm run bench:session [-- <dataset filter>] [runs=N] [frames=N] [starts=F,...]: one scripted
// session, the same for both maps, in headless Chromium at 1280x720: the vario map (the public
// ES build and a cube built fresh by ssc build) against MapLibre GL JS showing tippecanoe vector
// tiles of the same data (issue 13). Both sites come from the project's static server on 127.0.0.1,
// every file gzip-encoded as a CDN would send it. The session: open at the base scale (1:1,000
// for bgt_otterlo_1800m, the style's baseScale for nlcd_zion), zoom out to the full extent in
// `frames` frames (120; geometric in scale), pan a quarter of the data's width in frames/6,
// zoom back in to the base scale in frames/2. Each frame sets the view and waits until the map
// is complete (vario: 'complete', the image on screen shows the whole view, with one
// supersampling frame; MapLibre: 'idle'), recording the data bytes sent so far (server side),
// setView-to-complete ms and the triangles drawn. The next frame follows at once, as in a
// user's zoom: the vario map's redraw once the slice has stopped (blending off) is not waited for.
// Each run also opens each map once more on a slow network (Chromium's own throttling, as
// Lighthouse's "Slow 4G": 1.6 Mbit/s down, 150 ms more per request) and times its first map:
// there the bytes and requests before the first map, code and data, count as on a phone. It does
// so again with the map opened at the start's scale times each of `starts` (1.414 and 4, and
// `extent`: the whole extent, the map's default first view; `phone`: the whole extent on a phone
// held upright, 390x844, the page that size; `starts=` for none), at the same centre: a first
// view above the base scale takes the cube's own chunks (or, up to twice the base scale, first
// the floor's: the interim floor), where MapLibre takes tiles of a lower zoom.
// Prints, per dataset, the medians over `runs` runs (3) and their ratio, the vario map's data
// bytes by kind of file, and what the session's views need of the surface chunks
// (triangles-in-view.ts: a floor for the chunk encoding as it is); `csv=<file>` also
// writes every frame (medians over the runs); `waterfall` also prints, for each map's last run,
// every response the page had whole before the first map on the slow network, with when it came
// from the navigation's start (what lies on a phone's path to the first map). On the slow network
// a response counts from when the browser has it (Playwright's request timing, the worker's
// requests too), not from when the server finished sending it: Chromium's throttling hands it to
// the page later, by the bytes still queued before it. SwiftShader is a software GPU: the times
// compare the two maps on one machine, nothing more.
import { cp, mkdir, mkdtemp, rm, stat, writeFile } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import path from 'node:path';
import type { Browser, BrowserContext, Page } from 'playwright-core';
import { loadStyle } from '../preprocess/style.js';
import { createStaticServer } from '../server/static-server.js';
import { launchChromium } from '../e2e/helpers/browser.js';
import { buildBenchCube } from './bench-cube.js';
import { benchArgs, datasets, median, root, type Dataset } from './datasets.js';
import { gzipSiblings } from './gzip-siblings.js';
import { logResponses, type Sent } from './response-log.js';
import { toMapLibreView, type LngLatView, type ProjectedView } from './scale-zoom.js';
import { startQuery, writeSessionPages, type FirstMap, type FrameResult } from './session-pages.js';
import { printTable } from './table.js';
import { fitScale, scriptedSession, SESSION_HEIGHT as HEIGHT, SESSION_WIDTH as WIDTH } from './session-script.js';
import { PHONE_VIEW_PX } from '../format/pixel-size.js';
import { sessionNeeds } from './triangles-in-view.js';
import { buildTiles, tippecanoeVersion, TIPPECANOE_MISSING, writeWgs84GeoJson } from './tippecanoe-tiles.js';

const MAPLIBRE_FILES = ['maplibre-gl.mjs', 'maplibre-gl-shared.mjs', 'maplibre-gl-worker.mjs', 'maplibre-gl.css'];

interface PageBench {
  first: Promise<FirstMap>;
  frame(v: ProjectedView | LngLatView): Promise<FrameResult>;
}
declare const bench: PageBench;

interface RunResult {
  firstMs: number;
  /** The first map on a slow network (SLOW_NETWORK), ms; the bytes the page had before it, code and data. */
  slowFirstMs: number;
  slowBytesBeforeFirst: number;
  /** The responses the page had whole before that first map: ms from the navigation's start, bytes, path. */
  slowResponses: { ms: number; bytes: number; path: string }[];
  /** The same first map opened at each of the other start scales (`starts=`), in their order. */
  slowFirstAt: { ms: number; bytes: number }[];
  bytesBeforeFirst: number;
  /** Data bytes sent up to each frame's completion. */
  bytesSoFar: number[];
  frames: FrameResult[];
  /** Everything sent that is not data (the page, the library), bytes. */
  codeBytes: number;
  /** Data bytes for the session, and before the first map, by kind of file (`fileKind`). */
  byKind: Map<string, number>;
  byKindBeforeFirst: Map<string, number>;
}

/** What a cube's file holds, from its name (docs/FORMAT.md, "Cube directory"). */
const CUBE_FILE_KINDS: [RegExp, string][] = [
  [/\/c-[^/]*$/, 'surface chunks'],
  [/\/b-[^/]*$/, 'floor chunks'],
  [/\/l-[^/]*$/, 'line chunks'],
  [/\/(index\.json|i-[^/]*)$/, 'index'],
  [/\/f-[^/]*$/, 'face tables'],
  [/\/a-[^/]*$/, 'attributes'],
];
/** Lighthouse's "Slow 4G" as Chromium's DevTools throttle it: latency added per request, throughput in bytes/s. */
const SLOW_NETWORK = { offline: false, latency: 150, downloadThroughput: (1.6e6 * 0.9) / 8, uploadThroughput: (750e3 * 0.9) / 8 };

const fileKind = (p: string): string => CUBE_FILE_KINDS.find(([re]) => re.test(p.split('?')[0]!))?.[1] ?? 'other';

interface OpenPage {
  context: BrowserContext;
  page: Page;
  first: FirstMap;
  /** Errors the page threw or logged. */
  problems: string[];
  /** When the browser had each response whole (ms since the epoch), by request path, in order. */
  arrivals: { path: string; at: number }[];
}

/** A page's size, CSS px. */
interface Viewport {
  width: number;
  height: number;
}

const SESSION_VIEWPORT: Viewport = { width: WIDTH, height: HEIGHT };

/** A first view of bench:session, and the size of the page it opens in. */
interface Start<V> {
  view: V;
  viewport: Viewport;
}

/** Opens `url` in a fresh context (an empty cache; on `network`'s conditions when given) up to its first complete map; `log` starts empty. */
async function openToFirstMap(browser: Browser, url: string, log: Sent[], network?: typeof SLOW_NETWORK, viewport = SESSION_VIEWPORT): Promise<OpenPage> {
  const context = await browser.newContext({ viewport });
  try {
    const page = await context.newPage();
    const problems: string[] = [];
    const arrivals: { path: string; at: number }[] = [];
    // Playwright's request start (wall clock) plus its end (from when the request was issued):
    // late by the request's queueing in the browser, a few ms.
    page.on('requestfinished', (r) => {
      const t = r.timing(), u = new URL(r.url());
      if (t.responseEnd >= 0) arrivals.push({ path: u.pathname + u.search, at: t.startTime + t.responseEnd });
    });
    page.on('pageerror', (e) => problems.push(e.message));
    page.on('console', (m) => {
      if (m.type() === 'error') problems.push(m.text());
    });
    if (network) {
      const cdp = await context.newCDPSession(page);
      await cdp.send('Network.enable');
      await cdp.send('Network.emulateNetworkConditions', network);
    }
    log.length = 0;
    await page.goto(url);
    await page.waitForFunction(() => typeof bench !== 'undefined');
    return { context, page, first: await page.evaluate(() => bench.first), problems, arrivals };
  } catch (err) {
    await context.close();
    throw err;
  }
}

/** Opens `page` in a fresh context (an empty cache), runs the session, and sums up the server's log. */
async function runPage(browser: Browser, url: string, views: (ProjectedView | LngLatView)[], starts: Start<ProjectedView | LngLatView>[], log: Sent[], isData: (p: string) => boolean): Promise<RunResult> {
  const { context, page, first, problems } = await openToFirstMap(browser, url, log);
  let session: Omit<RunResult, 'slowFirstMs' | 'slowBytesBeforeFirst' | 'slowResponses' | 'slowFirstAt'>;
  try {
    const frames = await page.evaluate(async (vs) => {
      const out: FrameResult[] = [];
      for (const v of vs) out.push(await bench.frame(v));
      return out;
    }, views);
    if (problems.length > 0) throw new Error(`${url}: ${problems.join('; ')}`);
    const end = frames[frames.length - 1]!.at;
    const dataByKind = (at: number): Map<string, number> => {
      const m = new Map<string, number>();
      for (const r of log) if (r.at <= at && isData(r.path)) m.set(fileKind(r.path), (m.get(fileKind(r.path)) ?? 0) + r.bytes);
      return m;
    };
    const dataUpTo = (at: number): number => [...dataByKind(at).values()].reduce((s, b) => s + b, 0);
    session = {
      firstMs: first.ms,
      bytesBeforeFirst: dataUpTo(first.at),
      bytesSoFar: frames.map((f) => dataUpTo(f.at)),
      frames,
      codeBytes: log.reduce((s, r) => s + (r.at <= end && !isData(r.path) ? r.bytes : 0), 0),
      byKind: dataByKind(end),
      byKindBeforeFirst: dataByKind(first.at),
    };
  } finally {
    await context.close();
  }
  // The slow first maps empty the log, so they come after the session's sums; and after its page
  // is closed, so that nothing of it runs beside them.
  const slow = await firstOnSlowNetwork(browser, url, log);
  const slowFirstAt: RunResult['slowFirstAt'] = [];
  for (const st of starts) {
    const other = await firstOnSlowNetwork(browser, url + startQuery(st.view), log, st.viewport);
    slowFirstAt.push({ ms: other.slowFirstMs, bytes: other.slowBytesBeforeFirst });
  }
  return { ...session, ...slow, slowFirstAt };
}

/** The page opened in a fresh context on SLOW_NETWORK, to its first complete map. */
async function firstOnSlowNetwork(browser: Browser, url: string, log: Sent[], viewport?: Viewport): Promise<Pick<RunResult, 'slowFirstMs' | 'slowBytesBeforeFirst' | 'slowResponses'>> {
  const { context, first, problems, arrivals } = await openToFirstMap(browser, url, log, SLOW_NETWORK, viewport);
  try {
    if (problems.length > 0) throw new Error(`${url} on a slow network: ${problems.join('; ')}`);
    // Each response the server sent, with when the browser had it whole (the next arrival of its
    // path); one the browser never finished (still coming at the first map, or aborted) counts as
    // not had.
    const pending = [...arrivals];
    const came = log.map((r) => {
      const k = pending.findIndex((a) => a.path === r.path);
      const at = k < 0 ? Infinity : pending.splice(k, 1)[0]!.at;
      return { ...r, at };
    }).sort((a, b) => a.at - b.at);
    const before = came.filter((r) => r.at <= first.at);
    const start = first.at - first.ms;
    return {
      slowFirstMs: first.ms,
      slowBytesBeforeFirst: before.reduce((s, r) => s + r.bytes, 0),
      slowResponses: before.map((r) => ({ ms: r.at - start, bytes: r.bytes, path: r.path })),
    };
  } finally {
    await context.close();
  }
}

const mb = (b: number): string => `${(b / 1e6).toFixed(2)} MB`;
const ratio = (a: number, b: number): string => `${(a / b).toFixed(2)}x`;

/** A first view of bench:session: a factor of the start's scale, or the whole extent (1280x720, or a phone's). */
type StartAt = number | 'extent' | 'phone';

async function runDataset(browser: Browser, d: Dataset, runs: number, zoomOutFrames: number, startFactors: StartAt[], csv: string[], waterfall: boolean): Promise<void> {
  const tmp = await mkdtemp(path.join(tmpdir(), 'ssc-bench-session-'));
  try {
    const site = path.join(tmp, 'site');
    await mkdir(site);
    const cube = buildBenchCube(d, path.join(site, 'cube'));
    const meta = cube.index.meta;
    if (!meta.proj4) throw new Error(`${d.name}: the cube's index has no proj4 definition, so MapLibre's view cannot be placed`);
    const style = await loadStyle(d.style);
    const classProperty = style.classProperty;
    if (classProperty === null) throw new Error(`${d.style}: the style has no classProperty to colour the tiles by`);
    const toLngLat = toMapLibreView(meta.proj4, WIDTH, meta.pixelSizeMm);
    const s = scriptedSession(meta, zoomOutFrames);
    // The other first views: the session's start, zoomed out by each factor.
    const phone: Viewport = { width: PHONE_VIEW_PX[0], height: PHONE_VIEW_PX[1] };
    const starts: Start<ProjectedView>[] = startFactors.map((f) => ({
      view: { center: s.start.center, scale: f === 'extent' ? s.fullScale : f === 'phone' ? fitScale(meta, phone.width, phone.height) : s.start.scale * f },
      viewport: f === 'phone' ? phone : SESSION_VIEWPORT,
    }));
    const proj4Def = meta.proj4;
    const mapLibreStarts = starts.map((st) => ({ ...st, view: toMapLibreView(proj4Def, st.viewport.width, meta.pixelSizeMm)(st.view) }));
    // MapLibre draws a 512-px vector source's tiles of floor(zoom): the tiles span the zooms
    // the session shows, the highest holding the full detail.
    const zooms = [s.start, ...starts.map((st) => st.view), ...s.frames.map((f) => f.view)].map((v) => toLngLat(v).zoom);
    const geojson = path.join(tmp, `${d.name}.wgs84.geojson`);
    await writeWgs84GeoJson(d.file, classProperty, geojson);
    process.stderr.write(`tiling ${d.name}... `);
    const t0 = performance.now();
    const tiles = await buildTiles(geojson, path.join(site, 'tiles'), Math.floor(Math.min(...zooms)), Math.floor(Math.max(...zooms)));
    process.stderr.write(`${((performance.now() - t0) / 1000).toFixed(1)} s\n`);
    await cp(path.join(root, 'dist/lib'), path.join(site, 'lib'), { recursive: true });
    await mkdir(path.join(site, 'maplibre'));
    for (const f of MAPLIBRE_FILES) await cp(path.join(root, 'node_modules/maplibre-gl/dist', f), path.join(site, 'maplibre', f));
    await writeSessionPages(site, s.start, toLngLat(s.start), { ...style, classProperty }, tiles);
    const gz = await gzipSiblings(site, ['cube', 'tiles']);
    const needs = await sessionNeeds(cube.dir, [s.start, ...s.frames.map((f) => f.view)].map((v) => ({ scale: v.scale, centre: v.center })), async (f) => (await stat(path.join(cube.dir, `${f}.gz`))).size, WIDTH, HEIGHT);

    const server = createStaticServer({ root: site });
    const log = logResponses(server.server);
    await server.listen(0, '127.0.0.1');
    const results: { vario: RunResult[]; maplibre: RunResult[] } = { vario: [], maplibre: [] };
    try {
      for (let r = 0; r < runs; r++) {
        // Turn about, so that neither map always runs on a machine the other has just warmed.
        for (const which of r % 2 === 0 ? (['vario', 'maplibre'] as const) : (['maplibre', 'vario'] as const)) {
          const views = which === 'vario' ? s.frames.map((f) => f.view) : s.frames.map((f) => toLngLat(f.view));
          const prefix = which === 'vario' ? '/cube/' : '/tiles/';
          const res = await runPage(browser, `${server.url}${which}.html`, views, which === 'vario' ? starts : mapLibreStarts, log, (p) => p.startsWith(prefix));
          results[which].push(res);
          process.stderr.write(`  ${d.name} run ${r + 1} ${which}: first map ${res.firstMs.toFixed(0)} ms, ${mb(res.bytesSoFar[res.bytesSoFar.length - 1]!)}, frame median ${median(res.frames.map((f) => f.ms)).toFixed(0)} ms\n`);
        }
      }
    } finally {
      await server.close();
    }

    const n = s.frames.length;
    /** Per frame, the median over the runs. */
    const perFrame = (rs: RunResult[], f: (r: RunResult, i: number) => number | null): (number | null)[] =>
      Array.from({ length: n }, (_, i) => {
        const xs = rs.map((r) => f(r, i)).filter((x): x is number => x !== null);
        return xs.length === 0 ? null : median(xs);
      });
    const sum = (which: 'vario' | 'maplibre'): { total: number; beforeFirst: number; frameMs: number; meanFrameMs: number; firstMs: number; slowFirstMs: number; slowBytes: number; code: number; ms: (number | null)[]; bytes: (number | null)[]; tri: (number | null)[] } => {
      const rs = results[which];
      const ms = perFrame(rs, (r, i) => r.frames[i]!.ms);
      return {
        total: median(rs.map((r) => r.bytesSoFar[n - 1]!)),
        beforeFirst: median(rs.map((r) => r.bytesBeforeFirst)),
        frameMs: median(ms.filter((x): x is number => x !== null)),
        // 'complete' (and MapLibre's 'idle') come when a frame's drawing is issued; a software GPU
        // may still be running it, and the next frame's first GL calls then wait for it. The
        // session's whole time per frame counts that wait wherever it falls; a median may not.
        meanFrameMs: median(rs.map((r) => r.frames.reduce((t, f) => t + f.ms, 0) / n)),
        firstMs: median(rs.map((r) => r.firstMs)),
        slowFirstMs: median(rs.map((r) => r.slowFirstMs)),
        slowBytes: median(rs.map((r) => r.slowBytesBeforeFirst)),
        code: median(rs.map((r) => r.codeBytes)),
        ms,
        bytes: perFrame(rs, (r, i) => r.bytesSoFar[i]!),
        tri: perFrame(rs, (r, i) => r.frames[i]!.triangles),
      };
    };
    const v = sum('vario'), m = sum('maplibre');
    process.stdout.write(`\n${d.name}: ${n} frames (${s.frames.filter((f) => f.phase === 'zoom out').length} out from 1:${Math.round(s.start.scale)}, pan, in), ${WIDTH}x${HEIGHT}, median of ${runs} run${runs > 1 ? 's' : ''}, gzip for both\n`);
    printTable([
      ['', 'vario map', 'MapLibre + tippecanoe', 'ratio'],
      ['data bytes for the session', mb(v.total), mb(m.total), ratio(v.total, m.total)],
      ['data bytes before the first map', mb(v.beforeFirst), mb(m.beforeFirst), ratio(v.beforeFirst, m.beforeFirst)],
      ['median time from setView to a complete frame', `${v.frameMs.toFixed(0)} ms`, `${m.frameMs.toFixed(0)} ms`, ratio(v.frameMs, m.frameMs)],
      ["the session's time per frame (mean)", `${v.meanFrameMs.toFixed(0)} ms`, `${m.meanFrameMs.toFixed(0)} ms`, ratio(v.meanFrameMs, m.meanFrameMs)],
      ['first complete map after navigation', `${(v.firstMs / 1000).toFixed(2)} s`, `${(m.firstMs / 1000).toFixed(2)} s`, ratio(v.firstMs, m.firstMs)],
      ['code bytes (page, library, workers)', mb(v.code), mb(m.code), ratio(v.code, m.code)],
      ['first complete map on a slow network', `${(v.slowFirstMs / 1000).toFixed(2)} s`, `${(m.slowFirstMs / 1000).toFixed(2)} s`, ratio(v.slowFirstMs, m.slowFirstMs)],
      ['bytes before it (code and data)', mb(v.slowBytes), mb(m.slowBytes), ratio(v.slowBytes, m.slowBytes)],
    ]);
    const phases = [...new Set(s.frames.map((f) => f.phase))];
    const rows = [['phase', 'frames', 'vario ms', 'MapLibre ms', 'vario triangles', 'MapLibre triangles', 'vario MB at end', 'MapLibre MB at end']];
    for (const p of phases) {
      const idx = s.frames.flatMap((f, i) => (f.phase === p ? [i] : []));
      const med = (xs: (number | null)[]): string => {
        const got = idx.map((i) => xs[i]).filter((x): x is number => x !== null && x !== undefined);
        return got.length === 0 ? '-' : Math.round(median(got)).toString();
      };
      const last = idx[idx.length - 1]!;
      rows.push([p, String(idx.length), med(v.ms), med(m.ms), med(v.tri), med(m.tri), (v.bytes[last]! / 1e6).toFixed(2), (m.bytes[last]! / 1e6).toFixed(2)]);
    }
    printTable(rows);
    if (starts.length > 0) {
      const medianAt = (rs: RunResult[], k: number, f: (a: { ms: number; bytes: number }) => number): number => median(rs.map((r) => f(r.slowFirstAt[k]!)));
      printTable([
        ['first complete map on a slow network, opened at', 'vario map', 'MapLibre + tippecanoe', 'ratio', 'vario bytes before it', 'MapLibre bytes before it', 'ratio'],
        ...starts.map((st, k) => {
          const varioMs = medianAt(results.vario, k, (a) => a.ms), mapLibreMs = medianAt(results.maplibre, k, (a) => a.ms);
          const varioBytes = medianAt(results.vario, k, (a) => a.bytes), mapLibreBytes = medianAt(results.maplibre, k, (a) => a.bytes);
          const f = startFactors[k];
          const at = f === 'extent' ? 'the whole extent, the default view' : f === 'phone' ? `the whole extent in a ${st.viewport.width}x${st.viewport.height} page` : `${f}x the start`;
          return [`1:${Math.round(st.view.scale).toLocaleString('en')} (${at})`, `${(varioMs / 1000).toFixed(2)} s`, `${(mapLibreMs / 1000).toFixed(2)} s`, ratio(varioMs, mapLibreMs), mb(varioBytes), mb(mapLibreBytes), ratio(varioBytes, mapLibreBytes)];
        }),
      ]);
    }
    const kinds = CUBE_FILE_KINDS.map(([, k]) => k).concat('other');
    const byKind = (f: (r: RunResult) => Map<string, number>): string =>
      kinds.map((k) => [k, median(results.vario.map((r) => f(r).get(k) ?? 0))] as const).filter(([, b]) => b > 0).map(([k, b]) => `${k} ${mb(b)}`).join(', ');
    process.stdout.write(`vario data bytes by kind of file: session ${byKind((r) => r.byKind)}; before the first map ${byKind((r) => r.byKindBeforeFirst)}\n`);
    process.stdout.write(`surface chunks the session's views query (each once, no margin): ${mb(needs.queriedBytes)}; their share that some view needs: ${mb(needs.neededBytes)}, of which some view's slice cuts ${mb(needs.cutBytes)} (the rest lies at or below every slice that needs it)\n`);
    process.stdout.write(`whole dataset, gzip: cube ${mb(gz.get('cube')!)}, tiles (z${tiles.minZoom}-${tiles.maxZoom}) ${mb(gz.get('tiles')!)}, ratio ${ratio(gz.get('cube')!, gz.get('tiles')!)}\n`);
    process.stdout.write(`tiles: ${tiles.command}\n`);
    if (waterfall) {
      for (const which of ['vario', 'maplibre'] as const) {
        const last = results[which][runs - 1]!;
        process.stdout.write(`${which}, last run, slow network: responses the page had before the first map (${(last.slowFirstMs / 1000).toFixed(2)} s)\n`);
        for (const r of last.slowResponses) process.stdout.write(`  ${(r.ms / 1000).toFixed(2)} s ${(r.bytes / 1000).toFixed(1).padStart(7)} kB  ${r.path}\n`);
      }
    }
    for (let i = 0; i < n; i++) {
      const f = s.frames[i]!;
      const cell = (x: number | null | undefined): string => (x === null || x === undefined ? '' : String(Math.round(x)));
      csv.push([d.name, i + 1, f.phase, Math.round(f.view.scale), cell(v.bytes[i]), cell(m.bytes[i]), cell(v.ms[i]), cell(m.ms[i]), cell(v.tri[i]), cell(m.tri[i])].join(','));
    }
  } finally {
    await rm(tmp, { recursive: true, force: true });
  }
}

async function main(): Promise<void> {
  const version = tippecanoeVersion();
  if (version === null) {
    process.stderr.write(`${TIPPECANOE_MISSING}\n`);
    process.exit(1);
  }
  const { runs, filter } = benchArgs(3);
  const args = process.argv.slice(2);
  const frames = Number(args.find((a) => a.startsWith('frames='))?.slice(7) ?? 120);
  if (!Number.isInteger(frames) || frames < 1) throw new Error('frames= takes a whole number >= 1');
  const csvFile = args.find((a) => a.startsWith('csv='))?.slice(4);
  const startsArg = args.find((a) => a.startsWith('starts='))?.slice(7) ?? '1.414,4,extent,phone';
  const startFactors: StartAt[] = startsArg === '' ? [] : startsArg.split(',').map((w) => (w === 'extent' || w === 'phone' ? w : Number(w)));
  if (startFactors.some((f) => typeof f === 'number' && !(f > 0))) throw new Error(`starts=${startsArg}: a comma-separated list of factors > 0 (of the start's scale), "extent" or "phone", or nothing`);
  const sets = datasets(filter?.includes('=') || filter === 'waterfall' ? undefined : filter, ['bgt_otterlo_1800m', 'nlcd_zion']);
  process.stderr.write(`${version}\n`);
  const csv = ['dataset,frame,phase,scale,vario bytes so far,maplibre bytes so far,vario ms,maplibre ms,vario triangles,maplibre triangles'];
  const browser = await launchChromium();
  try {
    for (const d of sets) await runDataset(browser, d, runs, frames, startFactors, csv, args.includes('waterfall'));
  } finally {
    await browser.close();
  }
  if (csvFile) await writeFile(csvFile, `${csv.join('\n')}\n`);
}

main().catch((err: unknown) => {
  console.error(err);
  process.exit(1);
});
