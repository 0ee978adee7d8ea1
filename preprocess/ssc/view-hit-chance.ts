// The cost model of the chunk split: a chunk is fetched by the views whose ground box meets
// its box at a z in its z range. Its likelihood is the chance that a view placed at random, at
// a scale drawn evenly in log-scale from the chunk's z range, meets the chunk's ground box.

/** A box in the cube: ground x0, y0, x1, y1, then the z range z0, z1. */
export type Box6 = [number, number, number, number, number, number];

export interface ViewModel {
  extent: [number, number, number, number];
  /** Scale denominator at z. */
  scaleAt: (z: number) => number;
  /** Ground width and height of a view per unit of scale denominator (1280 x 720 px at 0.28 mm: 0.3584, 0.2016). */
  viewPerScale: [number, number];
}

/** The scale denominator at which the whole extent fits the model's view. */
export function wholeExtentScale(m: Pick<ViewModel, 'extent' | 'viewPerScale'>): number {
  const [vw, vh] = m.viewPerScale;
  const [ex0, ey0, ex1, ey1] = m.extent;
  return Math.max((ex1 - ex0) / vw, (ey1 - ey0) / vh);
}

/** The chance function for views over the extent, from the base scale to where the whole extent fits. */
export function viewHitChance(m: ViewModel): (...box: Box6) => number {
  const [vw, vh] = m.viewPerScale;
  const [ex0, ey0, ex1, ey1] = m.extent;
  const ew = ex1 - ex0, eh = ey1 - ey0;
  // Views are drawn evenly in log-scale from the base scale to where the whole extent fits.
  const sMin = Math.log(m.scaleAt(0)), sMax = Math.max(sMin + 0.1, Math.log(wholeExtentScale(m)));
  return (x0, y0, x1, y1, z0, z1) => {
    const s0 = Math.min(sMax, Math.log(m.scaleAt(z0))), s1 = Math.min(sMax, Math.log(m.scaleAt(Math.max(z0, z1))));
    if (s1 <= sMin && s0 <= sMin) return 0.05;
    const steps = 8;
    let sum = 0;
    for (let k = 0; k < steps; k++) {
      const sc = Math.exp(s0 + ((k + 0.5) / steps) * (s1 - s0));
      const w = vw * sc, h = vh * sc;
      sum += Math.min(1, (x1 - x0 + w) / (ew + w)) * Math.min(1, (y1 - y0 + h) / (eh + h));
    }
    // Weighted by the log-scale range: a chunk seen over more zoom is fetched more often.
    return (sum / steps) * Math.max(1e-9, s1 - s0 + 0.05);
  };
}
