// The comparison mode of usability tests: the same cube shown as a classic multi-scale map,
// whose content exists only at a few scales (the base scale times powers of a factor, as the
// seed paper's multi-scale test data: 1:10 000, 1:20 000, 1:40 000, ...). The view still zooms
// continuously; its content snaps to the level a tiled map would show there.

/** Level scale denominators from `baseScale` up by `factor` until one reaches `maxScale`. */
export function discreteLevels(baseScale: number, maxScale: number, factor = 2): number[] {
  if (!(factor > 1) || !(baseScale > 0)) throw new Error('discrete levels need a base scale > 0 and a factor > 1');
  const out = [baseScale];
  while (out[out.length - 1]! < maxScale && out.length < 64) out.push(out[out.length - 1]! * factor);
  return out;
}

/** The level shown at `scale`: the nearest in log scale (as a tiled map rounds its zoom). */
export function levelFor(levels: readonly number[], scale: number): number {
  let best = levels[0]!;
  for (const l of levels) if (Math.abs(Math.log(scale / l)) < Math.abs(Math.log(scale / best))) best = l;
  return best;
}
