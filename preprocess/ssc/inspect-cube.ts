// What a cube directory holds, measured: chunk sizes, what chunking costs over one unchunked
// file, the index, the floor chunks, the line chunks, and what a 1280x720 view needs at scales
// from the base scale to the whole extent (detail must follow scale).
import { promises as fs } from 'node:fs';
import path from 'node:path';
import { isExternal, isLeaf, type IndexNode } from '../../format/cube-index.js';
import { scaleAtZ, zAtScale } from '../../format/scale.js';
import { groundPerScale } from '../../format/pixel-size.js';
import { wholeExtentScale } from './view-hit-chance.js';
import { boxMeets, EVERYWHERE } from '../../format/index-query.js';
import { lineOfChunk } from '../../format/line-chunk.js';
import { groundBox, lineAliveAt } from '../../format/line-record.js';
import { CubeReader } from './read-cube.js';
import { unchunkedBytes as oneFileBytes } from './unchunked-bytes.js';

export interface ViewRow {
  scale: number;
  z: number;
  chunks: number;
  triangles: number;
  bytes: number;
  /** Lines alive at z whose box meets the view, and the bytes of the line chunks fetched for it. */
  lines: number;
  lineBytes: number;
}

export interface CubeReport {
  name: string;
  faces: number;
  steps: number;
  scaleRange: [number, number];
  chunks: number;
  triangles: number;
  bytes: { total: number; min: number; median: number; max: number; cv: number };
  unchunkedBytes: number;
  overhead: number;
  index: { depth: number; files: number; bytes: number };
  /** The floor chunks (docs/FORMAT.md, "Floor chunks"; null: none): the views below `top` take them. */
  floor: { chunks: number; triangles: number; bytes: number; top: number } | null;
  /** The line chunks (null: a cube without lines). */
  lines: { chunks: number; lines: number; bytes: number } | null;
  views: ViewRow[];
  viewRatio: { triangles: number; bytes: number };
}

