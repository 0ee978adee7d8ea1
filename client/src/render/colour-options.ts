// The look of the map the user chooses (blending, boundaries, the paint of faces whose feature
// state has highlight or hover) turned into the colour pass's parameters for one frame: device pixel
// sizes, the blend distance while it applies, and the pattern anchored to the ground so that it
// moves with the map.
import type { ViewGeometry } from '../geometry/view.js';
import type { FrameColourParams, StatePaintParams } from './colour-pass.js';
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

/** The feature states that are drawn, in the order painted: hover under highlight. */
export const DRAWN_STATES = ['hover', 'highlight'] as const;
export type DrawnState = (typeof DRAWN_STATES)[number];

/** How a face with `highlight: true` (or `hover: true`) in its feature state is drawn: on its own pixels only. */
export interface StatePaint {
  /** Mixed over the face's colour with `opacity` (0: no fill). */
  color: string;
  opacity: number;
  /** A line inside the face along its edges, `outlineWidth` CSS px wide (0: none). */
  outlineColor: string;
  outlineWidth: number;
}

export type StatePaints = Record<DrawnState, StatePaint>;

/** Selection: a yellow wash with a red edge; hover: a blue edge only. */
export const DEFAULT_STATE_PAINTS: StatePaints = {
  highlight: { color: '#ffd400', opacity: 0.5, outlineColor: '#d40000', outlineWidth: 2 },
  hover: { color: '#1a73e8', opacity: 0, outlineColor: '#1a73e8', outlineWidth: 2 },
};

/** Pattern period and line width, CSS pixels. */
const PATTERN_CELL = 8;
const PATTERN_LINE = 1.25;

export function colourParams(o: {
  view: ViewGeometry;
  /** Device pixels per CSS pixel. */
  ratio: number;
  boundaries: BoundaryOptions;
  paints: StatePaints;
  /** c, or 0 when blending does not apply to this frame. */
  blendDistance: number;
  /** This frame's weight in the accumulated colour. */
  weight: number;
}): FrameColourParams {
  const { view, ratio, boundaries: b } = o;
  // Boundary band: n device pixels, from the pixel before each id change to the one after.
  const n = b.enabled ? Math.max(1, Math.round(b.width * ratio)) : 0;
  const bc = parseColour(b.color);
  const cell = PATTERN_CELL * ratio;
  // gl_FragCoord + shift = ground coordinate / resolution (mod the cell): patterns stay on the
  // ground when the map pans. Worked out in float64 here; the shader gets the small remainder.
  const shiftX = view.centerX / view.resolution - view.width / 2;
  const shiftY = view.centerY / view.resolution - view.height / 2;
  const paint = (h: StatePaint): StatePaintParams => {
    const fill = parseColour(h.color), line = parseColour(h.outlineColor);
    return {
      fill: [fill[0], fill[1], fill[2], h.opacity],
      outline: [line[0], line[1], line[2], 1],
      width: h.outlineWidth > 0 ? Math.max(1, Math.round(h.outlineWidth * ratio)) : 0,
    };
  };
  return {
    blendDistance: o.blendDistance,
    boundaryBefore: Math.floor(n / 2),
    boundaryAfter: n - Math.floor(n / 2),
    boundaryColour: [bc[0], bc[1], bc[2], b.opacity],
    patternCell: cell,
    patternLine: PATTERN_LINE * ratio,
    patternShift: [((shiftX % cell) + cell) % cell, ((shiftY % cell) + cell) % cell],
    statePaints: DRAWN_STATES.map((s) => paint(o.paints[s])),
    weight: o.weight,
  };
}
