import type { PipelineOptions } from '../pipeline.js';

// Small parsers for command-line values; a bad value is a UsageError naming the option.
export class UsageError extends Error {
  constructor(message: string) {
    super(message);
    this.name = 'UsageError';
  }
}

export function parseSize(v: string | undefined, name = '--size'): { width: number; height: number } {
  const m = v ? /^(\d+)x(\d+)$/i.exec(v) : null;
  if (!m) throw new UsageError(`${name} must be WIDTHxHEIGHT in pixels, e.g. 1280x720`);
  const width = Number(m[1]), height = Number(m[2]);
  if (width < 1 || height < 1 || width > 16384 || height > 16384) throw new UsageError(`${name} must be between 1x1 and 16384x16384`);
  return { width, height };
}

export function parseBbox(v: string | undefined): [number, number, number, number] | undefined {
  if (v === undefined) return undefined;
  const parts = v.split(',').map(Number);
  if (parts.length !== 4 || parts.some((p) => !Number.isFinite(p)) || parts[0]! >= parts[2]! || parts[1]! >= parts[3]!) {
    throw new UsageError('--bbox must be x0,y0,x1,y1 with x0 < x1 and y0 < y1');
  }
  return parts as [number, number, number, number];
}

export function parseNumber(v: string | undefined, name: string, opts: { min?: number; integer?: boolean } = {}): number | undefined {
  if (v === undefined) return undefined;
  const n = Number(v);
  if (!Number.isFinite(n) || (opts.integer && !Number.isInteger(n)) || (opts.min !== undefined && n < opts.min)) {
    throw new UsageError(`${name} must be ${opts.integer ? 'an integer' : 'a number'}${opts.min !== undefined ? ` >= ${opts.min}` : ''} (got ${JSON.stringify(v)})`);
  }
  return n;
}

export function requireOne(values: Record<string, unknown>, names: string[]): string {
  const given = names.filter((n) => values[n] !== undefined);
  if (given.length !== 1) throw new UsageError(`give exactly one of ${names.map((n) => '--' + n).join(', ')}`);
  return given[0]!;
}

/** Options of every command that runs the generalization (ssc generalize, ssc build). */
export const generalizeOptionSpecs = {
  style: { type: 'string' },
  'class-property': { type: 'string' },
  crs: { type: 'string' },
  layer: { type: 'string' },
  precision: { type: 'string' },
  'base-scale': { type: 'string' },
  'allow-holes': { type: 'boolean' },
  group: { type: 'string' },
  quiet: { type: 'boolean' },
  problems: { type: 'string' },
  'max-problems': { type: 'string' },
  'drop-duplicates': { type: 'boolean' },
  'sliver-width': { type: 'string' },
  'refuse-slivers': { type: 'boolean' },
} as const;

export interface GeneralizeValues {
  style?: string | undefined;
  'class-property'?: string | undefined;
  crs?: string | undefined;
  layer?: string | undefined;
  precision?: string | undefined;
  'base-scale'?: string | undefined;
  'allow-holes'?: boolean | undefined;
  group?: string | undefined;
  quiet?: boolean | undefined;
  problems?: string | undefined;
  'max-problems'?: string | undefined;
  'drop-duplicates'?: boolean | undefined;
  'sliver-width'?: string | undefined;
  'refuse-slivers'?: boolean | undefined;
}

/** The pipeline's options from the generalize options, with progress on stderr unless --quiet. */
export function pipelineOptions(values: GeneralizeValues): PipelineOptions {
  const precision = parseNumber(values.precision, '--precision', { min: 0 });
  const baseScale = parseNumber(values['base-scale'], '--base-scale', { min: 1 });
  const group = parseNumber(values.group, '--group', { min: 1, integer: true });
  const maxProblems = parseNumber(values['max-problems'], '--max-problems', { min: 1, integer: true });
  const sliverWidth = parseNumber(values['sliver-width'], '--sliver-width', { min: 0 });
  return {
    ...(sliverWidth !== undefined ? { sliverWidth } : {}),
    ...(values['refuse-slivers'] ? { refuseSlivers: true } : {}),
    ...(maxProblems !== undefined ? { maxProblems } : {}),
    ...(values['drop-duplicates'] ? { dropDuplicates: true } : {}),
    ...(values.style ? { style: values.style } : {}),
    ...(values['class-property'] ? { classProperty: values['class-property'] } : {}),
    ...(values.crs ? { crs: values.crs } : {}),
    ...(values.layer ? { layer: values.layer } : {}),
    ...(precision !== undefined ? { precision } : {}),
    ...(baseScale !== undefined ? { baseScale } : {}),
    ...(values['allow-holes'] ? { allowHoles: true } : {}),
    ...(group !== undefined ? { group } : {}),
    ...(values.quiet ? {} : { log: (m: string) => process.stderr.write(m + '\n') }),
  };
}

/** Options of the commands that draw a view to an image (ssc map, ssc slice). */
// --no-lines: the faces alone (lines are drawn as the style's line rules say).
export const viewOptionSpecs = {
  step: { type: 'string' },
  scale: { type: 'string' },
  size: { type: 'string' },
  bbox: { type: 'string' },
  out: { type: 'string' },
  ids: { type: 'string' },
  'no-lines': { type: 'boolean' },
} as const;

export interface ViewValues {
  step?: string | undefined;
  scale?: string | undefined;
  size?: string | undefined;
  bbox?: string | undefined;
  out?: string | undefined;
  ids?: string | undefined;
  'no-lines'?: boolean | undefined;
}

/** The checked view options: image size, ground box, and the step or scale asked for. */
export function viewArgs(values: ViewValues, positionals: string[], what: string): {
  input: string; out: string; width: number; height: number; bbox: [number, number, number, number] | undefined;
  step: number | undefined; scale: number | undefined; lines: boolean;
} {
  if (positionals.length !== 1) throw new UsageError(`give one ${what}`);
  if (!values.out) throw new UsageError('--out <image.png> is required');
  requireOne(values as Record<string, unknown>, ['step', 'scale']);
  const { width, height } = parseSize(values.size);
  return {
    input: positionals[0]!, out: values.out, width, height, bbox: parseBbox(values.bbox),
    step: parseNumber(values.step, '--step', { min: 0 }), scale: parseNumber(values.scale, '--scale', { min: 1 }),
    lines: !values['no-lines'],
  };
}
