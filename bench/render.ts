// npm run bench:render [-- <dataset filter>]: the WebGL2 client in headless Chromium at
// 1280x720, for bgt_otterlo_1800m and nlcd_zion at the base scale, a middle scale and the full
// extent. Per view: time from page load to the first complete map, frame time (median and p95
// over 60 frames of continuous redrawing, each frame a new view so the worker queries the
// index), triangles submitted per frame and those the view needs (triangles-in-view.ts), index
// query time per frame, the chunks and bytes the view needs, and GPU memory: the chunks' and
// the frame's targets' (those of overlays and lines only once they are drawn). Lines: segments submitted per
// frame, the line chunks' bytes, and the frame time with the lines hidden, measured in turns
// with the lines shown on the same page; in a third turn every triangle of the chunks is drawn,
// as before draw runs, for comparison. Cubes are built fresh (ssc build) and served by the
// project's static server.
// SwiftShader is a software GPU: the numbers compare versions on one machine, nothing more.
import { execFile } from 'node:child_process';
import path from 'node:path';
import { promisify } from 'node:util';
import { CubeReader } from '../preprocess/ssc/read-cube.js';
import { launchChromium } from '../e2e/helpers/browser.js';
import { withClientSite } from './client-site.js';
import { datasets, median, root } from './datasets.js';
import { linesInView } from './lines-in-view.js';
import { printTable } from './table.js';
import { trianglesInView } from './triangles-in-view.js';

const run = promisify(execFile);
const WIDTH = 1280, HEIGHT = 720, FRAMES = 60, WARMUP = 5;
/** Frame time with and without lines: this many turns of each, FRAMES / TURNS frames a turn. */
const TURNS = 3;

/** The test page's map (a VarioMap) and its engine (engineOf(map)), as the page has them. */
interface PageMap {
  whenIdle(): Promise<{ complete: boolean }>;
  getCenterProjected(): [number, number];
  jumpTo(v: { centerProjected: [number, number] }): void;
  getMetadata(): unknown;
  setLinesVisible(v: boolean): void;
}
interface PageEngine {
  firstCompleteAt: number | null;
  redraw(): void;
  on(t: 'render', f: (s: Stats) => void): void;
  off(t: 'render', f: (s: Stats) => void): void;
  neededChunks(): { visible: string[]; margin: string[] };
  setWholeChunks(whole: boolean): void;
  stats(): { gpuBytes: number; targetBytes: number };
}
interface Stats { triangles: number; segments: number; queryMs: number }
declare const map: PageMap;
declare const engine: PageEngine;

function p95(xs: number[]): number {
  const s = [...xs].sort((a, b) => a - b);
  return s[Math.min(s.length - 1, Math.ceil(0.95 * s.length) - 1)]!;
}

