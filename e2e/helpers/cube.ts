// Real cubes for the browser tests (`ssc build` of a dataset into a temporary directory) and
// the CPU reference slicer (`ssc slice --ids`, or in this process with the z of each pixel), the
// oracle of the GPU's ID buffer.
import { execFile } from 'node:child_process';
import { mkdtemp, readFile, rm } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { promisify } from 'node:util';
import { decodeChunk } from '../../format/chunk.js';
import { parseIndex, parseSubIndex, type ChunkLeaf, type CubeMeta, type InnerNode, type LineChunkLeaf } from '../../format/cube-index.js';
import { EVERYWHERE, queryIndex } from '../../format/index-query.js';
import { zAtScale } from '../../format/scale.js';
import { parseSurface, surfaceZ, type Surface } from '../../format/slicing-surface.js';
import { pointSegmentDistance } from '../../format/point-segment.js';
import { sliceCube } from '../../preprocess/commands/slice-cube.js';
import { fitView } from '../../preprocess/map/rasterize.js';
import { CubeReader } from '../../preprocess/ssc/read-cube.js';
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

/**
 * The CPU slicer run here: per pixel (rows from the top) the face, the z of the surface shown
 * (-Infinity: none) and the face below it; and the slicing surface's z.
 */
export async function cpuSliceWithZ(cubeDir: string, a: SliceArgs): Promise<{ ids: Uint32Array; z: Float64Array; lower: Uint32Array; zMax: number; sliceZ: (x: number, y: number) => number }> {
  const cube = await CubeReader.open(cubeDir);
  const meta = cube.index.meta;
  const surface: Surface = { base: a.step ?? zAtScale(meta, a.scale!), spec: a.surface ? parseSurface(a.surface) : { kind: 'flat' } };
  const { slicer } = await sliceCube(cube, meta.zMax, fitView(meta.extent, a.width, a.height, a.bbox), surface);
  return { ids: slicer.ids, z: slicer.depth, lower: slicer.lower, zMax: meta.zMax, sliceZ: (x, y) => surfaceZ(surface, x, y, meta.zMax) };
}

export interface CubeContents {
  meta: CubeMeta;
  leaves: ChunkLeaf[];
  /** The floor chunks (docs/FORMAT.md, "Floor chunks"; none in a cube of one chunk) and their top. */
  floorLeaves: ChunkLeaf[];
  floorTop: number;
  /** The line chunks (none in a cube without lines). */
  lines: LineChunkLeaf[];
  subIndexFiles: string[];
  /** Those of them in the floor's tree (a floor too large for index.json). */
  floorSubIndexFiles: string[];
  root: InnerNode;
  /** The floor's root as index.json holds it (none without floor chunks). */
  floorRoot: InnerNode | undefined;
  subs: Map<string, InnerNode>;
}

/** The cube's metadata, every chunk leaf and every sub-index file, read from its directory. */
export async function readCube(cubeDir: string): Promise<CubeContents> {
  const index = parseIndex(JSON.parse(await readFile(path.join(cubeDir, 'index.json'), 'utf8')));
  const subs = new Map<string, InnerNode>();
  const leavesOf = async (root: InnerNode): Promise<ChunkLeaf[]> => {
    let q = queryIndex(root, EVERYWHERE, (r) => subs.get(r));
    while (q.missing.length > 0) {
      for (const ref of q.missing) subs.set(ref, parseSubIndex(JSON.parse(await readFile(path.join(cubeDir, ref), 'utf8')), ref));
      q = queryIndex(root, EVERYWHERE, (r) => subs.get(r));
    }
    return q.leaves;
  };
  const leaves = await leavesOf(index.root);
  const cubeSubs = subs.size;
  const floorLeaves = index.floor ? await leavesOf(index.floor.root) : [];
  const subIndexFiles = [...subs.keys()];
  return { meta: index.meta, leaves, floorLeaves, floorTop: index.floor?.top ?? 0, lines: index.lines ?? [], subIndexFiles, floorSubIndexFiles: subIndexFiles.slice(cubeSubs), root: index.root, floorRoot: index.floor?.root, subs };
}

/** Every triangle of a cube, x, y and z of each corner in ground coordinates, found by place. */
export async function cubeTriangles(cubeDir: string): Promise<CubeTriangles> {
  const { leaves } = await readCube(cubeDir);
  const out: number[] = [];
  for (const leaf of leaves) {
    const c = await decodeChunk(await readFile(path.join(cubeDir, leaf.file)));
    const p = c.positions;
    for (let k = 0; k < c.indices.length; k++) {
      const v = c.indices[k]!;
      out.push(c.originX + p[3 * v]!, c.originY + p[3 * v + 1]!, p[3 * v + 2]!);
    }
  }
  return new CubeTriangles(Float64Array.from(out));
}


