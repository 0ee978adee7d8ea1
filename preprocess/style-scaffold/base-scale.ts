// The base scale recommended for data without one (docs/STYLE.md, "Choosing baseScale").
// The map keeps a constant number of faces per map area at every scale (format/scale.ts), so
// the base scale sets how dense every scale of the map is: it is chosen so that the data's
// mean face, its area divided by its face count, is MEAN_FACE_PX resolution pixels across.

/** How many resolution pixels (0.28 mm by default) the mean face spans at the base scale. */
export const MEAN_FACE_PX = 20;

/** Rounds up or down to 1, 2 or 5 x 10^n, the nearest in ratio. */
export function roundScale(raw: number): number {
  const e = Math.pow(10, Math.floor(Math.log10(raw)));
  const m = raw / e;
  return (m < 1.5 ? 1 : m < 3.5 ? 2 : m < 7.5 ? 5 : 10) * e;
}

/** Base scale denominator at which a face of the data's mean area is MEAN_FACE_PX pixels across. */
export function recommendBaseScale(totalArea: number, faces: number, resolutionMm: number): number {
  const side = Math.sqrt(totalArea / Math.max(1, faces));
  if (!(side > 0)) return 1;
  return Math.max(1, roundScale(side / ((MEAN_FACE_PX * resolutionMm) / 1000)));
}
