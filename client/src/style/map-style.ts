// The style a map draws, changed at run time (setStyle, setClassStyle): checked with the same
// schema as the cube's style (format/style.ts), and against the cube's classes, whose order the
// faces' class numbers refer to. Nothing is changed when a check fails. Pure.
import * as v from 'valibot';
import { lineRules } from '../../../format/line-style.js';
import { describeIssues } from '../../../format/schema-issues.js';
import { ClassStyleSchema, drawnStyle, StyleSchema, type ClassStyleJson, type CubeStyle, type StyleClass, type StyleJson } from '../../../format/style.js';

export type { ClassStyleJson, CubeStyle, StyleJson };

export class StyleError extends Error {
  constructor(message: string) {
    super(message);
    this.name = 'StyleError';
  }
}

function problems(what: string, issues: readonly v.BaseIssue<unknown>[]): StyleError {
  const list = describeIssues(issues);
  return new StyleError(`${what}: ${list.length === 1 ? list[0]! : `${list.length} problems: ${list.join('; ')}`}`);
}

const quoted = (keys: string[]): string => keys.map((k) => JSON.stringify(k)).join(', ');

/**
 * A whole style for a cube whose classes are `cubeClasses`: every class of the cube needs an
 * entry and there may be none other. The result keeps the cube's class order, whatever the
 * style's order.
 */
export function parseMapStyle(json: unknown, cubeClasses: readonly Pick<StyleClass, 'key'>[]): CubeStyle {
  const r = v.safeParse(StyleSchema, json);
  if (!r.success) throw problems('setStyle', r.issues);
  const style = drawnStyle(r.output);
  const byKey = new Map(style.classes.map((c) => [c.key, c]));
  const missing = cubeClasses.filter((c) => !byKey.has(c.key)).map((c) => c.key);
  const cubeKeys = new Set(cubeClasses.map((c) => c.key));
  const unknown = style.classes.filter((c) => !cubeKeys.has(c.key)).map((c) => c.key);
  const faults: string[] = [];
  if (missing.length) faults.push(`classes: the cube's ${quoted(missing)} ${missing.length === 1 ? 'is' : 'are'} missing`);
  if (unknown.length) faults.push(`classes: the cube has no ${quoted(unknown)} (its classes: ${quoted([...cubeKeys])})`);
  if (faults.length) throw new StyleError(`setStyle: ${faults.join('; ')}`);
  // The line rules follow the classes into the cube's order, which the line chunks' rule numbers refer to.
  const classes = cubeClasses.map((c) => byKey.get(c.key)!);
  return { ...style, classes, lines: lineRules(classes) };
}

/** `style` with class `key` changed as `change` says (a new object; `style` is left alone). */
export function withClassStyle(style: CubeStyle, key: string, change: unknown): CubeStyle {
  const i = style.classes.findIndex((c) => c.key === key);
  if (i < 0) throw new StyleError(`setClassStyle: no class ${JSON.stringify(key)} (the classes: ${quoted(style.classes.map((c) => c.key))})`);
  const r = v.safeParse(ClassStyleSchema, change);
  if (!r.success) throw problems(`setClassStyle(${JSON.stringify(key)})`, r.issues);
  const c: StyleClass = { ...style.classes[i]! };
  const { label, color, pattern } = r.output;
  if (label !== undefined) c.label = label;
  if (color !== undefined) c.color = color.toLowerCase();
  if (pattern === null) delete c.pattern;
  else if (pattern !== undefined) c.pattern = { ...pattern, color: pattern.color.toLowerCase() };
  const classes = style.classes.slice();
  classes[i] = c;
  return { ...style, classes };
}

/** A deep copy, for getStyle(): the caller may change it without changing the map. */
export function copyStyle(style: CubeStyle): CubeStyle {
  return structuredClone(style);
}
