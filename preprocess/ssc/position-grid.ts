// The grids of a cube: the one its input is snapped to (the tGAP's precision) and the position
// grid of its chunks, one power of two for every chunk, so that a point shared by two chunks
// decodes to the same value in both (origins are whole units, on the grid).
//
// The chunks' grid is no finer than needed: about 1/256 of a pixel at the base scale
// (bgt_otterlo_1800m at 1:1,000: 2^-10 m, about 1 mm; nlcd_zion at 1:50,000: 2^-5 m). Each
// chunk's box grid (its 24 bits) is finer than that on data of ordinary size, and a finer grid
// mostly costs bytes: on bgt_otterlo_1800m the chunks' points took 1.36 MB gzip at the box grids
// (2^-13 m), 1.05 MB at 2^-10, 0.81 MB at 2^-7. Finer is not always larger, though:
// meshoptimizer's vertex codec takes the deltas byte by byte, so where a step falls within a
// byte matters. nlcd_zion's points took 1.85 MB at 2^-5, 1.58 MB at 2^-8. So the build tries the
// grid and the three finer ones on a sample of chunks and keeps the one that encodes smallest
// (chooseGrid).
//
// The input is snapped by default to a coarser power of two, 1/32 of a base pixel (2^-7 m, 7.8 mm,
// at 1:1,000; 2^-2 m at 1:50,000), and the chunks' grid may then be that one, or the input's
// own when coarser (pointGrid: 1 m for nlcd_zion's whole metres): every input point
// lies on it exactly, and the points the generalization and the surfaces make (split midpoints
// and centres) are put on it where they can be (snap-new-vertices.ts). On bgt_otterlo_1800m the chunks
// took 2.31 MB gzip with the input snapped to 1 mm and the chunks on 2^-10 m, 2.08 MB with both
// on 2^-7 m; its line chunks 0.29 and 0.24 MB. Rounding every point to 2^-7 m instead (1/36 of a
// pixel, the input on 1 mm) moved corners enough to leave a pixel of the e2e lens test
// uncovered; a decimal grid such as 1 mm is rounded so, and its chunks keep the 1/256 grid.

/** Grid steps per pixel of the base scale: the chunks' grid. */
export const GRID_STEPS_PER_PIXEL = 256;

/** Steps per pixel of the base scale of the default snapping grid (`defaultPrecision`). */
export const SNAP_STEPS_PER_PIXEL = 32;

/**
 * The exponent e of the largest power of two at most a `perPixel`th of a pixel of `pixelSizeMm`
 * at `baseScale`, and at most 1 unit, so that whole-unit origins lie on it.
 */
function gridExponentPerPixel(baseScale: number, pixelSizeMm: number, perPixel: number): number {
  const step = (baseScale * pixelSizeMm) / 1000 / perPixel;
  if (!(step > 0) || !Number.isFinite(step)) throw new Error(`no position grid for base scale ${baseScale} and pixel size ${pixelSizeMm} mm`);
  let e = Math.min(0, Math.floor(Math.log2(step)));
  // log2 may round across a power of two: settle on the exact one.
  while (e < 0 && 2 ** (e + 1) <= step) e++;
  while (2 ** e > step) e--;
  return e;
}

/**
 * The grid exponent e (steps of 2^e ground units) for a cube drawn at `baseScale` with pixels of
 * `pixelSizeMm`: the largest with 2^e at most a 256th of a base pixel, and at most 1 unit.
 */
export const cubeGridExponent = (baseScale: number, pixelSizeMm: number): number => gridExponentPerPixel(baseScale, pixelSizeMm, GRID_STEPS_PER_PIXEL);

/** The input's snapping grid when none is given (`ssc generalize --precision`): 2^e at most a 32nd of a base pixel, at most 1 unit. */
export const defaultPrecision = (baseScale: number, pixelSizeMm: number): number => 2 ** gridExponentPerPixel(baseScale, pixelSizeMm, SNAP_STEPS_PER_PIXEL);

/** The coarsest grid of its own an input's points may keep (pointGrid), in steps per base pixel. */
export const POINT_GRID_STEPS_PER_PIXEL = 8;

/**
 * The coarsest power of two coarser than defaultPrecision, up to an 8th of a base pixel and 1
 * unit, of which every coordinate is a whole multiple; null when there is none. The snapped
 * input's points (topology vertices) of nlcd_zion, in whole metres at 1:50,000, lie on 1 m; the
 * points the build makes then go to that grid, and so may the chunks (coarsestGrid): 1 m
 * instead of 2^-2 m, about a 14th of a pixel, and the chunks of its whole-extent view 1,520 ->
 * 1,447 kB gzip (docs/FORMAT.md, "Chunk file"). The snapping precision, also the tolerance of
 * the topology's repairs, stays as it was.
 */
export function pointGrid(baseScale: number, pixelSizeMm: number, coordinates: Iterable<ArrayLike<number>>): number | null {
  const finest = gridExponentPerPixel(baseScale, pixelSizeMm, SNAP_STEPS_PER_PIXEL);
  let e = gridExponentPerPixel(baseScale, pixelSizeMm, POINT_GRID_STEPS_PER_PIXEL);
  for (const run of coordinates) {
    for (let i = 0; i < run.length; i++) {
      // Dividing by a power of two is exact: v is a multiple of 2^e exactly when the quotient is whole.
      while (!Number.isInteger(run[i]! / 2 ** e)) if (--e <= finest) return null;
    }
  }
  return e > finest ? 2 ** e : null;
}

/**
 * The coarsest grid the chunks of a cube may take (chooseGrid tries it and finer ones): the
 * cube's grid, or the input's snapping grid `precision` when that is a power of two coarser than
 * it (every input point lies on it), at most 1 unit.
 */
export function coarsestGrid(baseScale: number, pixelSizeMm: number, precision: number): number {
  const e = cubeGridExponent(baseScale, pixelSizeMm);
  const p = Math.round(Math.log2(precision));
  return precision > 0 && 2 ** p === precision ? Math.max(e, Math.min(0, p)) : e;
}

/** Grids tried below the coarsest allowed (bestGrid). */
export const GRID_CANDIDATES = 4;

/**
 * Of the grids `coarsest`, `coarsest - 1`, ... (GRID_CANDIDATES of them), the one for which
 * `bytes` (the encoded size of a sample of the cube's chunks on it) is least; on a tie the
 * coarser. Deterministic as `bytes` is.
 */
export function chooseGrid(coarsest: number, bytes: (e: number) => number): number {
  let best = coarsest, least = bytes(coarsest);
  for (let e = coarsest - 1; e > coarsest - GRID_CANDIDATES; e--) {
    const b = bytes(e);
    if (b < least) {
      least = b;
      best = e;
    }
  }
  return best;
}
