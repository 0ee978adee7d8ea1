// The position grid of a cube's chunks: one power of two for every chunk, so that a point
// shared by two chunks decodes to the same value in both (origins are whole units, on the grid),
// and no finer than needed: about 1/256 of a pixel at the base scale (bgt_otterlo_1800m at
// 1:1,000: 2^-10 m, about 1 mm; nlcd_zion at 1:50,000: 2^-5 m, and 2^-8 m chosen, below). Each
// chunk's box grid (its 24 bits) is finer than that on data of ordinary size, and a finer grid
// mostly costs bytes: on bgt_otterlo_1800m the chunks' points took 1.36 MB gzip at the box
// grids (2^-13 m), 1.05 MB at 2^-10, 0.81 MB at 2^-7. Not coarser: a GPU snaps vertices to its own sub-pixel grid, and at
// 1/32 of a pixel a corner moved that far left a pixel of the e2e lens test uncovered.
// Finer is not always larger, though: meshoptimizer's vertex codec takes the deltas byte by
// byte, so where a step falls within a byte matters. nlcd_zion's points took 1.85 MB at 2^-5,
// 1.58 MB at 2^-8. So the build tries the grid and the three finer ones on a sample of chunks
// and keeps the one that encodes smallest (chooseGrid).

/** Grid steps per pixel of the base scale. */
export const GRID_STEPS_PER_PIXEL = 256;

/**
 * The grid exponent e (steps of 2^e ground units) for a cube drawn at `baseScale` with pixels of
 * `pixelSizeMm`: the largest with 2^e at most a 256th of a base pixel, and at most 1 unit, so
 * that whole-unit origins lie on the grid.
 */
export function cubeGridExponent(baseScale: number, pixelSizeMm: number): number {
  const step = (baseScale * pixelSizeMm) / 1000 / GRID_STEPS_PER_PIXEL;
  if (!(step > 0) || !Number.isFinite(step)) throw new Error(`no position grid for base scale ${baseScale} and pixel size ${pixelSizeMm} mm`);
  let e = Math.min(0, Math.floor(Math.log2(step)));
  // log2 may round across a power of two: settle on the exact one.
  while (e < 0 && 2 ** (e + 1) <= step) e++;
  while (2 ** e > step) e--;
  return e;
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
