// A first style for a dataset (`ssc style`, docs/STYLE.md): its classes with colours from a
// known nomenclature or their names, linear classes suggested from the faces' shape, and a
// base scale from the faces' size. The style is a starting point a user edits.
import path from 'node:path';
import type { RawInput } from '../io/read-input.js';
import { InputError } from '../io/errors.js';
import { PIXEL_SIZE_MM } from '../../format/pixel-size.js';
import type { StyleJson } from '../../format/style.js';
import { recommendBaseScale } from './base-scale.js';
import { chooseClassColours, ONE_CLASS_COLOR, type ChosenClass } from './class-colours.js';
import { classStats, guessClassProperty, guessIdProperty, type ClassPropertyGuess, type ClassStats } from './class-stats.js';

/** A class is suggested linear when its faces are at least this elongated (a strip about 12 times longer than wide)... */
export const LINEAR_MIN_ELONGATION = 3;
/** ...and narrower than this many resolution pixels at the base scale (class-stats.ts has both measures). */
export const LINEAR_MAX_WIDTH_PX = 8;

export interface ScaffoldRow extends ClassStats, ChosenClass {
  linear: boolean;
}

export interface Scaffold {
  style: StyleJson;
  /** How the class property was found: given, guessed (with the candidates) or none. */
  classProperty: { name: string | null; given: boolean; guess: ClassPropertyGuess | null };
  rows: ScaffoldRow[];
  /** Mean face side in CRS units, from which the base scale follows. */
  meanFaceSide: number;
}

/** The class value of every feature; features without one are named together in one error. */
function classValues(raw: RawInput, property: string | null): string[] {
  if (property === null) return raw.features.map(() => 'all');
  const missing: string[] = [];
  const values = raw.features.map((f) => {
    const v = f.properties[property];
    if (v === undefined || v === null || (typeof v !== 'string' && typeof v !== 'number' && typeof v !== 'boolean')) {
      missing.push(`#${f.ref.index}${f.ref.id !== null ? ` (id ${JSON.stringify(f.ref.id)})` : ''}`);
      return '';
    }
    return String(v);
  });
  if (missing.length > 0) {
    const shown = missing.slice(0, 10).join(', ') + (missing.length > 10 ? `, and ${missing.length - 10} more` : '');
    throw new InputError(`${missing.length} of ${raw.features.length} features have no value for the class property ${JSON.stringify(property)}: ${shown}`, { file: raw.file });
  }
  return values;
}

export function scaffoldStyle(raw: RawInput, opts: { classProperty?: string } = {}): Scaffold {
  const guess = opts.classProperty === undefined ? guessClassProperty(raw.features) : null;
  const property = opts.classProperty ?? guess!.property;
  const values = classValues(raw, property);
  const stats = classStats(raw.features, (_, i) => values[i]!);
  const totalArea = stats.reduce((s, c) => s + c.area, 0);
  const faces = raw.features.length;
  const resolutionMm = PIXEL_SIZE_MM;
  const baseScale = recommendBaseScale(totalArea, faces, resolutionMm);
  const maxWidth = (LINEAR_MAX_WIDTH_PX * resolutionMm * baseScale) / 1000;
  const chosen = property === null
    ? [{ key: 'all', label: 'all', color: ONE_CLASS_COLOR, weight: 1, source: 'one class' }]
    : chooseClassColours(stats.map((s) => s.key));
  const rows: ScaffoldRow[] = stats.map((s, i) => ({
    ...s,
    ...chosen[i]!,
    linear: s.elongation >= LINEAR_MIN_ELONGATION && s.width < maxWidth,
  }));
  const style: StyleJson = {
    name: path.basename(raw.file).replace(/\.(geo|topo)?json(\.gz)?$/i, ''),
    classProperty: property,
    idProperty: guessIdProperty(raw.features),
    baseScale,
    resolutionMm,
    allowHoles: false,
    background: '#ffffff',
    attribution: '',
    defaultCompatibility: 0.5,
    classes: Object.fromEntries(rows.map((r) => [r.key, { label: r.label, color: r.color, weight: r.weight, linear: r.linear }])),
  };
  return { style, classProperty: { name: property, given: opts.classProperty !== undefined, guess }, rows, meanFaceSide: Math.sqrt(totalArea / Math.max(1, faces)) };
}

/** The style as JSON with one line per class, as the bundled styles are written. */
export function formatStyleJson(style: StyleJson): string {
  const lines = Object.entries(style).map(([k, v]) => {
    if (k !== 'classes' || Array.isArray(v) || typeof v !== 'object' || v === null) return `  ${JSON.stringify(k)}: ${JSON.stringify(v)}`;
    const cls = Object.entries(v as Record<string, Record<string, unknown>>).map(
      ([key, c]) => `    ${JSON.stringify(key)}: { ${Object.entries(c).map(([f, x]) => `${JSON.stringify(f)}: ${JSON.stringify(x)}`).join(', ')} }`,
    );
    return `  "classes": {\n${cls.join(',\n')}\n  }`;
  });
  return `{\n${lines.join(',\n')}\n}\n`;
}
