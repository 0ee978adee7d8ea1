// How the lines of a linear class are drawn (docs/FORMAT.md, "Style", "Lines"): the `line`
// object of a class, optionally varied by one attribute of the input features, and the rules it
// resolves to. The build gives every line the index of its rule (stored in the line chunk);
// the map and the CPU drawers look the rule up in `lineRules` by that index.
//
// One list of rules for the whole style, in class order and within a class the default first,
// then `rules` in the order given: the index a line stores and the order lines are drawn in
// (a later rule over an earlier one).
import * as v from 'valibot';
import { finite, hex, positive, str } from './schema-values.js';

const mm = () => v.pipe(finite(), v.minValue(0, 'must be a number of mm >= 0'));

const CasingSchema = v.strictObject(
  {
    /** Width of the casing on each side of the line, in mm on screen. */
    width: v.pipe(finite(), v.gtValue(0, 'must be a number of mm > 0')),
    color: hex(),
  },
  'a casing is an object of width and color',
);

/** What a rule may set; what it leaves out it takes from the line's defaults. */
const ruleFields = {
  /** Width in mm on screen; 0: no line. */
  width: v.optional(mm()),
  color: v.optional(hex()),
  /** null: none (takes away the default's casing). */
  casing: v.optional(v.nullable(CasingSchema)),
  minScale: v.optional(positive()),
  maxScale: v.optional(positive()),
  /** Importance per metre of line when lines are pruned (default: the class's weight). */
  weight: v.optional(positive()),
};

const value = () => v.union([v.string(), v.number()], 'must be a string or a number');

const LineRuleSchema = v.strictObject(
  { values: v.pipe(v.array(value(), 'must be a list of values'), v.minLength(1, 'is empty')), ...ruleFields },
  'a rule is an object of values, width, color, casing, minScale, maxScale and weight',
);

type Scales = { minScale?: number | undefined; maxScale?: number | undefined };
const scaleOrder = (r: Scales): boolean => r.minScale === undefined || r.maxScale === undefined || r.minScale <= r.maxScale;
const ORDER = 'minScale must not be above maxScale';

export const LineStyleSchema = v.pipe(
  v.strictObject(
    {
      ...ruleFields,
      width: mm(),
      /** The input attribute whose value picks a rule. */
      by: v.optional(str()),
      rules: v.optional(v.array(LineRuleSchema, 'must be a list of rules')),
    },
    'a line is an object of width, color, casing, minScale, maxScale, weight, by and rules',
  ),
  v.rawCheck(({ dataset, addIssue }) => {
    if (!dataset.typed) return;
    const l = dataset.value;
    if ((l.by === undefined) !== (l.rules === undefined)) addIssue({ message: 'by and rules go together: the attribute and the rules for its values' });
    if (!scaleOrder(l)) addIssue({ message: ORDER });
    const seen = new Map<string, number>();
    l.rules?.forEach((r, i) => {
      if (!scaleOrder({ minScale: r.minScale ?? l.minScale, maxScale: r.maxScale ?? l.maxScale })) addIssue({ message: `rules[${i}]: ${ORDER}` });
      for (const x of r.values) {
        const k = String(x), first = seen.get(k);
        if (first !== undefined) addIssue({ message: `rules[${i}]: value ${JSON.stringify(k)} is in rules[${first}] already` });
        else seen.set(k, i);
      }
    });
  }),
);

export type LineStyleJson = v.InferOutput<typeof LineStyleSchema>;

/** The most line rules a style may have: the map's line pass keeps a rule's number in 7 bits of a byte (line.frag). */
export const MAX_LINE_RULES = 127;

/** How many rules the `line` of a class resolves to (lineRules): its defaults, then each of `rules`. */
export function lineRuleCount(line: LineStyleJson | undefined): number {
  return line ? 1 + (line.rules?.length ?? 0) : 0;
}

/** A line rule resolved: everything the drawers need, inherited from the line's defaults. */
export interface LineRule {
  classIndex: number;
  /** The attribute and its values (as strings) this rule draws; null: the class's other lines. */
  by: string | null;
  values: string[] | null;
  /** mm on screen; 0: not drawn (such lines are not stored). */
  width: number;
  /** Lower-case "#rrggbb". */
  color: string;
  /** Drawn under every line's fill, `width` mm beyond each side of it. */
  casing: { width: number; color: string } | null;
  /** Drawn where minScale <= scale denominator <= maxScale (absent: no bound). */
  minScale?: number;
  maxScale?: number;
  /** Importance per metre when lines are pruned. */
  weight: number;
}

/** The line style of a class as `lineRules` reads it. */
export interface LinedClass {
  color: string;
  weight: number;
  line?: LineStyleJson | undefined;
}

/** Every line rule of the classes, in index order (see the header). Classes without `line` have none. */
export function lineRules(classes: readonly LinedClass[]): LineRule[] {
  const out: LineRule[] = [];
  classes.forEach((c, classIndex) => {
    // What this pushes for a class is what lineRuleCount counts: the defaults, then each of `rules`.
    const l = c.line;
    if (!l) return;
    const base = resolve(classIndex, null, null, l, { width: l.width, color: c.color, casing: null, weight: c.weight });
    out.push(base);
    for (const r of l.rules ?? []) out.push(resolve(classIndex, l.by!, r.values.map(String), r, base));
  });
  return out;
}

type Fields = { width?: number | undefined; color?: string | undefined; casing?: { width: number; color: string } | null | undefined } & Scales & { weight?: number | undefined };

function resolve(classIndex: number, by: string | null, values: string[] | null, f: Fields, d: Omit<LineRule, 'classIndex' | 'by' | 'values'>): LineRule {
  const casing = f.casing === undefined ? d.casing : f.casing;
  const rule: LineRule = {
    classIndex, by, values,
    width: f.width ?? d.width,
    color: (f.color ?? d.color).toLowerCase(),
    casing: casing ? { width: casing.width, color: casing.color.toLowerCase() } : null,
    weight: f.weight ?? d.weight,
  };
  const minScale = f.minScale ?? d.minScale, maxScale = f.maxScale ?? d.maxScale;
  if (minScale !== undefined) rule.minScale = minScale;
  if (maxScale !== undefined) rule.maxScale = maxScale;
  return rule;
}

/**
 * The rule of a line of class `classIndex` whose feature has `attributes`: the rule listing the
 * value of its `by` attribute (compared as a string), else the class's default; -1 for a class
 * without `line`.
 */
export function lineRuleFinder(rules: readonly LineRule[]): (classIndex: number, attributes: Record<string, unknown> | null | undefined) => number {
  const byClass = new Map<number, { base: number; by: string | null; byValue: Map<string, number> }>();
  rules.forEach((r, i) => {
    if (r.values === null) {
      byClass.set(r.classIndex, { base: i, by: null, byValue: new Map() });
      return;
    }
    const c = byClass.get(r.classIndex)!;
    c.by = r.by;
    for (const x of r.values) c.byValue.set(x, i);
  });
  return (classIndex, attributes) => {
    const c = byClass.get(classIndex);
    if (!c) return -1;
    const x = c.by !== null ? attributes?.[c.by] : undefined;
    return (x !== undefined && x !== null ? c.byValue.get(String(x)) : undefined) ?? c.base;
  };
}

/** Whether a rule is drawn at scale denominator `scale`. */
export const lineRuleDrawnAt = (r: Pick<LineRule, 'minScale' | 'maxScale'>, scale: number): boolean =>
  (r.minScale === undefined || scale >= r.minScale) && (r.maxScale === undefined || scale <= r.maxScale);
