// Where the cube's index.json is, from the `source` option: the file itself (a path ending in
// .json), or the cube's directory, with or without its trailing slash (as a user writes it).

export function indexUrl(source: string, base: string): string {
  const url = new URL(source, base);
  if (!/\.json$/i.test(url.pathname)) url.pathname = `${url.pathname.replace(/\/?$/, '/')}index.json`;
  return url.href;
}

/**
 * The URL of a file of the cube (a chunk, a sub-index file, a page) that the index at `indexUrl`
 * names: beside it, its query left behind. The map and the worker both name files so: the
 * worker matches the bodies the map fetched for it by this URL (head-start.ts).
 */
export function cubeFileUrl(file: string, indexUrl: string): string {
  return new URL(file, indexUrl).href;
}
