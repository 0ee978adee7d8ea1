// How many removals of the same step still have to follow each one where it lies. The tGAP
// puts a step's overlapping removal triangles in successive phases (preprocess/tgap/simplify.ts),
// all inside that step. A smooth cube lets each one recede over up to a zoom level; but an
// overlapping later one must lie above it, so it could only start when the one before had
// ended, at its phase, and was squeezed into a fraction of the step. Where a refresh simplifies
// every edge at once, thousands are: nlcd_zion's worst frame. Knowing that h more must follow
// above it, a removal takes 1 / (h + 1) of its time and leaves the rest to them.
import Flatbush from 'flatbush';
import { trianglesOverlap } from '../geom/triangles-overlap.js';

/**
 * Per removal (in the order they are drawn; `coords`: 6 numbers per triangle, x0 y0 x1 y1 x2
 * y2; `phases`: the tGAP's phase of each), the longest chain of later removals of a higher
 * phase that overlap it, one after the other.
 */
export function removalHeights(coords: Float64Array, phases: ArrayLike<number>): Int32Array {
  const n = phases.length;
  const heights = new Int32Array(n);
  if (n < 2) return heights;
  const index = new Flatbush(n);
  for (let i = 0; i < n; i++) {
    const c = coords.subarray(6 * i, 6 * i + 6);
    index.add(Math.min(c[0]!, c[2]!, c[4]!), Math.min(c[1]!, c[3]!, c[5]!), Math.max(c[0]!, c[2]!, c[4]!), Math.max(c[1]!, c[3]!, c[5]!));
  }
  index.finish();
  for (let i = n - 1; i >= 0; i--) {
    const c = coords.subarray(6 * i, 6 * i + 6);
    const near = index.search(Math.min(c[0]!, c[2]!, c[4]!), Math.min(c[1]!, c[3]!, c[5]!), Math.max(c[0]!, c[2]!, c[4]!), Math.max(c[1]!, c[3]!, c[5]!));
    let h = 0;
    for (const j of near) {
      if (j > i && phases[j]! > phases[i]! && heights[j]! + 1 > h && trianglesOverlap(c, coords.subarray(6 * j, 6 * j + 6))) h = heights[j]! + 1;
    }
    heights[i] = h;
  }
  return heights;
}
