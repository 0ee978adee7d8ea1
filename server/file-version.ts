// When two stats describe the same file, and the same version of it. Writing, renaming,
// linking or unlinking a file all move its ctime, so equal times mean no such change since.
import type { Stats } from 'node:fs';

/** The same file: the same inode on the same device, whatever its contents now. */
export function sameFile(a: Stats, b: Stats): boolean {
  return a.ino === b.ino && a.dev === b.dev;
}

/** The same file, unchanged: as far as stat can tell, the same bytes. */
export function sameVersion(a: Stats, b: Stats): boolean {
  return sameFile(a, b) && a.size === b.size && a.mtimeMs === b.mtimeMs && a.ctimeMs === b.ctimeMs;
}

/** A string naming one version, for use as a map key. */
export function versionKey(s: Stats): string {
  return `${s.dev}:${s.ino}:${s.size}:${s.mtimeMs}:${s.ctimeMs}`;
}
