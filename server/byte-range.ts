// The Range request header (RFC 9110 §14.2) for one file of known size. Only a single byte
// range is answered with 206; a header we do not understand, or several ranges, is ignored
// and the whole file is sent, as the RFC allows.

export type RangeRequest =
  | { kind: 'whole' }
  | { kind: 'unsatisfiable' }
  | { kind: 'range'; start: number; end: number }; // end inclusive

export function parseRange(header: string | undefined, size: number): RangeRequest {
  if (header === undefined) return { kind: 'whole' };
  const m = /^\s*bytes\s*=(.*)$/i.exec(header);
  if (!m) return { kind: 'whole' };
  const specs = m[1]!.split(',').map((s) => s.trim()).filter((s) => s !== '');
  if (specs.length !== 1) return { kind: 'whole' };
  const spec = specs[0]!;
  const suffix = /^-(\d+)$/.exec(spec);
  if (suffix) {
    const length = Number(suffix[1]);
    // A zero-length suffix, or any suffix of an empty file, selects nothing.
    if (length === 0 || size === 0) return { kind: 'unsatisfiable' };
    return { kind: 'range', start: Math.max(0, size - length), end: size - 1 };
  }
  const bounded = /^(\d+)-(\d*)$/.exec(spec);
  if (!bounded) return { kind: 'whole' };
  const start = Number(bounded[1]);
  const last = bounded[2] === '' ? Infinity : Number(bounded[2]);
  if (last < start) return { kind: 'whole' }; // invalid, so ignored (not unsatisfiable)
  if (start >= size) return { kind: 'unsatisfiable' };
  return { kind: 'range', start, end: Math.min(last, size - 1) };
}
