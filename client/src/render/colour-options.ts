// The look of the map the user chooses (blending, boundaries) turned into the colour pass's
// parameters for one frame: device pixel sizes, the blend distance while it applies, and the
// pattern anchored to the ground so that it moves with the map.
import type { ViewGeometry } from '../geometry/view.js';
import type { ColourParams } from './colour-pass.js';
import { parseColour } from './style-texture.js';

export type BlendMode = 'off' | 'moving' | 'always';

export interface BlendingOptions {
  /** 'moving': only while the slice moves (zoom, surface changes); 'always'; 'off'. */
  mode: BlendMode;
  /** c: surfaces less than this many steps below the slice blend toward the face below. */
  distance: number;
}

export interface BoundaryOptions {
  enabled: boolean;
  /** Line width in CSS pixels. */
  width: number;
  color: string;
  opacity: number;
}

/** Pattern period and line width, CSS pixels. */
const PATTERN_CELL = 8;
const PATTERN_LINE = 1.25;

export function colourParams(o: {
  view: ViewGeometry;
  /** Device pixels per CSS pixel. */
  ratio: number;
  background: string;
  boundaries: BoundaryOptions;
  /** c, or 0 when blending does not apply to this frame. */
  blendDistance: number;
  /** This frame's weight in the accumulated colour. */
  weight: number;
}): Omit<ColourParams, 'style' | 'classCount'> {
  const { view, ratio, boundaries: b } = o;
  // Boundary band: n device pixels, from the pixel before each id change to the one after.
  const n = b.enabled ? Math.max(1, Math.round(b.width * ratio)) : 0;
  const bc = parseColour(b.color);
  const cell = PATTERN_CELL * ratio;
  // gl_FragCoord + shift = ground coordinate / resolution (mod the cell): patterns stay on the
  // ground when the map pans. Worked out in float64 here; the shader gets the small remainder.
  const shiftX = view.centerX / view.resolution - view.width / 2;
  const shiftY = view.centerY / view.resolution - view.height / 2;
  return {
    background: parseColour(o.background),
    blendDistance: o.blendDistance,
    boundaryBefore: Math.floor(n / 2),
    boundaryAfter: n - Math.floor(n / 2),
    boundaryColour: [bc[0], bc[1], bc[2], b.opacity],
    patternCell: cell,
    patternLine: PATTERN_LINE * ratio,
    patternShift: [((shiftX % cell) + cell) % cell, ((shiftY % cell) + cell) % cell],
    weight: o.weight,
  };
}
