// npm run bench:index [-- <dataset filter>] [runs=N]: queryIndex (format/index-query.ts, what the
// map's worker runs for every view) on the index trees of freshly built cubes of
// bgt_otterlo_1800m and nlcd_zion, each built twice: with the default chunk size, and with 8 KiB
// chunks for a tree of thousands of chunks in sub-index files (all loaded here). Views of three
// sizes at the base scale, a middle scale and the scale showing the whole extent, each at 1000
// places (the same every run) with a flat surface. Per query: chunks found and nodes visited
// (means), and microseconds (median and p99 of each run; the table gives their medians over runs).
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { queryIndex, type QueryBox } from '../format/index-query.js';
import { zAtScale } from '../format/scale.js';
import { buildBenchCube, type BenchCube } from './bench-cube.js';
import { benchArgs, datasets } from './datasets.js';
import { mean, median, percentile } from './stats.js';
import { printTable } from './table.js';

const PLACES = 1000;
const VIEWS: [number, number][] = [[1280, 720], [1920, 1080], [3840, 2160]];
const SMALL_CHUNKS = 8192;

const { runs, filter } = benchArgs(5);
const sets = datasets(filter, ['bgt_otterlo_1800m', 'nlcd_zion']);

/** A repeatable sequence in [0, 1) (mulberry32): every run and every version asks the same places. */
function random(seed: number): () => number {
  let a = seed;
  return () => {
    a = (a + 0x6d2b79f5) | 0;
    let t = Math.imul(a ^ (a >>> 15), 1 | a);
    t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

/** The queries for views of w x h pixels at `scale`, centred at PLACES places over the extent. */
function queries(cube: BenchCube, w: number, h: number, scale: number): QueryBox[] {
  const meta = cube.index.meta;
  const [x0, y0, x1, y1] = meta.extent;
  const z = zAtScale(meta, scale);
  const metresPerPixel = (meta.pixelSizeMm / 1000) * scale;
  const hw = (w / 2) * metresPerPixel, hh = (h / 2) * metresPerPixel;
  const rnd = random(12345);
  return Array.from({ length: PLACES }, () => {
    const cx = x0 + rnd() * (x1 - x0), cy = y0 + rnd() * (y1 - y0);
    return { ground: [cx - hw, cy - hh, cx + hw, cy + hh], zMin: z, zMax: z };
  });
}

function measure(cube: BenchCube, qs: QueryBox[]): { chunks: number; visited: number; medianUs: number; p99Us: number } {
  const loaded = (ref: string) => cube.subs.get(ref);
  const medians: number[] = [];
  const p99s: number[] = [];
  let chunks = 0, visited = 0;
  for (let run = -1; run < runs; run++) {
    // Run -1 warms the JIT up and is not counted.
    const us: number[] = [];
    const found: number[] = [];
    const nodes: number[] = [];
    for (const q of qs) {
      const t0 = performance.now();
      const r = queryIndex(cube.index.root, q, loaded);
      us.push((performance.now() - t0) * 1000);
      found.push(r.leaves.length);
      nodes.push(r.visited);
    }
    if (run < 0) continue;
    medians.push(median(us));
    p99s.push(percentile(us, 0.99));
    chunks = mean(found);
    visited = mean(nodes);
  }
  return { chunks, visited, medianUs: median(medians), p99Us: median(p99s) };
}

const dir = mkdtempSync(path.join(tmpdir(), 'ssc-bench-'));
const rows: string[][] = [['cube', 'chunks', 'sub-indexes', 'view', 'scale', 'z', 'chunks/query', 'nodes visited', 'median us', 'p99 us']];
try {
  for (const d of sets) {
    for (const chunkBytes of [undefined, SMALL_CHUNKS]) {
      const cube = buildBenchCube(d, path.join(dir, `${d.name}-${chunkBytes ?? 'default'}`), { chunkBytes });
      const meta = cube.index.meta;
      const [x0, y0, x1, y1] = meta.extent;
      for (const [w, h] of VIEWS) {
        const full = (Math.max((x1 - x0) / w, (y1 - y0) / h) * 1000) / meta.pixelSizeMm;
        for (const scale of [meta.baseScale, Math.sqrt(meta.baseScale * full), full]) {
          const r = measure(cube, queries(cube, w, h, scale));
          rows.push([
            cube.label, String(cube.leaves.length), String(cube.subs.size), `${w}x${h}`, `1:${Math.round(scale)}`, zAtScale(meta, scale).toFixed(0),
            r.chunks.toFixed(1), r.visited.toFixed(1), r.medianUs.toFixed(2), r.p99Us.toFixed(2),
          ]);
        }
      }
      rmSync(cube.dir, { recursive: true, force: true });
    }
  }
} finally {
  rmSync(dir, { recursive: true, force: true });
}
console.log(`bench:index, queryIndex at ${PLACES} places per row, ${runs} runs (median of each run's median and p99), node ${process.version}`);
printTable(rows);
