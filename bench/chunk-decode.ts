// npm run bench:chunks [-- <dataset filter>] [runs=N]: the surface chunks' size and decoding
// (format/surface-file.ts, what the map's worker runs on every chunk it receives) over every
// chunk of a freshly built cube of bgt_otterlo_1800m and nlcd_zion, from bytes already in memory;
// the cube's chunks and its floor chunks (boundaries, cut by earcut) each in a row. Sizes:
// all chunk files raw and gzip (level 6, as the build precompresses them for serving). Each run
// decodes all chunks over and over for a quarter second; the table gives the median over the
// runs (and the slowest and fastest run's MB/s), and ms per MB of decoded (GPU-ready) vertices
// and indices, which stays comparable when the file format changes. A second table gives the
// chunks one 1280x720 view needs, centred, at the base scale, a middle scale and the full
// extent (bench:render's views): those whose box meets its ground box at its flat z, without
// the prefetch margin; their bytes raw and gzip; at the base scale the floor chunks as well.
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { gzipSync } from 'node:zlib';
import { EVERYWHERE, queryIndex, type QueryBox } from '../format/index-query.js';
import type { ChunkLeaf } from '../format/cube-index.js';
import { decodeSurfaceFile } from '../format/surface-file.js';
import { zAtScale } from '../format/scale.js';
import { buildBenchCube } from './bench-cube.js';
import { benchArgs, datasets } from './datasets.js';
import { median } from './stats.js';
import { printTable } from './table.js';

const RUN_MS = 250;
const { runs, filter } = benchArgs(7);
const sets = datasets(filter, ['bgt_otterlo_1800m', 'nlcd_zion']);
const dir = mkdtempSync(path.join(tmpdir(), 'ssc-bench-'));
const WIDTH = 1280, HEIGHT = 720;
const viewRows: string[][] = [['dataset', 'view', 'scale', 'chunks', 'MB', 'MB gzip']];
const rows: string[][] = [['dataset', 'kind', 'chunks', 'MB', 'MB gzip', 'triangles', 'passes/run', 'ms/pass', 'MB/s', 'ms/decoded MB', 'chunks/s', 'MB/s range']];
try {
  for (const d of sets) {
    const cube = buildBenchCube(d, path.join(dir, d.name));
    const floorRoot = cube.index.floor?.root;
    const floorLeaves = floorRoot ? queryIndex(floorRoot, EVERYWHERE, (r) => cube.subs.get(r)).leaves : [];
    // Each chunk in its own ArrayBuffer, as a fetch hands it over; and its gzip size.
    const bodies = new Map<string, ArrayBuffer>(), gzipped = new Map<string, number>();
    for (const l of [...cube.leaves, ...floorLeaves]) {
      const b = readFileSync(path.join(cube.dir, l.file));
      bodies.set(l.file, b.buffer.slice(b.byteOffset, b.byteOffset + b.byteLength));
      gzipped.set(l.file, gzipSync(b, { level: 6 }).byteLength);
    }
    const meta = cube.index.meta;
    const [x0, y0, x1, y1] = meta.extent;
    const full = (Math.max((x1 - x0) / WIDTH, (y1 - y0) / HEIGHT) * 1000) / meta.pixelSizeMm;
    const viewRow = (view: string, scale: number, leaves: ChunkLeaf[]): string[] => [
      d.name, view, `1:${Math.round(scale)}`, String(leaves.length),
      (leaves.reduce((s, l) => s + l.bytes, 0) / 1e6).toFixed(3), (leaves.reduce((s, l) => s + gzipped.get(l.file)!, 0) / 1e6).toFixed(3),
    ];
    for (const [name, scale] of [['base', meta.baseScale], ['middle', Math.sqrt(meta.baseScale * full)], ['extent', full]] as const) {
      // Ground units per pixel at this scale (the CRS in metres).
      const px = (scale * meta.pixelSizeMm) / 1000, cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
      const z = zAtScale(meta, scale);
      const q: QueryBox = { ground: [cx - (px * WIDTH) / 2, cy - (px * HEIGHT) / 2, cx + (px * WIDTH) / 2, cy + (px * HEIGHT) / 2], zMin: z, zMax: z };
      viewRows.push(viewRow(name, scale, queryIndex(cube.index.root, q, (r) => cube.subs.get(r)).leaves));
      if (floorRoot && z < cube.index.floor!.top) viewRows.push(viewRow(`${name}, floor chunks`, scale, queryIndex(floorRoot, q, (r) => cube.subs.get(r)).leaves));
    }
    for (const [kind, leaves] of [['cube', cube.leaves], ['floor', floorLeaves]] as const) {
      if (leaves.length === 0) continue;
      const list = leaves.map((l) => bodies.get(l.file)!);
      const bytes = list.reduce((s, b) => s + b.byteLength, 0);
      const gzipBytes = leaves.reduce((s, l) => s + gzipped.get(l.file)!, 0);
      // A run decodes every chunk, pass after pass, for at least RUN_MS (a pass alone can take
      // 2 ms, too short to time well); its rate is passes x bytes over its time.
      let triangles = 0, decoded = 0;
      const msPerPass: number[] = [];
      const passes: number[] = [];
      for (let run = -1; run < runs; run++) {
        // Run -1 warms the JIT up and is not counted.
        const t0 = performance.now();
        let n = 0, t = 0;
        do {
          t = 0;
          decoded = 0;
          for (const b of list) {
            const c = await decodeSurfaceFile(b);
            t += c.triangleCount;
            decoded += c.vertexByteLength + c.indices.byteLength;
          }
          n++;
        } while (performance.now() - t0 < RUN_MS);
        if (run >= 0) {
          msPerPass.push((performance.now() - t0) / n);
          passes.push(n);
        }
        triangles = t;
      }
      const mbs = msPerPass.map((m) => bytes / 1e6 / (m / 1000));
      const m = median(msPerPass);
      rows.push([
        d.name, kind, String(list.length), (bytes / 1e6).toFixed(2), (gzipBytes / 1e6).toFixed(2), String(triangles), String(median(passes)), m.toFixed(2),
        median(mbs).toFixed(0), (m / (decoded / 1e6)).toFixed(2), Math.round(list.length / (m / 1000)).toString(),
        `${Math.min(...mbs).toFixed(0)}..${Math.max(...mbs).toFixed(0)}`,
      ]);
    }
    rmSync(cube.dir, { recursive: true, force: true });
  }
} finally {
  rmSync(dir, { recursive: true, force: true });
}
console.log(`bench:chunks, chunk bytes and decoding over every chunk of the cube and every floor chunk, ${runs} runs (median), node ${process.version}`);
printTable(rows);
console.log('\nchunks one view needs (1280x720, centred, flat z; no prefetch margin)');
printTable(viewRows);
