// Hand-made polygon inputs for the topology and refusal tests: tiny GeoJSON files drawn in
// small local numbers, written shifted into a projected CRS, with a style for their classes.
import { readdirSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { tempDir } from './temp-dir.js';

export type Json = null | boolean | number | string | Json[] | { [key: string]: Json };
export type XY = [number, number];

// Fixtures are drawn in small local numbers and written shifted by (OX, OY), in a projected
// CRS: (0, 0) is (1000, 2000) in the file. The two offsets differ so that a swapped x and y
// would show.
export const OX = 1000, OY = 2000;
export const CRS = 'EPSG:28992';
export const at = (x: number, y: number): XY => [OX + x, OY + y];

/** Counterclockwise rectangle, open (no closing point). */
export const rect = (x0: number, y0: number, x1: number, y1: number): XY[] => [[x0, y0], [x1, y0], [x1, y1], [x0, y1]];
/** Shifted positions of a local ring, closed unless `open`. */
export const ring = (pts: XY[], open = false): Json[] => {
  const out: Json[] = pts.map(([x, y]) => at(x, y));
  return open ? out : [...out, at(pts[0]![0], pts[0]![1])];
};
export const polygon = (...rings: XY[][]): Json => ({ type: 'Polygon', coordinates: rings.map((r) => ring(r)) });
export const feature = (id: string | null, geometry: Json, cls = 'field'): Json => ({
  type: 'Feature',
  properties: id === null ? { cls } : { id, cls },
  geometry,
});
export const collection = (features: Json[], crs: string | null = CRS): Json => ({
  type: 'FeatureCollection',
  ...(crs ? { crs: { type: 'name', properties: { name: crs } } } : {}),
  features,
});

export const STYLE = {
  name: 'topology cases',
  classProperty: 'cls',
  baseScale: 1000,
  classes: {
    field: { color: '#b3d49a', weight: 1 },
    water: { color: '#9ec9e8', weight: 2 },
  },
};

export interface Case {
  dir: string;
  input: string;
  style: string;
  /** Files in the folder before any run: what must still be all that is there after a refusal. */
  files: string[];
}

export function writeCase(t: { after: (fn: () => void) => void }, name: string, doc: Json | string, style: object = STYLE): Case {
  const dir = tempDir(t);
  const input = path.join(dir, name);
  writeFileSync(input, typeof doc === 'string' ? doc : JSON.stringify(doc));
  const styleFile = path.join(dir, 'style.json');
  writeFileSync(styleFile, JSON.stringify(style));
  return { dir, input, style: styleFile, files: readdirSync(dir).sort() };
}
