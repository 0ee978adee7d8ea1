// tGAP -> the cube directory (docs/FORMAT.md): surfaces, chunks, line chunks, face and
// attribute pages, the R-tree index, and a gzip and a brotli copy of every file. Written to a temporary directory
// and renamed into place, so a failed build leaves nothing behind.
import { createHash } from 'node:crypto';
import { promises as fs } from 'node:fs';
import path from 'node:path';
import { brotliCompressSync, constants as zc, gzipSync } from 'node:zlib';
import { encodeIndex, hashedName, INDEX_FORMAT, INDEX_VERSION, type ChunkLeaf, type CubeIndexJson, type LineChunkLeaf } from '../../format/cube-index.js';
import { groundPerScale, PHONE_VIEW_PX, PIXEL_SIZE_MM } from '../../format/pixel-size.js';
import { scaleAtZ, zAtScale } from '../../format/scale.js';
import { writeDirAtomic } from '../io/atomic-write.js';
import { proj4Definition } from '../io/crs-definition.js';
import { PHASES, scaleInfoOf, type Tgap } from '../../format/tgap-model.js';
import { assembleChunk } from './assemble-chunk.js';
import { chooseGrid, coarsestGrid } from './position-grid.js';
import { floorTop, planChunks } from './chunking.js';
import { wholeExtentScale } from './view-hit-chance.js';
import { floorChunks } from './floor-chunks.js';
import { encodeAttributePage, ATTRIBUTE_PAGE_SIZE } from '../../format/attribute-page.js';
import { encodeFacePage, FACE_PAGE_SIZE } from '../../format/face-page.js';
import { packTree, rootOutOfLine, splitTree } from './rtree-index.js';
import { buildSurfaces, type SurfaceStats } from './surfaces.js';
import { cubeLines, lineChunks } from './cube-lines.js';
import { parseStyle } from '../style.js';
import { lapTimer } from '../lap-timer.js';

/**
 * Target chunk size (decoded bytes; files are about a fifth of it). Measured with bench:session
 * (zoom out, pan and zoom in; gzip; the session's bytes, those before the first map, and the
 * first map's time against MapLibre's in the same run):
 * - bgt_otterlo_1800m (3 runs): 32 KiB 1.82 MB, 0.24 MB; 64 KiB 1.81 MB, 0.30 MB; 96 KiB
 *   1.91 MB, 0.45 MB; 128 KiB 1.94 MB, 0.54 MB. The first map 0.85x to 0.95x at every size.
 * - nlcd_zion (1 run): 32 KiB 5.27 MB, 0.90 MB, first map 1.12x; 64 KiB 5.17 MB, 0.93 MB,
 *   1.05x; 128 KiB 4.95 MB, 0.97 MB, 0.76x.
 * Every request costs the browser and the server time whatever its size: nlcd_zion's first view
 * takes 186 chunks at 32 KiB and 107 at 64 KiB, and fetching 186 chunk files six at a time took
 * 0.7 to 1.2 s with nothing drawn. Larger chunks cost bgt_otterlo_1800m, whose first view covers
 * 2% of its extent, more bytes than they save in requests. Earlier (before the smooth cube):
 * 256 KiB fetched 2.29 MB in 42 chunks, 16 KiB 1.84 MB in 423.
 */
export const DEFAULT_CHUNK_BYTES = 64 * 1024;
/**
 * Floor chunks are planned this many times the chunk size: a map opened at the base scale needs
 * the floor chunks over its view before anything else, and over HTTP/1.1 a browser asks for 6
 * files at a time. bgt_otterlo_1800m's view at 1:1,000 took 8 floor chunks (46 kB gzip over 9
 * views) and 2 rounds, now 5 (59 kB) and 1: bench:session's first map on Slow 4G 1.96 -> 1.85 s;
 * nlcd_zion's at 1:50,000 56 (323 kB) and now 29 (324 kB). All the floor chunks: 0.35 -> 0.34 MB
 * and 1.69 -> 1.65 MB. (Measured as triangles; the plan still counts triangle bytes, and the
 * floor chunk files, boundaries, are a quarter to a third smaller.)
 */
