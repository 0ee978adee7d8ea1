// Where the cube's index.json is, from the `source` option: the file itself (a path ending in
// .json), or the cube's directory, with or without its trailing slash (as a user writes it).

export function indexUrl(source: string, base: string): string {
  const url = new URL(source, base);
  if (!/\.json$/i.test(url.pathname)) url.pathname = `${url.pathname.replace(/\/?$/, '/')}index.json`;
  return url.href;
}
