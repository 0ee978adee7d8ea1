// The path of a request target as a list of plain file-name segments, or the reason to refuse
// it. Segments are split on raw slashes before percent-decoding, and decoded exactly once, so
// neither %2f nor %252e%252e can become a separator or a `..` later on.

export type TargetPath =
  | { ok: true; segments: string[]; trailingSlash: boolean; query: string }
  | { ok: false; status: 400 | 404 };

// Separators and control characters (NUL above all) have no place in a file name we serve.
// eslint-disable-next-line no-control-regex -- matching control characters is the point
const FORBIDDEN_IN_SEGMENT = /[/\\\x00-\x1f\x7f]/;

export function parseTargetPath(requestTarget: string): TargetPath {
  // Absolute-form (http://host/path) must be accepted too (RFC 9112 §3.2.2); only its path
  // matters here, taken raw rather than through URL, which would resolve dot segments.
  const authority = /^https?:\/\/[^/?#]*/i.exec(requestTarget);
  const rest = authority ? requestTarget.slice(authority[0].length) : requestTarget;
  const target = authority && !rest.startsWith('/') ? '/' + rest : rest;
  if (!target.startsWith('/')) return { ok: false, status: 400 }; // "*" and other forms
  const queryAt = target.search(/[?#]/);
  const rawPath = queryAt < 0 ? target : target.slice(0, queryAt);
  const query = queryAt < 0 || target[queryAt] === '#' ? '' : target.slice(queryAt);
  if (rawPath.includes('\\')) return { ok: false, status: 400 };
  const segments: string[] = [];
  let hidden = false;
  for (const raw of rawPath.split('/')) {
    if (raw === '') continue; // leading, trailing and doubled slashes
    let segment: string;
    try {
      segment = decodeURIComponent(raw);
    } catch {
      return { ok: false, status: 400 }; // malformed escapes or invalid UTF-8
    }
    if (segment === '.' || segment === '..' || FORBIDDEN_IN_SEGMENT.test(segment)) return { ok: false, status: 400 };
    // Dotfiles (.git, .env) are never part of a map; keep them private even if present.
    if (segment.startsWith('.')) hidden = true;
    segments.push(segment);
  }
  if (hidden) return { ok: false, status: 404 };
  return { ok: true, segments, trailingSlash: rawPath.endsWith('/'), query };
}

/** The URL path for segments, each percent-encoded, so a redirect can only stay on this server. */
export function pathForSegments(segments: readonly string[], trailingSlash: boolean): string {
  const joined = '/' + segments.map(encodeURIComponent).join('/');
  return trailingSlash && segments.length > 0 ? joined + '/' : joined;
}
