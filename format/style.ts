// The style (docs/FORMAT.md, "Style"): which property holds the class, and per class its
// colour, label, importance weight, pattern, whether it is linear and how its lines are drawn
// (line-style.ts). One schema for the file a cartographer writes (`ssc generalize --style`)
// and for the copy stored in the tGAP and in index.json (meta.style), which the map reads.
import * as v from 'valibot';
import { lineRuleCount, lineRules, LineStyleSchema, MAX_LINE_RULES, type LineRule, type LineStyleJson } from './line-style.js';
import { PIXEL_SIZE_MM } from './pixel-size.js';
import { bool, finite, hex, positive, str, unit } from './schema-values.js';

export const PATTERN_KINDS = ['hatch', 'dots', 'cross'] as const;

export const PatternSchema = v.object({
  kind: v.picklist(PATTERN_KINDS, 'must be hatch, dots or cross'),
  color: hex(),
  minScale: v.optional(finite()),
  maxScale: v.optional(finite()),
});

const classEntries = {
  label: v.optional(str()),
  color: hex(),
  /** Importance per unit area: the least important face (area x weight) goes first. */
  weight: v.optional(positive(), 1),
  /** Long thin faces (roads, watercourses): split among their neighbours instead of merged whole. */
  linear: v.optional(bool(), false),
  /** Drawn over the fill within a scale range (client side). */
  pattern: v.optional(PatternSchema),
  /** How its lines are drawn (line-style.ts); a linear class without it draws no lines. */
  line: v.optional(LineStyleSchema),
  /**
   * A linear class whose network this linear class's lines join (a bridge deck carrying a
   * road): they meet it where their areas touch, and are pruned as one network with it.
   */
  network: v.optional(str()),
};

/** Only a linear class has lines. */
const linesAreLinear = <T extends { linear: boolean; line?: unknown }>() => v.check<T, string>((c) => c.line === undefined || c.linear, 'line: only a linear class (linear: true) has lines');
const ClassSchema = v.pipe(v.object(classEntries), linesAreLinear());
/** In an array the key is given in the class: JSON objects put numeric keys first, arrays keep order. */
const KeyedClassSchema = v.pipe(v.object({ key: v.union([v.string(), v.number()], 'must be a string or a number'), ...classEntries }), linesAreLinear());

export const StyleSchema = v.pipe(v.object({
  name: v.optional(str(), 'unnamed'),
  classProperty: v.optional(v.nullable(str()), null),
  idProperty: v.optional(v.nullable(str()), null),
  /** Scale denominator of the input data (step 0); 0: chosen from the data. */
  baseScale: v.optional(v.pipe(finite(), v.check((n) => n === 0 || n >= 1, 'must be a number >= 1 (or 0: chosen from the data)')), 0),
  /** Simplification tolerance on the map, in mm: one standard pixel unless said otherwise. */
  resolutionMm: v.optional(v.pipe(finite(), v.minValue(0, 'must be a number >= 0')), PIXEL_SIZE_MM),
  /** Holes in the union of the faces are outside the domain (enclaves), not gaps. */
  allowHoles: v.optional(bool(), false),
  background: v.optional(hex(), '#ffffff'),
  attribution: v.optional(str(), ''),
  defaultCompatibility: v.optional(unit(), 0.5),
  // Chosen by the input's shape, so that an error names the field inside the class at fault.
  classes: v.lazy((input) =>
    Array.isArray(input)
      ? v.pipe(v.array(KeyedClassSchema), v.minLength(1, 'is empty'))
      : v.pipe(
        v.record(v.string(), ClassSchema, 'must be an object of class -> {color, weight, linear} or an array of {key, color, ...}'),
        v.check((r) => Object.keys(r).length > 0, 'is empty'),
      ),
  ),
  /** compatibility[loser][neighbour] in [0, 1]: how well the neighbour takes the loser's area. */
  compatibility: v.optional(v.record(v.string(), v.record(v.string(), unit())), {}),
}), v.forward(
  v.check((s) => lineRuleTotal(s.classes) <= MAX_LINE_RULES, (issue) => `has ${lineRuleTotal((issue.input as { classes: ClassesJson }).classes)} line rules (each class's line and each of its rules), more than the map draws (${MAX_LINE_RULES})`),
  ['classes'],
));

type ClassesJson = Record<string, { line?: LineStyleJson | undefined }> | { line?: LineStyleJson | undefined }[];

function lineRuleTotal(classes: ClassesJson): number {
  return Object.values(classes).reduce((n, c) => n + lineRuleCount(c.line), 0);
}

/**
 * A change to one class at run time (the map's setClassStyle): what the map draws and names,
 * not what the build uses (weight, linear). Strict: a misspelt key is an error, not ignored.
 * `pattern: null` takes the class's pattern away.
 */
export const ClassStyleSchema = v.strictObject(
  {
    label: v.optional(str()),
    color: v.optional(hex()),
    pattern: v.optional(v.nullable(PatternSchema)),
  },
  'must be an object of label, color and pattern',
);

export type StyleJson = v.InferInput<typeof StyleSchema>;
export type ClassStyleJson = v.InferInput<typeof ClassStyleSchema>;
export type ParsedStyleJson = v.InferOutput<typeof StyleSchema>;
export type PatternJson = v.InferOutput<typeof PatternSchema>;

/** One class with its key, in the style's order. */
export interface StyleClass {
  key: string;
  label: string;
  /** Lower-case "#rrggbb". */
  color: string;
  weight: number;
  linear: boolean;
  pattern?: PatternJson;
  /** How its lines are drawn, as the style gives it (resolved in `CubeStyle.lines`). */
  line?: LineStyleJson;
  /** The key of the linear class whose line network this class's lines join. */
  network?: string;
}

/** The style as the map draws it: background, the classes in order and the line rules. */
export interface CubeStyle {
  name: string;
  background: string;
  classes: StyleClass[];
  /** The line rules in index order (line-style.ts), which a line chunk's rule column refers to. */
  lines: LineRule[];
}

/** What the map draws of a parsed style: its name, background, classes (lower-case colours) and line rules. */
export function drawnStyle(style: ParsedStyleJson): CubeStyle {
  const classes = styleClasses(style);
  return { name: style.name, background: style.background.toLowerCase(), classes, lines: lineRules(classes) };
}

/** The classes of a parsed style in order, labels defaulting to the key and colours lower case. */
export function styleClasses(style: ParsedStyleJson): StyleClass[] {
  const entries: [string, v.InferOutput<typeof ClassSchema>][] = Array.isArray(style.classes)
    ? style.classes.map((c) => [String(c.key), c])
    : Object.entries(style.classes);
  return entries.map(([key, c]) => {
    const out: StyleClass = { key, label: c.label ?? key, color: c.color.toLowerCase(), weight: c.weight, linear: c.linear };
    if (c.pattern) out.pattern = { ...c.pattern, color: c.pattern.color.toLowerCase() };
    if (c.line) out.line = c.line;
    if (c.network !== undefined) out.network = c.network;
    return out;
  });
}
