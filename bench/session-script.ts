// bench:session's scripted session over a cube: from the base scale at the data's centre out to
// the full extent, a pan of a quarter of the data's width, and back in (bench:bounds sizes
// encodings on the same views).
import type { CubeMeta } from '../format/cube-index.js';
import type { ProjectedView } from './scale-zoom.js';
import { groundPerScale } from '../format/pixel-size.js';
import { wholeExtentScale } from '../preprocess/ssc/view-hit-chance.js';

export const SESSION_WIDTH = 1280, SESSION_HEIGHT = 720;

export interface Session {
  start: ProjectedView;
  /** The scale at which the whole extent fits the view: the map's default first view. */
  fullScale: number;
  /** Each frame's view and the phase it belongs to. */
  frames: { phase: string; view: ProjectedView }[];
}

/** The scale at which the whole extent fits a view of `width` x `height` px of the cube's pixel size. */
export const fitScale = (meta: Pick<CubeMeta, 'extent' | 'pixelSizeMm'>, width: number, height: number): number =>
  wholeExtentScale({ extent: meta.extent, viewPerScale: groundPerScale(width, height, meta.pixelSizeMm) });

export function scriptedSession(meta: CubeMeta, zoomOutFrames: number): Session {
  const [x0, y0, x1, y1] = meta.extent;
  const centre: [number, number] = [(x0 + x1) / 2, (y0 + y1) / 2];
  const base = meta.baseScale;
  const full = fitScale(meta, SESSION_WIDTH, SESSION_HEIGHT);
  const frames: Session['frames'] = [];
  for (let i = 1; i <= zoomOutFrames; i++) frames.push({ phase: 'zoom out', view: { center: centre, scale: base * (full / base) ** (i / zoomOutFrames) } });
  // A quarter of the data's width: at the full extent half the view would leave the data
  // (bgt_otterlo_1800m is square, the view wide), and the zoom in must end on it.
  const panFrames = Math.max(1, Math.round(zoomOutFrames / 6));
  const end: [number, number] = [centre[0] + (x1 - x0) / 4, centre[1]];
  for (let i = 1; i <= panFrames; i++) frames.push({ phase: 'pan', view: { center: [centre[0] + (end[0] - centre[0]) * (i / panFrames), centre[1]], scale: full } });
  const inFrames = Math.max(1, Math.round(zoomOutFrames / 2));
  for (let i = 1; i <= inFrames; i++) frames.push({ phase: 'zoom in', view: { center: end, scale: full * (base / full) ** (i / inFrames) } });
  return { start: { center: centre, scale: base }, fullScale: full, frames };
}
