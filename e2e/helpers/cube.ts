// Real cubes for the browser tests (`ssc build` of a dataset into a temporary directory) and
// the CPU reference slicer (`ssc slice --ids`), the oracle of the GPU's ID buffer.
import { execFile } from 'node:child_process';
import { mkdtemp, readFile, rm } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { promisify } from 'node:util';
import { decodeChunk } from '../../format/chunk.js';
import { parseIndex, parseSubIndex, type ChunkLeaf, type CubeMeta, type InnerNode } from '../../format/cube-index.js';
import { queryIndex } from '../../format/index-query.js';
import { dataset, repoRoot, styleFile } from '../../testing/paths.js';

const run = promisify(execFile);
export { repoRoot };
export const clientDir = path.join(repoRoot, 'dist/client');
const ssc = path.join(repoRoot, 'bin/ssc.js');
export const otterlo400 = dataset('bgt_otterlo_400m.geojson');
export const bgtStyle = styleFile('bgt.json');

export interface BuiltCube {
  dir: string;
  remove(): Promise<void>;
}

/** `ssc build` of the input into a fresh temporary directory. */
export async function buildCube(input: string, extra: string[] = [], style = bgtStyle): Promise<BuiltCube> {
  const dir = await mkdtemp(path.join(tmpdir(), 'ssc-e2e-'));
  const out = path.join(dir, 'cube');
  await run(process.execPath, [ssc, 'build', input, '--style', style, '--out', out, '--quiet', ...extra], { maxBuffer: 1 << 24 });
  return { dir: out, remove: () => rm(dir, { recursive: true, force: true }) };
}

export interface SliceArgs {
  /** Base z (--step) or scale denominator (--scale). */
  step?: number;
  scale?: number;
  width: number;
  height: number;
  bbox: [number, number, number, number];
  surface?: string;
}

/** The CPU slicer's face ids, rows from the top. */
export async function cpuSlice(cubeDir: string, a: SliceArgs): Promise<Uint32Array> {
  const tmp = await mkdtemp(path.join(tmpdir(), 'ssc-slice-'));
  try {
    const ids = path.join(tmp, 'ids.bin');
    const args = [ssc, 'slice', cubeDir, '--size', `${a.width}x${a.height}`, '--bbox', a.bbox.join(','), '--ids', ids, '--out', path.join(tmp, 'slice.png')];
    if (a.step !== undefined) args.push('--step', String(a.step));
    if (a.scale !== undefined) args.push('--scale', String(a.scale));
    if (a.surface) args.push('--surface', a.surface);
    await run(process.execPath, args, { maxBuffer: 1 << 24 });
    const buf = await readFile(ids);
    return new Uint32Array(buf.buffer, buf.byteOffset, buf.byteLength / 4).slice();
  } finally {
    await rm(tmp, { recursive: true, force: true });
  }
}

export interface CubeContents {
  meta: CubeMeta;
  leaves: ChunkLeaf[];
  subIndexFiles: string[];
  root: InnerNode;
  subs: Map<string, InnerNode>;
}

/** The cube's metadata, every chunk leaf and every sub-index file, read from its directory. */
export async function readCube(cubeDir: string): Promise<CubeContents> {
  const index = parseIndex(JSON.parse(await readFile(path.join(cubeDir, 'index.json'), 'utf8')));
  const subs = new Map<string, InnerNode>();
  const all = { ground: [-Infinity, -Infinity, Infinity, Infinity] as [number, number, number, number], zMin: -Infinity, zMax: Infinity };
  let q = queryIndex(index.root, all, (r) => subs.get(r));
  while (q.missing.length > 0) {
    for (const ref of q.missing) subs.set(ref, parseSubIndex(JSON.parse(await readFile(path.join(cubeDir, ref), 'utf8')), ref));
    q = queryIndex(index.root, all, (r) => subs.get(r));
  }
  return { meta: index.meta, leaves: q.leaves, subIndexFiles: [...subs.keys()], root: index.root, subs };
}

/** Every triangle of a cube as ground coordinates (x, y per corner, 6 numbers each). */
export async function cubeTriangles(cubeDir: string): Promise<Float64Array> {
  const { leaves } = await readCube(cubeDir);
  const out: number[] = [];
  for (const leaf of leaves) {
    const c = decodeChunk(await readFile(path.join(cubeDir, leaf.file)));
    const p = c.positions;
    for (let k = 0; k < c.indices.length; k++) {
      const v = c.indices[k]!;
      out.push(c.originX + p[3 * v]!, c.originY + p[3 * v + 1]!);
    }
  }
  return Float64Array.from(out);
}

function segmentDistance(px: number, py: number, ax: number, ay: number, bx: number, by: number): number {
  const dx = bx - ax, dy = by - ay;
  const len2 = dx * dx + dy * dy;
  const t = len2 === 0 ? 0 : Math.max(0, Math.min(1, ((px - ax) * dx + (py - ay) * dy) / len2));
  return Math.hypot(px - (ax + t * dx), py - (ay + t * dy));
}

