// A dataset's style: which property holds the class, and per class its colour, importance
// weight, compatibility with other classes and whether it is linear (split, not merged).
import { promises as fs } from 'node:fs';
import { InputError } from './io/errors.js';

export interface ClassStyle {
  /** The class value as it appears in the data (numbers are written as strings). */
  key: string;
  label: string;
  /** CSS hex colour "#rrggbb". */
  color: string;
  /** Importance per unit area: the least important face (area x weight) goes first. */
  weight: number;
  /** Long thin faces (roads, watercourses): split among their neighbours instead of merged whole. */
  linear: boolean;
  /** Optional pattern drawn over the fill within a scale range (client side). */
  pattern?: { kind: 'hatch' | 'dots' | 'cross'; color: string; minScale?: number; maxScale?: number };
}

export interface Style {
  name: string;
  classProperty: string | null;
  idProperty: string | null;
  /** Scale denominator of the input data (step 0). */
  baseScale: number;
  /** Simplification tolerance on the map, in mm (a screen pixel is 0.28 mm). */
  resolutionMm: number;
  /** Holes in the union of the faces are outside the domain (enclaves), not gaps. */
  allowHoles: boolean;
  background: string;
  classes: ClassStyle[];
  /** compat[loser][neighbour] in [0, 1], indexed like `classes`. */
  compat: Float64Array[];
  attribution: string;
}

interface StyleJson {
  name?: unknown;
  classProperty?: unknown;
  idProperty?: unknown;
  baseScale?: unknown;
  resolutionMm?: unknown;
  allowHoles?: unknown;
  background?: unknown;
  attribution?: unknown;
  defaultCompatibility?: unknown;
  classes?: unknown;
  compatibility?: unknown;
}

const HEX = /^#[0-9a-fA-F]{6}$/;

export async function loadStyle(file: string): Promise<Style> {
  let text: string;
  try {
    text = await fs.readFile(file, 'utf8');
  } catch (err) {
    throw new InputError(`cannot read style: ${(err as Error).message}`, { file });
  }
  let json: unknown;
  try {
    json = JSON.parse(text);
  } catch (err) {
    throw new InputError(`style is not valid JSON: ${(err as Error).message}`, { file });
  }
  return parseStyle(json, file);
}

export function parseStyle(json: unknown, file = 'style'): Style {
  const bad = (msg: string): never => {
    throw new InputError(`style: ${msg}`, { file });
  };
  if (typeof json !== 'object' || json === null || Array.isArray(json)) bad('expected a JSON object');
  const s = json as StyleJson;
  const str = (v: unknown, what: string, dflt: string | null): string | null => {
    if (v === undefined) return dflt;
    if (typeof v !== 'string') bad(`"${what}" must be a string`);
    return v as string;
  };
  const num = (v: unknown, what: string, dflt: number, min: number): number => {
    if (v === undefined) return dflt;
    if (typeof v !== 'number' || !Number.isFinite(v) || v < min) bad(`"${what}" must be a number >= ${min}`);
    return v as number;
  };
  // Classes as an object (class -> settings) or, where the order must be kept exactly (numeric
  // keys sort first in a JSON object), as an array of settings with a "key" each.
  let entries: [string, unknown][];
  if (Array.isArray(s.classes)) {
    entries = s.classes.map((c, i) => {
      const key = typeof c === 'object' && c !== null ? (c as { key?: unknown }).key : undefined;
      if (typeof key !== 'string' && typeof key !== 'number') bad(`classes[${i}] needs a "key"`);
      return [String(key), c] as [string, unknown];
    });
  } else if (typeof s.classes === 'object' && s.classes !== null) {
    entries = Object.entries(s.classes as Record<string, unknown>);
  } else {
    bad('"classes" must be an object of class -> {color, weight, linear}');
  }
  entries = entries!;
  if (new Set(entries.map((e) => e[0])).size !== entries.length) bad('a class is defined twice');
  if (entries.length === 0) bad('"classes" is empty');
  if (entries.length > 65535) bad('more than 65535 classes');
  const classes: ClassStyle[] = entries.map(([key, v]) => {
    if (typeof v !== 'object' || v === null) bad(`class ${JSON.stringify(key)} must be an object`);
    const c = v as Record<string, unknown>;
    const color = c.color;
    if (typeof color !== 'string' || !HEX.test(color)) bad(`class ${JSON.stringify(key)}: "color" must be "#rrggbb"`);
    const weight = c.weight === undefined ? 1 : c.weight;
    if (typeof weight !== 'number' || !(weight > 0) || !Number.isFinite(weight)) bad(`class ${JSON.stringify(key)}: "weight" must be a positive number`);
    if (c.linear !== undefined && typeof c.linear !== 'boolean') bad(`class ${JSON.stringify(key)}: "linear" must be true or false`);
    const out: ClassStyle = {
      key,
      label: typeof c.label === 'string' ? c.label : key,
      color: (color as string).toLowerCase(),
      weight: weight as number,
      linear: c.linear === true,
    };
    if (c.pattern !== undefined) out.pattern = parsePattern(c.pattern, key, bad);
    return out;
  });
  const index = new Map(classes.map((c, i) => [c.key, i]));
  const dflt = num(s.defaultCompatibility, 'defaultCompatibility', 0.5, 0);
  if (dflt > 1) bad('"defaultCompatibility" must be in [0, 1]');
  const compat = classes.map((_, i) => {
    const row = new Float64Array(classes.length).fill(dflt);
    row[i] = 1;
    return row;
  });
  if (s.compatibility !== undefined) {
    if (typeof s.compatibility !== 'object' || s.compatibility === null) bad('"compatibility" must be an object of loser -> {neighbour: value}');
    for (const [a, row] of Object.entries(s.compatibility as Record<string, unknown>)) {
      const ia = index.get(a);
      if (ia === undefined) bad(`compatibility names unknown class ${JSON.stringify(a)}`);
      if (typeof row !== 'object' || row === null) bad(`compatibility of ${JSON.stringify(a)} must be an object`);
      for (const [b, v] of Object.entries(row as Record<string, unknown>)) {
        const ib = index.get(b);
        if (ib === undefined) bad(`compatibility ${JSON.stringify(a)} names unknown class ${JSON.stringify(b)}`);
        if (typeof v !== 'number' || v < 0 || v > 1) bad(`compatibility ${JSON.stringify(a)} -> ${JSON.stringify(b)} must be in [0, 1]`);
        compat[ia!]![ib!] = v as number;
      }
    }
  }
  const background = str(s.background, 'background', '#ffffff')!;
  if (!HEX.test(background)) bad('"background" must be "#rrggbb"');
  if (s.allowHoles !== undefined && typeof s.allowHoles !== 'boolean') bad('"allowHoles" must be true or false');
  return {
    name: str(s.name, 'name', 'unnamed')!,
    classProperty: str(s.classProperty, 'classProperty', null),
    idProperty: str(s.idProperty, 'idProperty', null),
    baseScale: num(s.baseScale, 'baseScale', 0, 1),
    resolutionMm: num(s.resolutionMm, 'resolutionMm', 0.28, 0),
    allowHoles: s.allowHoles === true,
    background: background.toLowerCase(),
    classes,
    compat,
    attribution: str(s.attribution, 'attribution', '')!,
  };
}

