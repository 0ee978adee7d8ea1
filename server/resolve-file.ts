// Maps URL path segments to a file or directory under the root, following symlinks only as
// far as they stay inside it: the real path is checked, not the name asked for.
import type { Stats } from 'node:fs';
import { realpath, stat } from 'node:fs/promises';
import path from 'node:path';

export type Resolved =
  | { kind: 'file'; realPath: string; stats: Stats }
  | { kind: 'directory'; realPath: string; stats: Stats }
  | { kind: 'missing' };

const MISSING: Resolved = { kind: 'missing' };

/** True when `p` is `root` or below it; both absolute and normalized. */
export function isInside(root: string, p: string): boolean {
  if (p === root) return true;
  const prefix = root.endsWith(path.sep) ? root : root + path.sep;
  return p.startsWith(prefix);
}

/** `root` must itself be a real path (see fs.realpath). */
export async function resolveInside(root: string, segments: readonly string[]): Promise<Resolved> {
  const candidate = path.join(root, ...segments);
  if (!isInside(root, candidate)) return MISSING;
  let real: string;
  let stats: Stats;
  try {
    real = await realpath(candidate);
    if (!isInside(root, real)) return MISSING; // a symlink pointing out of the root
    stats = await stat(real);
  } catch {
    return MISSING; // absent, unreadable, or a dangling or looping link: all the same to a client
  }
  if (stats.isFile()) return { kind: 'file', realPath: real, stats };
  if (stats.isDirectory()) return { kind: 'directory', realPath: real, stats };
  return MISSING; // sockets, FIFOs and devices are never served
}
