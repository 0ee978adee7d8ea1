// Conditional requests (RFC 9110 §13): If-None-Match / If-Modified-Since decide a 304, and
// If-Range decides whether a Range still applies to the representation the client holds.

export interface Validators {
  etag: string; // strong, with its quotes
  lastModifiedMs: number; // whole seconds, as Last-Modified can say no more
}

const ENTITY_TAG = /(?:W\/)?"[^"]*"/g;

function opaque(tag: string): string {
  return tag.startsWith('W/') ? tag.slice(2) : tag;
}

/** True when the client's cached copy is current and a 304 is the answer (GET and HEAD). */
export function isNotModified(ifNoneMatch: string | undefined, ifModifiedSince: string | undefined, v: Validators): boolean {
  if (ifNoneMatch !== undefined) {
    if (ifNoneMatch.trim() === '*') return true;
    // Weak comparison: a W/ tag for the same bytes still means the copy is current.
    return (ifNoneMatch.match(ENTITY_TAG) ?? []).some((t) => opaque(t) === v.etag);
  }
  // If-Modified-Since counts only without If-None-Match, which is the more precise validator.
  if (ifModifiedSince !== undefined) {
    const since = Date.parse(ifModifiedSince);
    return Number.isFinite(since) && v.lastModifiedMs <= since;
  }
  return false;
}

/** True when a Range may be answered: no If-Range, or it names exactly this representation. */
export function rangeApplies(ifRange: string | undefined, v: Validators): boolean {
  if (ifRange === undefined) return true;
  const value = ifRange.trim();
  // Strong comparison only: bytes of a weakly equal copy cannot be spliced together.
  if (value.startsWith('"') || value.startsWith('W/')) return value === v.etag;
  const date = Date.parse(value);
  return Number.isFinite(date) && date === v.lastModifiedMs;
}
