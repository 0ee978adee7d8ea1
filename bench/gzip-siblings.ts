// A .gz copy beside every file of a site, as `ssc build` writes them for the cube (gzip level
// 6): the static server then sends each file gzip-encoded, as a CDN would.
import { readdir, readFile, writeFile } from 'node:fs/promises';
import path from 'node:path';
import { gzipSync } from 'node:zlib';

/** Writes the siblings under `dir`; returns the gzip bytes of the files below each of `sum` (relative folders). */
export async function gzipSiblings(dir: string, sum: readonly string[] = []): Promise<Map<string, number>> {
  const totals = new Map(sum.map((s) => [s, 0]));
  for (const e of await readdir(dir, { recursive: true, withFileTypes: true })) {
    if (!e.isFile() || e.name.endsWith('.gz')) continue;
    const file = path.join(e.parentPath, e.name);
    const gz = gzipSync(await readFile(file), { level: 6 });
    await writeFile(`${file}.gz`, gz);
    const rel = path.relative(dir, file);
    for (const s of sum) if (rel.startsWith(`${s}${path.sep}`)) totals.set(s, totals.get(s)! + gz.length);
  }
  return totals;
}