/** A triangle's plane at a point over it: z there and |grad z| (steps per ground unit). */
export interface PlaneAt {
  z: number;
  slope: number;
}

/** Triangles (9 numbers each: x, y, z per corner) in a grid of square cells, to ask about a point. */
export class CubeTriangles {
  private readonly cells = new Map<string, number[]>();
  private readonly cell: number;

  constructor(readonly data: Float64Array) {
    let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
    for (let t = 0; t < data.length; t += 3) {
      x0 = Math.min(x0, data[t]!); x1 = Math.max(x1, data[t]!);
      y0 = Math.min(y0, data[t + 1]!); y1 = Math.max(y1, data[t + 1]!);
    }
    // About 64 x 64 cells over the extent.
    this.cell = Math.max(x1 - x0, y1 - y0, 1) / 64;
    for (let t = 0; t < data.length; t += 9) {
      const [i0, j0] = this.key(Math.min(data[t]!, data[t + 3]!, data[t + 6]!), Math.min(data[t + 1]!, data[t + 4]!, data[t + 7]!));
      const [i1, j1] = this.key(Math.max(data[t]!, data[t + 3]!, data[t + 6]!), Math.max(data[t + 1]!, data[t + 4]!, data[t + 7]!));
      for (let i = i0; i <= i1; i++) {
        for (let j = j0; j <= j1; j++) {
          const list = this.cells.get(`${i},${j}`);
          if (list) list.push(t);
          else this.cells.set(`${i},${j}`, [t]);
        }
      }
    }
  }

  private key(x: number, y: number): [number, number] {
    return [Math.floor(x / this.cell), Math.floor(y / this.cell)];
  }

  /** Offsets of the triangles whose boxes, grown by tol, may hold (x, y). */
  private near(x: number, y: number, tol: number): Set<number> {
    const out = new Set<number>();
    const [i0, j0] = this.key(x - tol, y - tol), [i1, j1] = this.key(x + tol, y + tol);
    for (let i = i0; i <= i1; i++) for (let j = j0; j <= j1; j++) for (const t of this.cells.get(`${i},${j}`) ?? []) out.add(t);
    return out;
  }

  /** True when (x, y) lies within `tol` (ground units) of an edge of a triangle. */
  nearEdge(x: number, y: number, tol: number): boolean {
    const d = this.data;
    for (const t of this.near(x, y, tol)) {
      const ax = d[t]!, ay = d[t + 1]!, bx = d[t + 3]!, by = d[t + 4]!, cx = d[t + 6]!, cy = d[t + 7]!;
      if (x < Math.min(ax, bx, cx) - tol || x > Math.max(ax, bx, cx) + tol || y < Math.min(ay, by, cy) - tol || y > Math.max(ay, by, cy) + tol) continue;
      if (pointSegmentDistance(x, y, ax, ay, bx, by) <= tol || pointSegmentDistance(x, y, bx, by, cx, cy) <= tol || pointSegmentDistance(x, y, cx, cy, ax, ay) <= tol) return true;
    }
    return false;
  }

  /** The planes of the upward triangles over (x, y): z from their corners' z, as the slicers take it. */
  planesAt(x: number, y: number): PlaneAt[] {
    const d = this.data;
    const out: PlaneAt[] = [];
    for (const t of this.near(x, y, 0)) {
      const ax = d[t]!, ay = d[t + 1]!, az = d[t + 2]!, bx = d[t + 3]!, by = d[t + 4]!, bz = d[t + 5]!, cx = d[t + 6]!, cy = d[t + 7]!, cz = d[t + 8]!;
      const area = (bx - ax) * (cy - ay) - (cx - ax) * (by - ay);
      if (!(area > 0)) continue;
      const w0 = ((bx - x) * (cy - y) - (cx - x) * (by - y)) / area, w1 = ((cx - x) * (ay - y) - (ax - x) * (cy - y)) / area, w2 = 1 - w0 - w1;
      if (w0 < 0 || w1 < 0 || w2 < 0) continue;
      const gx = ((bz - az) * (cy - ay) - (cz - az) * (by - ay)) / area, gy = ((cz - az) * (bx - ax) - (bz - az) * (cx - ax)) / area;
      out.push({ z: w0 * az + w1 * bz + w2 * cz, slope: Math.hypot(gx, gy) });
    }
    return out;
  }
}

export interface Comparison {
  total: number;
  equal: number;
  share: number;
  /** Differing pixels on a face boundary of the reference (a differing id among their 8 neighbours). */
  onFaceBoundary: number;
  /** Differing pixels the caller's `nearEdge` explains (sub-pixel precision). */
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