export async function inspectCube(dir: string): Promise<CubeReport> {
  const cube = await CubeReader.open(dir);
  const leaves = await cube.loadAll();
  const meta = cube.index.meta;
  const sizes = leaves.map((l) => l.bytes).sort((a, b) => a - b);
  const total = sizes.reduce((a, b) => a + b, 0);
  const mean = total / Math.max(1, sizes.length);
  const sd = Math.sqrt(sizes.reduce((a, b) => a + (b - mean) ** 2, 0) / Math.max(1, sizes.length));
  let triangles = 0;
  const decoded = [];
  for (const leaf of leaves) {
    const c = await cube.chunk(leaf);
    decoded.push({ leaf, c });
    triangles += c.triangleCount;
  }
  // The same surfaces as one file: what chunking adds is headers, face tables, vertices repeated
  // on both sides of a chunk border and each chunk's codec starting afresh.
  const unchunkedBytes = oneFileBytes(decoded.map(({ c }) => c));
  const floor = cube.index.floor;
  const floorDecoded = [];
  for (const leaf of floor ? await cube.loadAll(floor.root) : []) floorDecoded.push({ leaf, c: await cube.chunk(leaf) });
  let depth = 0;
  // Through the sub-index files (all read above): a reference stands for its file's node.
  const walk = (n: IndexNode, d: number): void => {
    if (isExternal(n)) {
      const sub = cube.loadedSub(n.ref);
      if (sub) walk(sub, d);
      return;
    }
    depth = Math.max(depth, d);
    if (isLeaf(n)) return;
    for (const c of n.children) walk(c, d + 1);
  };
  walk(cube.index.root, 1);
  let indexBytes = 0;
  for (const name of await fs.readdir(dir)) {
    if (name === 'index.json' || (name.startsWith('i-') && name.endsWith('.json'))) indexBytes += (await fs.stat(path.join(dir, name))).size;
  }
  const lineLeaves = cube.lineChunks(EVERYWHERE);
  const lineData = await Promise.all(lineLeaves.map(async (leaf) => {
    const c = await cube.lineChunk(leaf);
    return { leaf, lines: Array.from({ length: c.lineCount }, (_, i) => lineOfChunk(c, i)).map((l) => ({ ...l, box: groundBox(l.paths) })) };
  }));
  const views: ViewRow[] = [];
  const [x0, y0, x1, y1] = meta.extent;
  const [vw, vh] = groundPerScale(1280, 720);
  const sBase = meta.baseScale;
  const sFull = Math.max(wholeExtentScale({ extent: meta.extent, viewPerScale: [vw, vh] }), sBase);
  for (let i = 0; i < 8; i++) {
    const scale = sBase * Math.pow(sFull / sBase, i / 7);
    const z = zAtScale(meta, scale);
    const hw = (vw / 2) * scale, hh = (vh / 2) * scale;
    // The mean over a 5 x 5 grid of view centres over the extent (a view at one place alone can
    // sit on the very edges where chunks meet).
    let tris = 0, bytes = 0, chunks = 0, lines = 0, lineBytes = 0;
    const grid = 5;
    for (let gy = 0; gy < grid; gy++) {
      for (let gx = 0; gx < grid; gx++) {
        const vx = x0 + ((gx + 0.5) / grid) * (x1 - x0), vy = y0 + ((gy + 0.5) / grid) * (y1 - y0);
        const ground: [number, number, number, number] = [vx - hw, vy - hh, vx + hw, vy + hh];
        // Below the floor's top the map takes the floor chunks (with nothing fetched yet).
        const atFloor = floor && z < floor.top;
        const hit = new Set(cube.queryLoaded({ ground, zMin: z, zMax: z }, atFloor ? floor.root : undefined).map((l) => l.file));
        for (const { leaf, c } of atFloor ? floorDecoded : decoded) {
          if (!hit.has(leaf.file)) continue;
          tris += c.triangleCount;
          bytes += leaf.bytes;
        }
        chunks += hit.size;
        const q = { ground, zMin: z, zMax: z };
        for (const { leaf, lines: ls } of lineData) {
          if (!boxMeets(leaf.bbox, q)) continue;
          lineBytes += leaf.bytes;
          lines += ls.filter((l) => lineAliveAt(l, z) && l.box[0] <= ground[2] && l.box[2] >= ground[0] && l.box[1] <= ground[3] && l.box[3] >= ground[1]).length;
        }
      }
    }
    const g2 = grid * grid;
    views.push({ scale, z, chunks: chunks / g2, triangles: Math.round(tris / g2), bytes: Math.round(bytes / g2), lines: Math.round(lines / g2), lineBytes: Math.round(lineBytes / g2) });
  }
  const ratio = (k: 'triangles' | 'bytes'): number => {
    const v = views.map((r) => r[k]);
    return Math.max(...v) / Math.max(1, Math.min(...v));
  };
  return {
    name: meta.name,
    faces: meta.baseFaces,
    steps: meta.steps,
    scaleRange: [meta.baseScale, scaleAtZ(meta, meta.zMax)],
    chunks: leaves.length,
    triangles,
    bytes: { total, min: sizes[0] ?? 0, median: sizes[Math.floor(sizes.length / 2)] ?? 0, max: sizes[sizes.length - 1] ?? 0, cv: mean > 0 ? sd / mean : 0 },
    unchunkedBytes,
    overhead: total / Math.max(1, unchunkedBytes),
    index: { depth, files: 1 + cube.subIndexFiles, bytes: indexBytes },
    floor: floor ? { chunks: floorDecoded.length, triangles: floorDecoded.reduce((n, d) => n + d.c.triangleCount, 0), bytes: floorDecoded.reduce((n, d) => n + d.leaf.bytes, 0), top: floor.top } : null,
    lines: cube.index.lines ? { chunks: lineData.length, lines: lineData.reduce((n, d) => n + d.lines.length, 0), bytes: lineLeaves.reduce((n, l) => n + l.bytes, 0) } : null,
    views,
    viewRatio: { triangles: ratio('triangles'), bytes: ratio('bytes') },
  };
}

