// npm run bench:build [-- <name filter>] [runs=N]: generalize + build for the four datasets,
// each run in a fresh process (medians), then what the cube holds (ssc inspect) and how long
// an index query takes, also for a cube cut into about 10,000 chunks.
import { spawnSync } from 'node:child_process';
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { groundPerScale } from '../format/pixel-size.js';
import { zAtScale } from '../format/scale.js';
import { wholeExtentScale } from '../preprocess/ssc/view-hit-chance.js';
import { inspectCube } from '../preprocess/ssc/inspect-cube.js';
import { CubeReader } from '../preprocess/ssc/read-cube.js';
import { benchArgs, datasets, median, root } from './datasets.js';
import { viewBox } from './triangles-in-view.js';

const { runs, filter } = benchArgs(3);
// Before any work: a missing dataset or a filter matching none is an error at once.
const sets = datasets(filter);
const dir = mkdtempSync(path.join(tmpdir(), 'ssc-bench-'));
const kb = (b: number): string => `${(b / 1024).toFixed(1)} KiB`;

function buildRun(file: string, style: string, out: string, chunkBytes?: number): { ms: number; generalizeMs: number; buildMs: number; maxRssMB: number } {
  const r = spawnSync(process.execPath, [path.join(root, 'dist/bench/child-run.js'), 'build', file, style, out, ...(chunkBytes ? [String(chunkBytes)] : [])], { encoding: 'utf8', maxBuffer: 1 << 24 });
  if (r.status !== 0) throw new Error(r.stderr);
  return JSON.parse(r.stdout.trim().split('\n').pop()!);
}

/** Median time of index queries for random 1280x720 views at random scales (all sub-indexes loaded). */
async function queryTime(cubeDir: string): Promise<{ chunks: number; medianUs: number; p99Us: number; hits: number }> {
  const cube = await CubeReader.open(cubeDir);
  const all = (await cube.loadAll()).length;
  const meta = cube.index.meta;
  const [x0, y0, x1, y1] = meta.extent;
  let seed = 12345;
  const rnd = (): number => ((seed = (seed * 1103515245 + 12345) % 2147483648) / 2147483648);
  const sFull = wholeExtentScale({ extent: meta.extent, viewPerScale: groundPerScale(1280, 720) });
  const times: number[] = [];
  let hits = 0;
  for (let i = 0; i < 2000; i++) {
    const scale = meta.baseScale * Math.pow(sFull / meta.baseScale, rnd());
    const z = zAtScale(meta, scale);
    const cx = x0 + rnd() * (x1 - x0), cy = y0 + rnd() * (y1 - y0);
    const ground = viewBox(scale, [cx, cy], 1280, 720);
    const t = performance.now();
    const leaves = cube.queryLoaded({ ground, zMin: z, zMax: z });
    times.push((performance.now() - t) * 1000);
    hits += leaves.length;
  }
  times.sort((a, b) => a - b);
  return { chunks: all, medianUs: median(times), p99Us: times[Math.floor(times.length * 0.99)]!, hits: hits / times.length };
}

console.log(`bench:build, ${runs} runs each (median), node ${process.version}`);
for (const d of sets) {
  const out = path.join(dir, d.name);
  const rs = [];
  for (let i = 0; i < runs; i++) rs.push(buildRun(d.file, d.style, out));
  const rep = await inspectCube(out);
  const q = await queryTime(out);
  console.log(`\n${d.name}: generalize + build ${(median(rs.map((r) => r.ms)) / 1000).toFixed(1)} s (generalize ${(median(rs.map((r) => r.generalizeMs)) / 1000).toFixed(1)} s, build ${(median(rs.map((r) => r.buildMs)) / 1000).toFixed(1)} s), peak ${median(rs.map((r) => r.maxRssMB)).toFixed(0)} MB`);
  console.log(`  chunks ${rep.chunks}, triangles ${rep.triangles}, bytes ${kb(rep.bytes.total)} (min ${kb(rep.bytes.min)}, median ${kb(rep.bytes.median)}, max ${kb(rep.bytes.max)}, CV ${rep.bytes.cv.toFixed(3)})`);
  console.log(`  chunked / unchunked ${rep.overhead.toFixed(4)}; index depth ${rep.index.depth}, ${rep.index.files} file(s), ${kb(rep.index.bytes)}`);
  console.log(`  index query: median ${q.medianUs.toFixed(1)} us, p99 ${q.p99Us.toFixed(1)} us over ${q.chunks} chunks (${q.hits.toFixed(1)} chunks per view)`);
  console.log(rep.lines ? `  line chunks ${rep.lines.chunks}, lines ${rep.lines.lines}, bytes ${kb(rep.lines.bytes)}` : '  no lines');
  console.log('  view 1280x720 (mean over 25 places): scale, z, chunks, triangles, bytes, lines, line bytes');
  for (const v of rep.views) console.log(`    1:${Math.round(v.scale)}  z ${v.z.toFixed(1)}  ${v.chunks.toFixed(1)}  ${v.triangles}  ${kb(v.bytes)}  ${v.lines}  ${kb(v.lineBytes)}`);
  console.log(`  max/min over the scales: triangles ${rep.viewRatio.triangles.toFixed(2)}, bytes ${rep.viewRatio.bytes.toFixed(2)}`);
  rmSync(out, { recursive: true, force: true });
}
// The index for a large cube: the largest dataset cut into about 10,000 chunks.
const big = sets[sets.length - 1];
if (big) {
  const out = path.join(dir, 'many');
  const probe = buildRun(big.file, big.style, out);
  const rep = await inspectCube(out);
  const small = Math.max(1024, Math.round(rep.bytes.total / 10000));
  buildRun(big.file, big.style, out, small);
  const q = await queryTime(out);
  console.log(`\n${big.name} in ${q.chunks} chunks of about ${kb(small)}: index query median ${q.medianUs.toFixed(1)} us, p99 ${q.p99Us.toFixed(1)} us (${q.hits.toFixed(1)} chunks per view); build ${(probe.ms / 1000).toFixed(1)} s`);
}
rmSync(dir, { recursive: true, force: true });
