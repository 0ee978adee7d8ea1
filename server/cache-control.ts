// Cache-Control by file name: content-hashed names never change, so caches may keep them
// for a year without asking; everything else (index.json above all) must be revalidated.
export const IMMUTABLE = 'public, max-age=31536000, immutable';
export const REVALIDATE = 'no-cache';

/** A run of at least 8 lowercase hex digits standing alone in the name: c-3fa9b2c1d4.bin. */
export const DEFAULT_IMMUTABLE_PATTERN = /(?:^|[^0-9A-Za-z])[0-9a-f]{8,}(?:[^0-9A-Za-z]|$)/;

// Whatever the pattern says, these name the current state of a map and must stay fresh.
const ALWAYS_REVALIDATED = new Set(['index.json', 'meta.json']);

export class CachePolicy {
  private readonly pattern: RegExp;

  constructor(pattern: RegExp = DEFAULT_IMMUTABLE_PATTERN) {
    // A global or sticky RegExp remembers lastIndex between test() calls; ours must not.
    this.pattern = pattern.global || pattern.sticky ? new RegExp(pattern.source, pattern.flags.replace(/[gy]/g, '')) : pattern;
  }

  /**
   * The header for a file asked for by this name: the last segment of the URL path, decoded
   * (as nginx's $uri is), and the name asked for rather than a precompressed sibling's.
   */
  headerFor(name: string): string {
    if (ALWAYS_REVALIDATED.has(name)) return REVALIDATE;
    return this.pattern.test(name) ? IMMUTABLE : REVALIDATE;
  }
}
