// Cross-origin reads: which origins may fetch the files, and the answer to a preflight.

export type CorsOrigins = '*' | readonly string[];

export const ALLOWED_METHODS = 'GET, HEAD';
// Headers a map client may set itself; the rest of a fetch's headers are safelisted anyway.
export const ALLOWED_REQUEST_HEADERS = 'Range, If-Range, If-None-Match, If-Modified-Since';
// Readable by the page only when exposed: the client checks ETags and ranges, and waits as long as
// a retried answer (5xx, 408, 429) asks (Retry-After), as from a CDN that limits its rate.
export const EXPOSED_HEADERS = 'ETag, Content-Length, Content-Range, Accept-Ranges, Retry-After';
export const PREFLIGHT_MAX_AGE_S = '86400';

export class CorsConfigError extends Error {
  constructor(message: string) {
    super(message);
    this.name = 'CorsConfigError';
  }
}

/** Parses `*` or a comma-separated list of origins (as given to `ssc serve --cors`). */
export function parseCorsOrigins(value: string): CorsOrigins {
  if (value.trim() === '*') return '*';
  return value.split(',').map((s) => s.trim()).filter((s) => s !== '');
}

function normalizeOrigin(origin: string): string {
  let url: URL;
  try {
    url = new URL(origin);
  } catch {
    throw new CorsConfigError(`not an origin: ${JSON.stringify(origin)} (want scheme://host[:port])`);
  }
  // An origin has no path, query or credentials; anything else is a likely typo worth refusing.
  if (url.origin === 'null' || url.pathname !== '/' || url.search !== '' || url.hash !== '' || url.username !== '' || url.password !== '') {
    throw new CorsConfigError(`not an origin: ${JSON.stringify(origin)} (want scheme://host[:port], nothing after it)`);
  }
  return url.origin;
}

export class CorsPolicy {
  private readonly any: boolean;
  private readonly origins: ReadonlySet<string>;

  constructor(origins: CorsOrigins | undefined) {
    this.any = origins === '*';
    this.origins = new Set(origins === undefined || origins === '*' ? [] : origins.map(normalizeOrigin));
  }

  get enabled(): boolean {
    return this.any || this.origins.size > 0;
  }

  /** With a list, the answer depends on Origin, so shared caches must key on it. */
  get variesByOrigin(): boolean {
    return !this.any && this.origins.size > 0;
  }

  /** The Access-Control-Allow-Origin value for a request, or undefined for none. */
  allowOrigin(origin: string | undefined): string | undefined {
    if (this.any) return '*';
    // Scheme and host are case-insensitive; browsers send them lowercase, curl users may not.
    return origin !== undefined && this.origins.has(origin.toLowerCase()) ? origin : undefined;
  }
}
