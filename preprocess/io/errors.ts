// Errors the user can act on: they name the file, the feature and the place that is wrong.
import type { ProblemKind } from './problems.js';

export interface FeatureRef {
  index: number;
  id: string | number | null;
}

export class InputError extends Error {
  readonly file: string | undefined;
  readonly feature: FeatureRef | undefined;
  readonly location: [number, number] | undefined;
  /** The message without the file, the feature and the place. */
  readonly detail: string;
  /** The kind of problem, where the thrower knows it (grouping of the problems of an input). */
  readonly kind: ProblemKind | undefined;

  constructor(message: string, opts: { file?: string; feature?: FeatureRef; location?: [number, number]; kind?: ProblemKind } = {}) {
    const parts: string[] = [];
    if (opts.file) parts.push(opts.file);
    if (opts.feature) parts.push(describeFeature(opts.feature));
    if (opts.location) parts.push(formatLocation(opts.location));
    super(parts.length ? `${parts.join(', ')}: ${message}` : message);
    this.name = 'InputError';
    this.file = opts.file;
    this.feature = opts.feature;
    this.location = opts.location;
    this.detail = message;
    this.kind = opts.kind;
  }
}

export function describeFeature(f: FeatureRef): string {
  return f.id === null || f.id === undefined ? `feature #${f.index}` : `feature #${f.index} (id ${JSON.stringify(f.id)})`;
}

export function formatLocation([x, y]: [number, number]): string {
  return `at (${fmt(x)}, ${fmt(y)})`;
}

// Millimetres for metres; for degrees (longitude/latitude, |v| <= 360) about a centimetre.
function fmt(v: number): string {
  if (!Number.isFinite(v)) return String(v);
  const k = Math.abs(v) <= 360 ? 1e7 : 1e3;
  return String(Math.round(v * k) / k);
}
