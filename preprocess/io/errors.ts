// Errors the user can act on: they name the file, the feature and the place that is wrong.

export interface FeatureRef {
  index: number;
  id: string | number | null;
}

export class InputError extends Error {
  readonly file: string | undefined;
  readonly feature: FeatureRef | undefined;
  readonly location: [number, number] | undefined;

  constructor(message: string, opts: { file?: string; feature?: FeatureRef; location?: [number, number] } = {}) {
    const parts: string[] = [];
    if (opts.file) parts.push(opts.file);
    if (opts.feature) parts.push(describeFeature(opts.feature));
    if (opts.location) parts.push(`at (${fmt(opts.location[0])}, ${fmt(opts.location[1])})`);
    super(parts.length ? `${parts.join(', ')}: ${message}` : message);
    this.name = 'InputError';
    this.file = opts.file;
    this.feature = opts.feature;
    this.location = opts.location;
  }
}

export function describeFeature(f: FeatureRef): string {
  return f.id === null || f.id === undefined ? `feature #${f.index}` : `feature #${f.index} (id ${JSON.stringify(f.id)})`;
}

function fmt(v: number): string {
  return Number.isFinite(v) ? String(Math.round(v * 1000) / 1000) : String(v);
}