export const FLOOR_CHUNK_FACTOR = 2;

/**
 * Line chunks are planned at this share of the chunk size: a line lives over much of the z
 * range, so a line chunk of the surface chunks' size spans a quarter of bgt_otterlo_1800m's
 * ground from nearly z 0 to the top: a first view at 1:1,414 took all 6 (123 kB gzip), one at
 * 1:4,000 83 kB. At a quarter there are 24 (125 kB in all): the session takes 104 kB of them
 * (123 before), those first views 47 and 63 kB; the first complete map on Slow 4G came
 * at 4,025 ms instead of 4,358 at 1:1,414, and at 4,141 instead of 4,109 at 1:4,000 (medians of
 * 5 loads, alternated). An eighth took the session 108 kB and the first view 30 kB, in as long.
 */
export const LINE_CHUNK_FACTOR = 0.25;

export interface BuildOptions {
  chunkBytes?: number;
  /** Largest index file (JSON bytes) before subtrees move to sub-index files. */
  subIndexBytes?: number;
  /** Write .gz and .br copies (default true). */
  precompress?: boolean;
  /** The smooth cube (docs/FORMAT.md, "Smooth cube"; the default); false: the classic cube, every surface horizontal. */
  smooth?: boolean;
  log?: (msg: string) => void;
}

export interface BuildReport {
  triangles: number;
  surfaces: SurfaceStats;
  chunks: number;
  chunkBytes: number[];
  /** Floor chunks written (docs/FORMAT.md, "Floor chunks"). */
  floorChunks: number;
  /** Lines written (0 without line rules) and the bytes of each line chunk. */
  lines: number;
  lineChunkBytes: number[];
  indexFiles: number;
  files: number;
  bytesWritten: number;
  /** The proj4 definition of the CRS written into index.json; null: none known (no longitude/latitude in the map). */
  proj4: string | null;
  timings: Record<string, number>;
}

/** A file's name in the cube: its kind, the first 16 hex digits of its SHA-256 (what a reader checks it by), its extension. */
export function hashName(prefix: string, bytes: Uint8Array | string, ext: string): string {
  return hashedName(prefix, createHash('sha256').update(bytes).digest('hex'), ext);
}

/**
 * The exponent of the coarsest position grid a cube of `t` may take (position-grid.ts): the
 * surfaces' new points are snapped to it, and the chunks take it or a finer one (chooseGrid).
 */
export function coarsestCubeGrid(t: Tgap): number {
  // The grid the tGAP's input points lie on (its precision in a tGAP written before `grid`).
  const o = t.meta.options;
  const pointsOn = typeof o.grid === 'number' ? o.grid : typeof o.precision === 'number' ? o.precision : 0;
  return coarsestGrid(t.meta.baseScale, PIXEL_SIZE_MM, pointsOn);
}

