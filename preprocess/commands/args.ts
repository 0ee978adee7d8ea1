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
