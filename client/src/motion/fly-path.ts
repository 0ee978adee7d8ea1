// flyTo's path: van Wijk and Nuij's optimal path through space and scale (zoom out, pan, zoom
// in), from d3-interpolate's interpolateZoom. The whole path is known before the flight starts,
// so the chunks along it can be fetched ahead of the view.
import { interpolateZoom } from 'd3-interpolate';
import type { Camera } from '../geometry/camera.js';
import { resolutionAtScale, scaleAtResolution } from '../geometry/view.js';

export const DEFAULT_RHO = 1.42;

// @types/d3-interpolate puts rho() on the interpolator; d3 has it on the factory.
const zoomWithRho = (rho: number): typeof interpolateZoom => (interpolateZoom as typeof interpolateZoom & { rho(r: number): typeof interpolateZoom }).rho(rho);

export interface FlyPath {
  at(t: number): Camera;
  /** Duration at `speed` (path length per second, in the paper's units: 1.2 is MapLibre's). */
  durationMs(speed: number): number;
  /** `n` + 1 cameras evenly along the path, from start to end. */
  samples(n: number): Camera[];
}

/** The path from `a` to `b` for a view `widthPx` CSS pixels wide. */
export function flyPath(a: Camera, b: Camera, widthPx: number, pixelSizeMm: number, rho = DEFAULT_RHO): FlyPath {
  const w = (c: Camera): number => resolutionAtScale(c.scale, pixelSizeMm) * widthPx;
  const interp = zoomWithRho(rho)([a.x, a.y, w(a)], [b.x, b.y, w(b)]);
  // d3 gives its duration as S * 1000 * rho / sqrt(2) ms, S being the path length.
  const length = (interp.duration * Math.SQRT2) / (1000 * rho);
  const at = (t: number): Camera => {
    if (t <= 0) return { ...a };
    if (t >= 1) return { ...b };
    const [x, y, width] = interp(t);
    return { x, y, scale: scaleAtResolution(width / widthPx, pixelSizeMm) };
  };
  return {
    at,
    durationMs: (speed) => (1000 * length) / speed,
    samples: (n) => Array.from({ length: n + 1 }, (_, i) => at(i / n)),
  };
}
