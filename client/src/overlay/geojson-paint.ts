// The paint of a GeoJSON overlay layer: colours ("#rrggbb"), opacities in [0, 1] and sizes in
// CSS px, checked with every problem named at once. Defaults are Leaflet's for GeoJSON paths
// (a blue line 3 px wide, a fill of the same blue at 0.2) rather than MapLibre's black, which
// would hide the map beneath; circles have MapLibre's radius 5 and a thin white ring that keeps
// them legible on any colour. Polygons are filled and outlined with the line paint (as
// Leaflet's paths); lineWidth 0 leaves the outline off.
import type { OverlayPaintParams } from '../render/overlay-pass.js';
import { parseColour } from '../render/style-texture.js';

export interface GeoJsonPaint {
  /** Polygons' interior. */
  fillColor: string;
  fillOpacity: number;
  /** LineStrings, and polygons' outlines; width in CSS px (0: none). */
  lineColor: string;
  lineWidth: number;
  lineOpacity: number;
  /** Points, as circles; radius in CSS px. */
  circleColor: string;
  circleRadius: number;
  circleOpacity: number;
  /** A ring around each circle, outside its radius (CSS px; 0: none). */
  circleStrokeColor: string;
  circleStrokeWidth: number;
  circleStrokeOpacity: number;
}

export const DEFAULT_GEOJSON_PAINT: Readonly<GeoJsonPaint> = {
  fillColor: '#3388ff',
  fillOpacity: 0.2,
  lineColor: '#3388ff',
  lineWidth: 3,
  lineOpacity: 1,
  circleColor: '#3388ff',
  circleRadius: 5,
  circleOpacity: 1,
  circleStrokeColor: '#ffffff',
  circleStrokeWidth: 1,
  circleStrokeOpacity: 1,
};

const COLOURS = ['fillColor', 'lineColor', 'circleColor', 'circleStrokeColor'] as const;
const OPACITIES = ['fillOpacity', 'lineOpacity', 'circleOpacity', 'circleStrokeOpacity'] as const;
const SIZES = ['lineWidth', 'circleRadius', 'circleStrokeWidth'] as const;

/** `base` with `change` merged in, or an Error (`what` starts it) naming every wrong value. */
export function mergePaint(base: GeoJsonPaint, change: Partial<GeoJsonPaint>, what: string): GeoJsonPaint {
  if (typeof change !== 'object' || change === null) throw new Error(`${what}: the paint must be an object, not ${JSON.stringify(change)}`);
  const problems: string[] = [];
  const known = new Set<string>([...COLOURS, ...OPACITIES, ...SIZES]);
  for (const k of Object.keys(change)) if (!known.has(k)) problems.push(`"${k}" is not a paint property (${[...known].join(', ')})`);
  const p = { ...base, ...change };
  for (const k of COLOURS) {
    try {
      parseColour(p[k], k);
    } catch (err) {
      problems.push((err as Error).message);
    }
  }
  for (const k of OPACITIES) if (!(typeof p[k] === 'number' && p[k] >= 0 && p[k] <= 1)) problems.push(`${k} must be a number in [0, 1], not ${JSON.stringify(p[k])}`);
  for (const k of SIZES) if (!(typeof p[k] === 'number' && Number.isFinite(p[k]) && p[k] >= 0)) problems.push(`${k} must be a number of CSS px >= 0, not ${JSON.stringify(p[k])}`);
  if (problems.length > 0) throw new Error(`${what}: ${problems.join('; ')}`);
  return p;
}

/** The paint as the overlay pass takes it: each colour with its opacity as alpha. */
export function paintParams(p: GeoJsonPaint): OverlayPaintParams {
  const rgba = (colour: string, opacity: number): [number, number, number, number] => {
    const c = parseColour(colour);
    return [c[0], c[1], c[2], c[3] * opacity];
  };
  return {
    fill: rgba(p.fillColor, p.fillOpacity),
    line: rgba(p.lineColor, p.lineOpacity),
    circle: rgba(p.circleColor, p.circleOpacity),
    circleStroke: rgba(p.circleStrokeColor, p.circleStrokeOpacity),
    lineWidth: p.lineWidth,
    circleRadius: p.circleRadius,
    circleStrokeWidth: p.circleStrokeWidth,
  };
}
