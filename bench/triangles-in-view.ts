// The triangles a view needs, counted on the CPU from the chunks (issue 13's "triangles needed by
// the faces actually visible"): those relevant at the view's z (lowest corner at or below it,
// upper face not yet ended: docs/FORMAT.md, "Surfaces"; a face's end from the face table pages,
// taken as its stepHigh, at or just above its true end) whose ground box meets the view. A frame
// that draws exactly these draws no triangle in vain; the renderer's count is set against it.
// Beside it the ID pass's overdraw (issue 13): the chunks the view queries sliced by the CPU
// reference slicer, counting per pixel every triangle over its centre at or below the slice,
// which the GPU's ID pass shades and keeps (it discards only what lies above the slice), per
// pixel with a face. One fragment per pixel is the floor.
// sessionNeeds takes the union over the views of a session: the bytes of the chunks they query,
// of the share of each chunk's triangles some view needs, and of that the share some view's
// slice cuts (bench:session).
import { groundPerScale } from '../format/pixel-size.js';
import { zAtScale } from '../format/scale.js';
import { CpuSlicer, sliceChunk } from '../preprocess/ssc/cpu-slicer.js';
import { CubeReader } from '../preprocess/ssc/read-cube.js';
import type { ChunkData } from '../format/chunk.js';

export interface ViewNeeds {
  /** Triangles the view needs. */
  triangles: number;
  /** Fragments the ID pass keeps per pixel with a face (1: no overdraw). */
  fragmentsPerPixel: number;
}

/** What a view needs, for views of one cube: its index and face pages are read once. */
export type TrianglesInView = (scale: number, centre: [number, number], width?: number, height?: number) => Promise<ViewNeeds>;

/** The counter of triangles needed by a `width` x `height` px view at 1:scale centred on `centre`. */
export async function trianglesInView(cubeDir: string): Promise<TrianglesInView> {
  const cube = await CubeReader.open(cubeDir);
  const meta = cube.index.meta;
  const endOf = await faceEnds(cube);
  return async (scale, centre, width = 1280, height = 720) => {
    const z = zAtScale(meta, scale);
    const [x0, y0, x1, y1] = viewBox(scale, centre, width, height);
    let n = 0;
    const sl = new CpuSlicer({ width, height, bbox: [x0, y0, x1, y1] }, () => z, true);
    for (const leaf of await cube.query({ ground: [x0, y0, x1, y1], zMin: z, zMax: z })) {
      const c = await cube.chunk(leaf);
      sliceChunk(sl, c);
      forNeededTriangles(c, z, [x0, y0, x1, y1], endOf, () => n++);
    }
    let fragments = 0, covered = 0;
    sl.fragments!.forEach((f, p) => {
      fragments += f;
      if (sl.ids[p] !== 0) covered++;
    });
    return { triangles: n, fragmentsPerPixel: covered === 0 ? 0 : fragments / covered };
  };
}

/** The ground box of a `width` x `height` px view at 1:scale centred on `centre`. */
export function viewBox(scale: number, centre: [number, number], width: number, height: number): [number, number, number, number] {
  const [w, h] = groundPerScale(width, height);
  return [centre[0] - (w / 2) * scale, centre[1] - (h / 2) * scale, centre[0] + (w / 2) * scale, centre[1] + (h / 2) * scale];
}

/** Each face's end (its stepHigh, at or just above its true end), read from the cube's face pages once. */
async function faceEnds(cube: CubeReader): Promise<(face: number) => number> {
  const ends = await cube.faceEnds();
  return (face) => ends[face] ?? Infinity;
}

/**
 * Calls `use` with each triangle of chunk `c` a slice at `z` needs within the ground box `box`,
 * and whether the slice cuts it (its highest corner is above `z`: a transition in progress)
 * rather than lying wholly at or below it (settled: what the partition at that state shows).
 */
export function forNeededTriangles(c: ChunkData, z: number, box: [number, number, number, number], endOf: (face: number) => number, use: (t: number, cut: boolean) => void): void {
  const [x0, y0, x1, y1] = box;
  const P = c.positions, I = c.indices;
  for (let t = 0; t < c.triangleCount; t++) {
    const a = I[3 * t]!, b = I[3 * t + 1]!, d = I[3 * t + 2]!;
    if (Math.min(P[3 * a + 2]!, P[3 * b + 2]!, P[3 * d + 2]!) > z || endOf(c.upper[a]!) <= z) continue;
    const tx0 = c.originX + Math.min(P[3 * a]!, P[3 * b]!, P[3 * d]!), tx1 = c.originX + Math.max(P[3 * a]!, P[3 * b]!, P[3 * d]!);
    const ty0 = c.originY + Math.min(P[3 * a + 1]!, P[3 * b + 1]!, P[3 * d + 1]!), ty1 = c.originY + Math.max(P[3 * a + 1]!, P[3 * b + 1]!, P[3 * d + 1]!);
    if (tx1 >= x0 && tx0 <= x1 && ty1 >= y0 && ty0 <= y1) use(t, Math.max(P[3 * a + 2]!, P[3 * b + 2]!, P[3 * d + 2]!) > z);
  }
}

export interface SessionNeeds {
  /** Bytes of the chunks some view of the session queries (each once). */
  queriedBytes: number;
  /** Those chunks' bytes in proportion to the triangles some view needs of each: a floor for this encoding. */
  neededBytes: number;
  /**
   * The part of `neededBytes` in triangles some view's slice cuts (transitions in progress); the
   * rest lie wholly at or below every slice that needs them, showing a state's partition, which
   * a map could draw from that state's boundaries instead (issue 13's edges-and-events question).
   */
  cutBytes: number;
}

/**
 * What a session of `views` (1:scale, centre) needs of the cube in `cubeDir`, in bytes of each
 * chunk's file as `bytesOf` weighs it (e.g. its gzip copy): the chunks the views query, and the
 * share of each that some view needs (the triangles counted by `trianglesInView`).
 */
export async function sessionNeeds(cubeDir: string, views: { scale: number; centre: [number, number] }[], bytesOf: (file: string) => Promise<number>, width = 1280, height = 720): Promise<SessionNeeds> {
  const cube = await CubeReader.open(cubeDir);
  const endOf = await faceEnds(cube);
  // Each chunk read and decoded once, however many views query it. Per needed triangle: whether some view cuts it.
  const needed = new Map<string, { chunk: ChunkData; used: Map<number, boolean> }>();
  for (const v of views) {
    const z = zAtScale(cube.index.meta, v.scale);
    const box = viewBox(v.scale, v.centre, width, height);
    for (const leaf of await cube.query({ ground: box, zMin: z, zMax: z })) {
      let e = needed.get(leaf.file);
      if (!e) needed.set(leaf.file, (e = { chunk: await cube.chunk(leaf), used: new Map() }));
      const used = e.used;
      forNeededTriangles(e.chunk, z, box, endOf, (t, cut) => used.set(t, cut || used.get(t) === true));
    }
  }
  let queriedBytes = 0, neededBytes = 0, cutBytes = 0;
  for (const [file, e] of needed) {
    const b = await bytesOf(file);
    queriedBytes += b;
    neededBytes += (b * e.used.size) / e.chunk.triangleCount;
    let cut = 0;
    for (const c of e.used.values()) if (c) cut++;
    cutBytes += (b * cut) / e.chunk.triangleCount;
  }
  return { queriedBytes, neededBytes, cutBytes };
}
