// Which files of a cube an index refers to, and which cached files a new build leaves unused.
// The service worker prunes its cache with these when the index changes; they are pure so that
// Node tests can check them. Files are named in the index JSON as "file" (chunks, face and
// attribute pages) and "ref" (sub-index files), relative to the index's directory.

const NAMED = /"(?:file|ref)"\s*:\s*"([^"\\]+)"/g;

/** The file names an index or sub-index (its JSON text) refers to. */
export function referencedFiles(json: string): string[] {
  return [...json.matchAll(NAMED)].map((m) => m[1]!);
}

/** Sub-index files among names: the ones whose text refers to further files. */
export const isSubIndex = (name: string): boolean => /^i-[0-9a-f]{8,}\.json$/.test(name);

/**
 * The cached URLs that sit directly in the index's directory but are not among `referenced`
 * (names relative to that directory): left over from an older build of the same cube.
 * URLs elsewhere (another cube, another directory) are never touched.
 */
export function unusedCubeFiles(cachedUrls: readonly string[], indexUrl: string, referenced: ReadonlySet<string>): string[] {
  const dir = new URL('./', indexUrl).href;
  return cachedUrls.filter((u) => {
    const url = new URL(u);
    url.search = '';
    url.hash = '';
    const href = url.href;
    if (!href.startsWith(dir)) return false;
    const name = decodeURIComponent(href.slice(dir.length));
    return name.length > 0 && !name.includes('/') && !referenced.has(name);
  });
}
