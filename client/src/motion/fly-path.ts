// flyTo's path: van Wijk and Nuij's optimal path through space and scale (zoom out, pan, zoom
// in; "Smooth and efficient zooming and panning", 2003, the form d3-interpolate's
// interpolateZoom uses). The whole path is known before the flight starts, so the chunks along
// it can be fetched ahead of the view. Worked out here rather than imported: d3-interpolate's
// bundle keeps all of d3-color (12 kB, 4.6 kB gzip of the map's script) for this one function;
// its test checks this against d3's.
import type { Camera } from '../geometry/camera.js';
import { resolutionAtScale, scaleAtResolution } from '../geometry/view.js';

export const DEFAULT_RHO = 1.42;

/** Below this squared ground distance (in the view-width unit) the path is a zoom in place. */
const IN_PLACE2 = 1e-12;

export interface FlyPath {
  at(t: number): Camera;
  /** Duration at `speed` (path length per second, in the paper's units: 1.2 is MapLibre's). */
  durationMs(speed: number): number;
  /** `n` + 1 cameras evenly along the path, from start to end. */
  samples(n: number): Camera[];
}

/**
 * The path between centres (x0, y0) and (x1, y1) with view widths w0 and w1 (ground units):
 * the centre and width at each share `t` of its length, and the length S (the paper's units).
 */
export function zoomPath(x0: number, y0: number, w0: number, x1: number, y1: number, w1: number, rho: number): { at(t: number): [number, number, number]; length: number } {
  const dx = x1 - x0, dy = y1 - y0, d2 = dx * dx + dy * dy;
  const rho2 = rho * rho, rho4 = rho2 * rho2;
  if (d2 < IN_PLACE2) {
    // Along the scale alone: the width changes geometrically.
    const S = Math.log(w1 / w0) / rho;
    return { at: (t) => [x0 + t * dx, y0 + t * dy, w0 * Math.exp(rho * t * S)], length: Math.abs(S) };
  }
  const d = Math.sqrt(d2);
  const b0 = (w1 * w1 - w0 * w0 + rho4 * d2) / (2 * w0 * rho2 * d);
  const b1 = (w1 * w1 - w0 * w0 - rho4 * d2) / (2 * w1 * rho2 * d);
  const r0 = Math.log(Math.sqrt(b0 * b0 + 1) - b0);
  const S = (Math.log(Math.sqrt(b1 * b1 + 1) - b1) - r0) / rho;
  const coshR0 = Math.cosh(r0), sinhR0 = Math.sinh(r0);
  return {
    at: (t) => {
      const r = rho * t * S + r0;
      const u = (w0 / (rho2 * d)) * (coshR0 * Math.tanh(r) - sinhR0);
      return [x0 + u * dx, y0 + u * dy, (w0 * coshR0) / Math.cosh(r)];
    },
    length: Math.abs(S),
  };
}

/** The path from `a` to `b` for a view `widthPx` CSS pixels wide. */
export function flyPath(a: Camera, b: Camera, widthPx: number, pixelSizeMm: number, rho = DEFAULT_RHO): FlyPath {
  const w = (c: Camera): number => resolutionAtScale(c.scale, pixelSizeMm) * widthPx;
  const path = zoomPath(a.x, a.y, w(a), b.x, b.y, w(b), Math.max(0.001, rho));
  const at = (t: number): Camera => {
    if (t <= 0) return { ...a };
    if (t >= 1) return { ...b };
    const [x, y, width] = path.at(t);
    return { x, y, scale: scaleAtResolution(width / widthPx, pixelSizeMm) };
  };
  return {
    at,
    durationMs: (speed) => (1000 * path.length) / speed,
    samples: (n) => Array.from({ length: n + 1 }, (_, i) => at(i / n)),
  };
}