function parsePattern(v: unknown, key: string, bad: (m: string) => never): NonNullable<ClassStyle['pattern']> {
  if (typeof v !== 'object' || v === null) bad(`class ${JSON.stringify(key)}: "pattern" must be an object`);
  const p = v as Record<string, unknown>;
  if (p.kind !== 'hatch' && p.kind !== 'dots' && p.kind !== 'cross') bad(`class ${JSON.stringify(key)}: pattern "kind" must be hatch, dots or cross`);
  if (typeof p.color !== 'string' || !HEX.test(p.color)) bad(`class ${JSON.stringify(key)}: pattern "color" must be "#rrggbb"`);
  const out: NonNullable<ClassStyle['pattern']> = { kind: p.kind as 'hatch' | 'dots' | 'cross', color: (p.color as string).toLowerCase() };
  if (p.minScale !== undefined) {
    if (typeof p.minScale !== 'number') bad(`class ${JSON.stringify(key)}: pattern "minScale" must be a number`);
    out.minScale = p.minScale as number;
  }
  if (p.maxScale !== undefined) {
    if (typeof p.maxScale !== 'number') bad(`class ${JSON.stringify(key)}: pattern "maxScale" must be a number`);
    out.maxScale = p.maxScale as number;
  }
  return out;
}

/** A style for data without one: every distinct class value gets a colour of a fixed palette. */
export function defaultStyle(classValues: string[], classProperty: string | null): Style {
  const palette = ['#8dd3c7', '#ffffb3', '#bebada', '#fb8072', '#80b1d3', '#fdb462', '#b3de69', '#fccde5', '#d9d9d9', '#bc80bd', '#ccebc5', '#ffed6f'];
  const keys = [...classValues].sort();
  const classes: ClassStyle[] = keys.map((key, i) => ({ key, label: key, color: palette[i % palette.length]!, weight: 1, linear: false }));
  const compat = classes.map((_, i) => {
    const row = new Float64Array(classes.length).fill(0.5);
    row[i] = 1;
    return row;
  });
  return { name: 'default', classProperty, idProperty: null, baseScale: 0, resolutionMm: 0.28, allowHoles: false, background: '#ffffff', classes, compat, attribution: '' };
}

/** The style as JSON again (stored in the tGAP and the cube's metadata). */
export function styleToJson(style: Style): Record<string, unknown> {
  const classes: Record<string, unknown>[] = [];
  const compatibility: Record<string, Record<string, number>> = {};
  style.classes.forEach((c, i) => {
    classes.push({ key: c.key, label: c.label, color: c.color, weight: c.weight, linear: c.linear, ...(c.pattern ? { pattern: c.pattern } : {}) });
    const row: Record<string, number> = {};
    style.classes.forEach((d, j) => {
      if (i !== j) row[d.key] = style.compat[i]![j]!;
    });
    compatibility[c.key] = row;
  });
  return {
    name: style.name,
    classProperty: style.classProperty,
    idProperty: style.idProperty,
    baseScale: style.baseScale,
    resolutionMm: style.resolutionMm,
    allowHoles: style.allowHoles,
    background: style.background,
    attribution: style.attribution,
    defaultCompatibility: 0.5,
    classes,
    compatibility,
  };
}
