// The triangles a view needs, counted on the CPU from the chunks (issue 13's "triangles needed by
// the faces actually visible"): those relevant at the view's z (lowest corner at or below it,
// upper face not yet ended: docs/FORMAT.md, "Surfaces"; a face's end from the face table pages,
// taken as its stepHigh, at or just above its true end) whose ground box meets the view. A frame
// that draws exactly these draws no triangle in vain; the renderer's count is set against it.
// Beside it the ID pass's overdraw (issue 13): the chunks the view queries sliced by the CPU
// reference slicer, counting per pixel every triangle over its centre at or below the slice,
// which the GPU's ID pass shades and keeps (it discards only what lies above the slice), per
// pixel with a face. One fragment per pixel is the floor.
import { readFile } from 'node:fs/promises';
import path from 'node:path';
import { decodeFacePage, faceRecord } from '../format/face-page.js';
import { PIXEL_SIZE_MM } from '../format/pixel-size.js';
import { zAtScale } from '../format/scale.js';
import { CpuSlicer, sliceChunk } from '../preprocess/ssc/cpu-slicer.js';
import { CubeReader } from '../preprocess/ssc/read-cube.js';

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
  const pages = await Promise.all(meta.faces.pages.map(async (p) => {
    const b = await readFile(path.join(cubeDir, p.file));
    return decodeFacePage(b.buffer.slice(b.byteOffset, b.byteOffset + b.byteLength));
  }));
  const ends = new Map<number, number>();
  const endOf = (face: number): number => {
    let e = ends.get(face);
    if (e === undefined) {
      const rec = pages.map((p) => faceRecord(p, face)).find((r) => r !== undefined);
      ends.set(face, (e = rec ? rec.stepHigh : Infinity));
    }
    return e;
  };
  return async (scale, centre, width = 1280, height = 720) => {
    const z = zAtScale(meta, scale);
    const res = (scale * PIXEL_SIZE_MM) / 1000;
    const [x0, y0, x1, y1] = [centre[0] - (width / 2) * res, centre[1] - (height / 2) * res, centre[0] + (width / 2) * res, centre[1] + (height / 2) * res];
    let n = 0;
    const sl = new CpuSlicer({ width, height, bbox: [x0, y0, x1, y1] }, () => z, true);
    for (const leaf of await cube.query({ ground: [x0, y0, x1, y1], zMin: z, zMax: z })) {
      const c = await cube.chunk(leaf);
      sliceChunk(sl, c);
      const P = c.positions, I = c.indices;
      for (let t = 0; t < c.triangleCount; t++) {
        const a = I[3 * t]!, b = I[3 * t + 1]!, d = I[3 * t + 2]!;
        if (Math.min(P[3 * a + 2]!, P[3 * b + 2]!, P[3 * d + 2]!) > z || endOf(c.upper[a]!) <= z) continue;
        const tx0 = c.originX + Math.min(P[3 * a]!, P[3 * b]!, P[3 * d]!), tx1 = c.originX + Math.max(P[3 * a]!, P[3 * b]!, P[3 * d]!);
        const ty0 = c.originY + Math.min(P[3 * a + 1]!, P[3 * b + 1]!, P[3 * d + 1]!), ty1 = c.originY + Math.max(P[3 * a + 1]!, P[3 * b + 1]!, P[3 * d + 1]!);
        if (tx1 >= x0 && tx0 <= x1 && ty1 >= y0 && ty0 <= y1) n++;
      }
    }
    let fragments = 0, covered = 0;
    sl.fragments!.forEach((f, p) => {
      fragments += f;
      if (sl.ids[p] !== 0) covered++;
    });
    return { triangles: n, fragmentsPerPixel: covered === 0 ? 0 : fragments / covered };
  };
}
