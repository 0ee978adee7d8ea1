// The cube's line vertices a view shows, counted on the CPU from the line chunks (issue 12's
// "per-view line vertices"): the vertices of the polylines alive at the view's z (simplified
// for it), of lines whose rule draws at its scale, that lie in the view.
import { readFile } from 'node:fs/promises';
import path from 'node:path';
import type { CubeIndex } from '../format/cube-index.js';
import { decodeLineChunk, lineOfChunk } from '../format/line-chunk.js';
import { linePathsAtZ } from '../format/line-record.js';
import { lineRuleDrawnAt } from '../format/line-style.js';
import { viewBox } from './triangles-in-view.js';
import { zAtScale } from '../format/scale.js';

/** Line vertices inside a `width` x `height` px view at 1:scale centred on `centre`. */
export async function linesInView(cubeDir: string, index: CubeIndex, scale: number, centre: [number, number], width = 1280, height = 720): Promise<number> {
  const meta = index.meta;
  const z = zAtScale(meta, scale);
  const [x0, y0, x1, y1] = viewBox(scale, centre, width, height);
  let n = 0;
  for (const leaf of index.lines ?? []) {
    const [bx0, by0, bz0, bx1, by1, bz1] = leaf.bbox;
    if (bx1 < x0 || bx0 > x1 || by1 < y0 || by0 > y1 || z < bz0 || z >= bz1) continue;
    const c = await decodeLineChunk(await readFile(path.join(cubeDir, leaf.file)), leaf.file);
    for (let i = 0; i < c.lineCount; i++) {
      const l = lineOfChunk(c, i);
      if (!lineRuleDrawnAt(meta.style.lines[l.rule]!, scale)) continue;
      for (const p of linePathsAtZ(l, z)) {
        for (let k = 0; k < p.length; k += 2) if (p[k]! >= x0 && p[k]! <= x1 && p[k + 1]! >= y0 && p[k + 1]! <= y1) n++;
      }
    }
  }
  return n;
}
