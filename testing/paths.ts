// Where the repository, its styles and the test datasets are, for tests and benchmarks alike.
// Found by walking up to package.json, so the same code works from source (tsx) and from dist/.
import { existsSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

function findRoot(start: string): string {
  let dir = start;
  for (;;) {
    if (existsSync(path.join(dir, 'package.json')) && existsSync(path.join(dir, 'preprocess'))) return dir;
    const up = path.dirname(dir);
    if (up === dir) throw new Error(`no repository root above ${start}`);
    dir = up;
  }
}

export const repoRoot = findRoot(path.dirname(fileURLToPath(import.meta.url)));

/** The workplace's copy of the shared datasets (../shared/data beside the repository). */
export const sharedDataDir = path.resolve(repoRoot, '../shared/data');

/**
 * A dataset from data/ in the repository, else from ../shared/data. A missing dataset is an
 * error that names both places: a test or benchmark never passes by skipping it.
 */
export function dataset(name: string): string {
  const own = path.join(repoRoot, 'data', name);
  if (existsSync(own)) return own;
  const shared = path.join(sharedDataDir, name);
  if (existsSync(shared)) return shared;
  throw new Error(`dataset ${name} is missing: looked in ${path.join(repoRoot, 'data')} and ${sharedDataDir}`);
}

export function styleFile(name: string): string {
  const file = path.join(repoRoot, 'styles', name);
  if (!existsSync(file)) throw new Error(`style ${name} is missing: looked for ${file}`);
  return file;
}
