// A dataset's style as the generalization uses it: the file is read with the schema of
// format/style.ts, then classes are numbered and compatibilities become a matrix.
import { promises as fs } from 'node:fs';
import * as v from 'valibot';
import { describeIssues } from '../format/schema-issues.js';
import { lineRules, type LineRule } from '../format/line-style.js';
import { styleClasses, StyleSchema, type StyleClass } from '../format/style.js';
import { PIXEL_SIZE_MM } from '../format/pixel-size.js';
import { InputError } from './io/errors.js';
import { chooseClassColours, ONE_CLASS_COLOR } from './style-scaffold/class-colours.js';
import { sortClassKeys } from './style-scaffold/class-stats.js';

/** A class as the generalization uses it (format/style.ts has the file's form). */
export type ClassStyle = StyleClass;

export interface Style {
  name: string;
  classProperty: string | null;
  idProperty: string | null;
  /** Scale denominator of the input data (step 0); 0 until chosen from the data. */
  baseScale: number;
  /** Simplification tolerance on the map, in mm. */
  resolutionMm: number;
  /** Holes in the union of the faces are outside the domain (enclaves), not gaps. */
  allowHoles: boolean;
  background: string;
  classes: ClassStyle[];
  /** The line rules of the linear classes in index order (format/line-style.ts). */
  lineRules: LineRule[];
  /** compat[loser][neighbour] in [0, 1], indexed like `classes`. */
  compat: Float64Array[];
  attribution: string;
}

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

/** The style of a style file; every problem of the file is named in one error. */
export function parseStyle(json: unknown, file = 'style'): Style {
  const bad = (problems: string[]): never => {
    throw new InputError(`style: ${problems.length === 1 ? problems[0] : `${problems.length} problems:\n  ${problems.join('\n  ')}`}`, { file });
  };
  const r = v.safeParse(StyleSchema, json);
  if (!r.success) return bad(describeIssues(r.issues));
  const s = r.output;
  const classes = styleClasses(s);
  const problems: string[] = [];
  const seen = new Set<string>();
  for (const c of classes) {
    if (seen.has(c.key)) problems.push(`classes: ${JSON.stringify(c.key)} is defined twice`);
    seen.add(c.key);
  }
  if (classes.length > 65535) problems.push('classes: more than 65535 classes');
  const index = new Map(classes.map((c, i) => [c.key, i]));
  const compat = classes.map((_, i) => {
    const row = new Float64Array(classes.length).fill(s.defaultCompatibility);
    row[i] = 1;
    return row;
  });
  for (const c of classes) {
    if (c.network === undefined) continue;
    const to = index.get(c.network);
    if (!c.linear) problems.push(`classes.${c.key}.network: only a linear class (linear: true) joins a line network`);
    if (to === undefined) problems.push(`classes.${c.key}.network: names unknown class ${JSON.stringify(c.network)}`);
    else if (!classes[to]!.linear) problems.push(`classes.${c.key}.network: names class ${JSON.stringify(c.network)}, which is not linear`);
  }
  for (const [a, row] of Object.entries(s.compatibility)) {
    const ia = index.get(a);
    if (ia === undefined) problems.push(`compatibility: names unknown class ${JSON.stringify(a)}`);
    for (const [b, value] of Object.entries(row)) {
      const ib = index.get(b);
      if (ib === undefined) problems.push(`compatibility.${a}: names unknown class ${JSON.stringify(b)}`);
      else if (ia !== undefined) compat[ia]![ib] = value;
    }
  }
  if (problems.length > 0) bad(problems);
  return {
    name: s.name,
    classProperty: s.classProperty,
    idProperty: s.idProperty,
    baseScale: s.baseScale,
    resolutionMm: s.resolutionMm,
    allowHoles: s.allowHoles,
    background: s.background.toLowerCase(),
    classes,
    lineRules: lineRules(classes),
    compat,
    attribution: s.attribution,
  };
}

/**
 * A style for data without one: the classes coloured as `ssc style` colours them (a known
 * nomenclature, the class name, else a fixed palette); one class when there is no class property.
 */
export function defaultStyle(classValues: string[], classProperty: string | null): Style {
  const chosen = classProperty === null
    ? classValues.map((key) => ({ key, label: key, color: ONE_CLASS_COLOR, weight: 1 }))
    : chooseClassColours(sortClassKeys(new Set(classValues)));
  const classes: ClassStyle[] = chosen.map((c) => ({ key: c.key, label: c.label, color: c.color, weight: c.weight, linear: false }));
  const compat = classes.map((_, i) => {
    const row = new Float64Array(classes.length).fill(0.5);
    row[i] = 1;
    return row;
  });
  return { name: 'default', classProperty, idProperty: null, baseScale: 0, resolutionMm: PIXEL_SIZE_MM, allowHoles: false, background: '#ffffff', classes, lineRules: [], compat, attribution: '' };
}

/** The style as JSON again (stored in the tGAP and the cube's metadata). */
export function styleToJson(style: Style): Record<string, unknown> {
  const classes: Record<string, unknown>[] = [];
  const compatibility: Record<string, Record<string, number>> = {};
  style.classes.forEach((c, i) => {
    classes.push({ key: c.key, label: c.label, color: c.color, weight: c.weight, linear: c.linear, ...(c.pattern ? { pattern: c.pattern } : {}), ...(c.line ? { line: c.line } : {}), ...(c.network !== undefined ? { network: c.network } : {}) });
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