async function main(): Promise<void> {
  const filter = process.argv[2];
  const sets = datasets(filter, ['bgt_otterlo_1800m', 'nlcd_zion']);
  const browser = await launchChromium();
  const rows: string[][] = [['dataset', 'view', 'scale', 'first map ms', 'frame ms median', 'frame ms p95', 'no lines ms', 'whole chunks ms', 'triangles/frame', 'whole chunks', 'needed in view', 'ID fragments/px', 'GPU MB', 'targets MB', 'at 5 places', 'segments/frame', 'line vertices in view', 'query ms/frame', 'chunks', 'MB', 'line MB', 'long tasks load', 'long tasks frames']];
  const ratios: string[] = [];
  try {
    for (const d of sets) {
      await withClientSite('ssc-bench-', async ({ dir, url }) => {
        process.stderr.write(`building ${d.name}...\n`);
        await run(process.execPath, [path.join(root, 'bin/ssc.js'), 'build', d.file, '--style', d.style, '--out', path.join(dir, 'cube'), '--quiet'], { maxBuffer: 1 << 26 });
        const reader = await CubeReader.open(path.join(dir, 'cube'));
        const index = reader.index;
        // Every chunk's bytes, the floor's too, through the sub-index files.
        const all = [...(await reader.loadAll()), ...(index.floor ? await reader.loadAll(index.floor.root) : [])];
        const leafBytes = new Map(all.map((l) => [l.file, l.bytes]));
        const lineBytes = new Map((index.lines ?? []).map((l) => [l.file, l.bytes]));
        const meta = index.meta;
        const [x0, y0, x1, y1] = meta.extent;
        const centre: [number, number] = [(x0 + x1) / 2, (y0 + y1) / 2];
        const full = (Math.max((x1 - x0) / WIDTH, (y1 - y0) / HEIGHT) * 1000) / meta.pixelSizeMm;
        const views: [string, number][] = [['base', meta.baseScale], ['middle', Math.sqrt(meta.baseScale * full)], ['extent', full]];
        const triangleMeans: number[] = [];
        const neededIn = await trianglesInView(path.join(dir, 'cube'));
        for (const [name, scale] of views) {
          const context = await browser.newContext({ viewport: { width: WIDTH, height: HEIGHT } });
          const page = await context.newPage();
          // Main-thread tasks over 50 ms, from the first script on: loading must not freeze the page.
          await page.addInitScript(() => {
            const g = globalThis as unknown as { longTasks: number[] };
            g.longTasks = [];
            new PerformanceObserver((list) => {
              for (const e of list.getEntries()) g.longTasks.push(e.duration);
              // Node's types know no 'longtask'; this function runs in the page, where it exists.
            }).observe({ type: 'longtask' as never, buffered: true });
          });
          const errors: string[] = [];
          page.on('pageerror', (e) => errors.push(e.message));
          await page.goto(`${url}index.html?source=cube/&center=${centre.join(',')}&scale=${scale}&supersampling=1`);
          await page.waitForFunction(() => typeof map !== 'undefined' && map.getMetadata() !== null);
          await page.evaluate(() => map.whenIdle());
          const firstMs = await page.evaluate(() => engine.firstCompleteAt);
          // The chunks on the GPU once the view is complete (with its margin and what lies ahead).
          const { gpuBytes, targetBytes } = await page.evaluate(() => engine.stats());
          const gpuMb = gpuBytes / 1e6, targetMb = targetBytes / 1e6;
          const longLoad = await page.evaluate(() => (globalThis as unknown as { longTasks: number[] }).longTasks.splice(0));
          // At the floor the cube's chunks are the margin, known once its sub-index files have
          // come, which they do after the floor chunks on screen: the map can be idle before.
          if (name === 'base') await page.waitForFunction(() => engine.neededChunks().margin.length > 0, null, { timeout: 10_000 });
          const needed = await page.evaluate(() => engine.neededChunks());
          const files = [...needed.visible, ...needed.margin];
          const bytes = files.reduce((s, f) => s + (leafBytes.get(f) ?? 0), 0);
          const lineMb = files.reduce((s, f) => s + (lineBytes.get(f) ?? 0), 0) / 1e6;
          /** n frames in a row, each a new view; the first `warmup` are dropped. */
          const frames = (n: number, warmup: number, lines: boolean, whole = false): Promise<{ ms: number[]; stats: Stats[] }> => page.evaluate(
            ([n, warmup, lines, whole]) =>
              new Promise<{ ms: number[]; stats: Stats[] }>((resolve) => {
                map.setLinesVisible(lines);
                engine.setWholeChunks(whole);
                const out: { t: number; s: Stats }[] = [];
                const [cx, cy] = map.getCenterProjected();
                const f = (s: Stats): void => {
                  out.push({ t: performance.now(), s: { triangles: s.triangles, segments: s.segments, queryMs: s.queryMs } });
                  if (out.length >= n + warmup + 1) {
                    engine.off('render', f);
                    const kept = out.slice(warmup);
                    resolve({ ms: kept.slice(1).map((k, i) => k.t - kept[i]!.t), stats: kept.map((k) => k.s) });
                    return;
                  }
                  // A new view every frame (a millimetre pan): a full redraw and an index query.
                  map.jumpTo({ centerProjected: [cx + (out.length % 2) * 1e-3, cy] });
                };
                engine.on('render', f);
                engine.redraw();
              }),
            [n, warmup, lines, whole] as const,
          );
          const frameMs: number[] = [], noLinesMs: number[] = [], wholeMs: number[] = [];
          const kept: Stats[] = [], wholeStats: Stats[] = [];
          for (let t = 0; t < TURNS; t++) {
            const on = await frames(FRAMES / TURNS, t === 0 ? WARMUP : 2, true);
            frameMs.push(...on.ms);
            kept.push(...on.stats);
            noLinesMs.push(...(await frames(FRAMES / TURNS, 2, false)).ms);
            // Every triangle of the chunks, as before draw runs: what they save, on this page.
            const whole = await frames(FRAMES / TURNS, 2, true, true);
            wholeMs.push(...whole.ms);
            wholeStats.push(...whole.stats);
          }
          await page.evaluate(() => engine.setWholeChunks(false));
          await page.evaluate(() => map.setLinesVisible(true));
          const longFrames = await page.evaluate(() => (globalThis as unknown as { longTasks: number[] }).longTasks.splice(0));
          const fmt = (xs: number[]): string => (xs.length === 0 ? '0' : `${xs.length} (max ${Math.round(Math.max(...xs))} ms)`);
          // One place can sit where chunks meet; the mean over the centre and four places
          // around it says what a view at this scale usually draws.
          const placed: number[] = [];
          for (const [fx, fy] of [[0.5, 0.5], [0.25, 0.25], [0.75, 0.25], [0.25, 0.75], [0.75, 0.75]] as const) {
            const c: [number, number] = [x0 + fx * (x1 - x0), y0 + fy * (y1 - y0)];
            placed.push(await page.evaluate(
              (at) => new Promise<number>((resolve) => {
                const f = (st: { triangles: number }): void => {
                  engine.off('render', f);
                  resolve(st.triangles);
                };
                map.jumpTo({ centerProjected: at });
                void map.whenIdle().then(() => {
                  engine.on('render', f);
                  engine.redraw();
                });
              }),
              c,
            ));
          }
          triangleMeans.push(placed.reduce((a, b) => a + b, 0) / placed.length);
          const lineVertices = await linesInView(path.join(dir, 'cube'), index, scale, centre);
          const { triangles: neededTriangles, fragmentsPerPixel } = await neededIn(scale, centre);
          const drawn = median(kept.map((s) => s.triangles));
          ratios.push(`${d.name} ${name}: triangles drawn / needed in view: ${(drawn / Math.max(1, neededTriangles)).toFixed(2)}`);
          rows.push([
            d.name, name, `1:${Math.round(scale)}`,
            firstMs === null ? 'never' : firstMs.toFixed(0),
            median(frameMs).toFixed(1), p95(frameMs).toFixed(1), median(noLinesMs).toFixed(1), median(wholeMs).toFixed(1),
            Math.round(drawn).toString(), Math.round(median(wholeStats.map((s) => s.triangles))).toString(), String(neededTriangles),
            fragmentsPerPixel.toFixed(2), gpuMb.toFixed(1), targetMb.toFixed(1),
            Math.round(triangleMeans[triangleMeans.length - 1]!).toString(),
            Math.round(median(kept.map((s) => s.segments))).toString(), String(lineVertices),
            median(kept.map((s) => s.queryMs)).toFixed(2),
            String(files.length), (bytes / 1e6).toFixed(2), lineMb.toFixed(2),
            fmt(longLoad), fmt(longFrames),
          ]);
          process.stderr.write(`${rows[rows.length - 1]!.join('  ')}\n`);
          if (errors.length > 0) throw new Error(`page errors: ${errors.join('; ')}`);
          await context.close();
        }
        ratios.push(`${d.name}: triangles per frame (mean of 5 places), largest / smallest over the three scales: ${(Math.max(...triangleMeans) / Math.min(...triangleMeans)).toFixed(2)}`);
      });
    }
  } finally {
    await browser.close();
  }
  printTable(rows);
  for (const r of ratios) process.stdout.write(`${r}\n`);
}

main().catch((err: unknown) => {
  console.error(err);
  process.exit(1);
});