/** True when (x, y) lies within `tol` (ground units) of an edge of one of the triangles. */
export function nearTriangleEdge(tris: Float64Array, x: number, y: number, tol: number): boolean {
  for (let t = 0; t < tris.length; t += 6) {
    const ax = tris[t]!, ay = tris[t + 1]!, bx = tris[t + 2]!, by = tris[t + 3]!, cx = tris[t + 4]!, cy = tris[t + 5]!;
    if (x < Math.min(ax, bx, cx) - tol || x > Math.max(ax, bx, cx) + tol || y < Math.min(ay, by, cy) - tol || y > Math.max(ay, by, cy) + tol) continue;
    if (segmentDistance(x, y, ax, ay, bx, by) <= tol || segmentDistance(x, y, bx, by, cx, cy) <= tol || segmentDistance(x, y, cx, cy, ax, ay) <= tol) return true;
  }
  return false;
}

/**
 * True when (x, y) lies inside a triangle narrower than `width` (ground units; its smallest
 * altitude): a GPU rasterizes such a needle at its sub-pixel precision all along its length,
 * so a pixel well inside it by the CPU's exact test may still be left to the surface below.
 */
export function inSliverTriangle(tris: Float64Array, x: number, y: number, width: number): boolean {
  for (let t = 0; t < tris.length; t += 6) {
    const ax = tris[t]!, ay = tris[t + 1]!, bx = tris[t + 2]!, by = tris[t + 3]!, cx = tris[t + 4]!, cy = tris[t + 5]!;
    if (x < Math.min(ax, bx, cx) || x > Math.max(ax, bx, cx) || y < Math.min(ay, by, cy) || y > Math.max(ay, by, cy)) continue;
    const d1 = (bx - ax) * (y - ay) - (by - ay) * (x - ax), d2 = (cx - bx) * (y - by) - (cy - by) * (x - bx), d3 = (ax - cx) * (y - cy) - (ay - cy) * (x - cx);
    if (!((d1 >= 0 && d2 >= 0 && d3 >= 0) || (d1 <= 0 && d2 <= 0 && d3 <= 0))) continue;
    const area2 = Math.abs((bx - ax) * (cy - ay) - (cx - ax) * (by - ay));
    const longest = Math.max(Math.hypot(bx - ax, by - ay), Math.hypot(cx - bx, cy - by), Math.hypot(ax - cx, ay - cy));
    if (area2 / longest < width) return true;
  }
  return false;
}

export interface Comparison {
  total: number;
  equal: number;
  share: number;
  /** Differing pixels on a face boundary of the reference (a differing id among their 8 neighbours). */
  onFaceBoundary: number;
  /** Differing pixels whose centre is within the sub-pixel tolerance of a triangle edge, or inside a needle narrower than a pixel. */
  subPixel: number;
  /** Differing pixels that are neither. */
  unexplained: number;
  /** Some differing pixels, for messages. */
  examples: string[];
}

/**
 * Compares two id images. A difference on a face boundary of `ref` is a rasterization detail;
 * so is one whose pixel centre lies within a small fraction of a pixel of some triangle edge
 * (`nearEdge`): a GPU decides such pixels at its sub-pixel precision, the CPU exactly.
 */
export function compareIds(gpu: Uint32Array, ref: Uint32Array, width: number, height: number, nearEdge?: (i: number, j: number) => boolean): Comparison {
  let equal = 0, onFaceBoundary = 0, subPixel = 0, unexplained = 0;
  const examples: string[] = [];
  for (let j = 0; j < height; j++) {
    for (let i = 0; i < width; i++) {
      const p = j * width + i;
      if (gpu[p] === ref[p]) {
        equal++;
        continue;
      }
      let boundary = false;
      for (let dj = -1; dj <= 1 && !boundary; dj++) {
        for (let di = -1; di <= 1; di++) {
          const x = i + di, y = j + dj;
          if (x < 0 || y < 0 || x >= width || y >= height) continue;
          if (ref[y * width + x] !== ref[p]) {
            boundary = true;
            break;
          }
        }
      }
      let kind: string;
      if (boundary) {
        onFaceBoundary++;
        kind = 'face boundary';
      } else if (nearEdge?.(i, j)) {
        subPixel++;
        kind = 'sub-pixel';
      } else {
        unexplained++;
        kind = 'UNEXPLAINED';
      }
      if (examples.length < 8 || (kind === 'UNEXPLAINED' && examples.length < 16)) examples.push(`(${i},${j}) gpu ${gpu[p]} cpu ${ref[p]} ${kind}`);
    }
  }
  return { total: width * height, equal, share: equal / (width * height), onFaceBoundary, subPixel, unexplained, examples };
}
