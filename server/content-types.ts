// Content-Type for a file name, by its last extension. The table is ours rather than a mime
// library's so that it matches docs/deploy.md's nginx types block exactly; text types carry
// their charset so browsers never guess.

const TYPES: Readonly<Record<string, string>> = {
  // the map's data
  json: 'application/json',
  bin: 'application/octet-stream',
  // the client
  html: 'text/html; charset=utf-8',
  js: 'text/javascript; charset=utf-8',
  mjs: 'text/javascript; charset=utf-8',
  css: 'text/css; charset=utf-8',
  wasm: 'application/wasm',
  map: 'application/json',
  webmanifest: 'application/manifest+json',
  txt: 'text/plain; charset=utf-8',
  svg: 'image/svg+xml',
  png: 'image/png',
  jpg: 'image/jpeg',
  jpeg: 'image/jpeg',
  webp: 'image/webp',
  avif: 'image/avif',
  ico: 'image/x-icon',
  woff2: 'font/woff2',
  // an archive asked for by its own name (a precompressed sibling is served as its original)
  gz: 'application/gzip',
};

export const DEFAULT_CONTENT_TYPE = 'application/octet-stream';

export function contentTypeFor(fileName: string): string {
  const dot = fileName.lastIndexOf('.');
  if (dot <= 0) return DEFAULT_CONTENT_TYPE;
  return TYPES[fileName.slice(dot + 1).toLowerCase()] ?? DEFAULT_CONTENT_TYPE;
}

/** Every extension with its type, for checking the nginx template against this table. */
export function contentTypeTable(): ReadonlyMap<string, string> {
  return new Map(Object.entries(TYPES));
}