export async function buildCube(t: Tgap, outDir: string, opts: BuildOptions = {}): Promise<BuildReport> {
  const log = opts.log ?? (() => {});
  const { timings, lap } = lapTimer();
  const smooth = opts.smooth ?? true;
  const coarsest = coarsestCubeGrid(t);
  // The faces the surfaces name: a smooth build skips some re-emits (late-reemits.ts).
  const { surfaces, stats, tgap: cubeTgap } = buildSurfaces(t, { smooth, snapStep: 2 ** coarsest });
  const { faces } = cubeTgap;
  lap('surfaces');
  log(`surfaces: ${surfaces.count} triangles (floor ${stats.floor}, merges ${stats.merge}, splits ${stats.split}, simplification ${stats.simplify}, redrawn ${stats.reemit})${smooth ? `, ${stats.tiltedMerges} merges and ${stats.tiltedRemovals} removals tilted, ${stats.heldMerges} merges held back (given to them: ${stats.mergesToHeld} losers, ${stats.piecesToHeld} pieces of areas, ${stats.splitPartsToHeld} split parts, ${stats.removalsToHeld} removals; ${stats.splitFollows} handed on by splits), ${stats.apexes} apexes, ${stats.skippedRemovals} removals left out (slivers handed back; ${stats.notchFallbacks} faces drawn without their notches; ${stats.sliversHandedOn} handed on when their giver was drawn again, ${stats.sliversLeftShowing} left showing it)` : ''}`);
  const info = scaleInfoOf(t);
  const view = {
    extent: t.meta.extent,
    scaleAt: (z: number) => scaleAtZ(info, z),
    viewPerScale: groundPerScale(1280, 720),
    targetBytes: opts.chunkBytes ?? DEFAULT_CHUNK_BYTES,
  };
  const chunking = { surfaces, xs: surfaces.xs, ys: surfaces.ys, ...view };
  const phone = { ...view, viewPerScale: groundPerScale(...PHONE_VIEW_PX) };
  const plan = planChunks(chunking, [view, phone].map((v) => zAtScale(info, wholeExtentScale(v))));
  lap('plan');
  const files = new Map<string, Uint8Array>();
  /** A file of the cube kept under its name by hash (hashName); returns the name. */
  const put = (kind: string, bytes: Uint8Array, ext = 'bin'): string => {
    const name = hashName(kind, bytes, ext);
    files.set(name, bytes);
    return name;
  };
  const classOf = (f: number): number => faces[f]!.classIndex;
  const chunkCount = plan.start.length - 1;
  const trisOf = (c: number): Uint32Array => plan.order.subarray(plan.start[c], plan.start[c + 1]);
  // The cube's grid, tried on every chunk up to 32 of them, spread evenly (position-grid.ts).
  const sampled = Math.min(32, chunkCount);
  const sample = Array.from({ length: sampled }, (_, i) => Math.floor((i * chunkCount) / sampled));
  const grid = chooseGrid(coarsest, (e) =>
    sample.reduce((sum, c) => sum + (trisOf(c).length > 0 ? assembleChunk(surfaces, trisOf(c), surfaces.xs, surfaces.ys, classOf, e).bytes.length : 0), 0));
  log(`position grid: 2^${grid}`);
  const leaves: ChunkLeaf[] = [];
  for (let c = 0; c < chunkCount; c++) {
    const tris = trisOf(c);
    if (tris.length === 0) continue;
    const ch = assembleChunk(surfaces, tris, surfaces.xs, surfaces.ys, classOf, grid);
    leaves.push({ bbox: ch.bbox, file: put('c', ch.bytes), bytes: ch.bytes.length, triangles: ch.triangles });
  }
  lap('chunks');
  // The floor once more, in chunks of its own for the views below every other surface
  // (docs/FORMAT.md, "Floor chunks"): none when nothing else lies above it, or when the cube is
  // one chunk (every view takes it whole anyway).
  const top = leaves.length > 1 ? floorTop(surfaces) : null;
  const floorLeaves: ChunkLeaf[] = [];
  if (top !== null) {
    for (const ch of floorChunks({ ...chunking, targetBytes: FLOOR_CHUNK_FACTOR * chunking.targetBytes }, top, classOf, grid)) {
      floorLeaves.push({ bbox: ch.bbox, file: put('b', ch.bytes), bytes: ch.bytes.length, triangles: ch.triangles });
    }
    log(`floor: ${floorLeaves.length} chunks below z ${top}`);
  }
  lap('floor');
  // Lines from the tGAP as generalized (the smooth build's face ids do not matter to them).
  const lineStyle = parseStyle(t.meta.style, `${t.meta.source}: the tGAP's style`);
  const lines = lineStyle.lineRules.length > 0 ? cubeLines(t, lineStyle) : null;
  const lineLeaves: LineChunkLeaf[] = [];
  for (const ch of lines ? lineChunks(lines, { ...view, targetBytes: LINE_CHUNK_FACTOR * view.targetBytes }, grid) : []) {
    lineLeaves.push({ bbox: ch.bbox, file: put('l', ch.bytes), bytes: ch.bytes.length, lines: ch.lines });
  }
  if (lines) log(`lines: ${lines.length} in ${lineLeaves.length} chunks`);
  lap('lines');
  const facePages: { first: number; file: string }[] = [];
  for (let first = 0; first < faces.length; first += FACE_PAGE_SIZE) {
    const bytes = encodeFacePage(faces, first, Math.min(FACE_PAGE_SIZE, faces.length - first));
    facePages.push({ first, file: put('f', bytes) });
  }
  const attributePages: { first: number; file: string }[] = [];
  const attrs = t.meta.attributes;
  for (let first = 0; first < attrs.length; first += ATTRIBUTE_PAGE_SIZE) {
    const bytes = encodeAttributePage(attrs, first);
    attributePages.push({ first, file: put('a', bytes, 'json') });
  }
  const subIndexBytes = opts.subIndexBytes ?? 128 * 1024;
  const subName = (json: string): string => hashName('i', json, 'json');
  const floor = top === null ? null : { top, tree: splitTree(packTree(floorLeaves), subIndexBytes, subName) };
  // With floor chunks, the first map at the floor needs the floor's tree alone: the cube's goes
  // out of index.json (docs/FORMAT.md, "index.json").
  const cubeTree = splitTree(packTree(leaves), subIndexBytes, subName);
  const tree = floor ? rootOutOfLine(cubeTree, subName) : cubeTree;
  for (const f of [...tree.files, ...(floor?.tree.files ?? [])]) files.set(f.name, new TextEncoder().encode(f.json));
  const style = t.meta.style as { name?: string; attribution?: string };
  const proj4 = t.meta.proj4 ?? proj4Definition(t.meta.crs);
  const index: CubeIndexJson = {
    format: INDEX_FORMAT,
    version: INDEX_VERSION,
    meta: {
      name: style.name ?? t.meta.source,
      crs: t.meta.crs,
      ...(t.meta.projectedFrom ? { projectedFrom: t.meta.projectedFrom } : {}),
      ...(proj4 ? { proj4 } : {}),
      extent: t.meta.extent,
      zMax: t.meta.steps,
      steps: t.meta.steps,
      phases: PHASES,
      baseScale: t.meta.baseScale,
      baseFaces: t.meta.baseFaces,
      pixelSizeMm: PIXEL_SIZE_MM,
      ...(smooth ? { smooth: true } : {}),
      scaleTable: info.scaleTable,
      style: t.meta.style as CubeIndexJson['meta']['style'],
      attribution: style.attribution ?? '',
      source: t.meta.source,
      faces: { count: faces.length, pageSize: FACE_PAGE_SIZE, pages: facePages },
      attributes: { count: attrs.length, pageSize: ATTRIBUTE_PAGE_SIZE, pages: attributePages },
    },
    root: tree.root,
    ...(floor ? { floor: { top: floor.top, root: floor.tree.root } } : {}),
    ...(lines ? { lines: lineLeaves } : {}),
  };
  files.set('index.json', encodeIndex(index));
  lap('index');
  let bytesWritten = 0;
  await writeDirAtomic(outDir, async (dir) => {
    for (const [name, bytes] of [...files].sort((a, b) => (a[0] < b[0] ? -1 : 1))) {
      await fs.writeFile(path.join(dir, name), bytes);
      bytesWritten += bytes.length;
      if (opts.precompress ?? true) {
        // Measured on the cube's chunks: gzip 6 and brotli 5 compress within 1.5% of gzip 9 and
        // brotli 9, three and eighteen times faster.
        const gz = gzipSync(bytes, { level: 6 });
        const br = brotliCompressSync(bytes, { params: { [zc.BROTLI_PARAM_QUALITY]: 5, [zc.BROTLI_PARAM_SIZE_HINT]: bytes.length } });
        await fs.writeFile(path.join(dir, `${name}.gz`), gz);
        await fs.writeFile(path.join(dir, `${name}.br`), br);
        bytesWritten += gz.length + br.length;
      }
    }
  });
  lap('write');
  return { triangles: surfaces.count, surfaces: stats, chunks: leaves.length, chunkBytes: leaves.map((l) => l.bytes), floorChunks: floorLeaves.length, lines: lines?.length ?? 0, lineChunkBytes: lineLeaves.map((l) => l.bytes), indexFiles: 1 + tree.files.length + (floor?.tree.files.length ?? 0), files: files.size, bytesWritten, proj4, timings };
}
