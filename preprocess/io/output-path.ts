// Output paths are checked before the work starts, and a failed write is one clear line:
// a missing folder or a path that is a directory is the user's to fix, not a stack trace.
import { constants, promises as fs } from 'node:fs';
import path from 'node:path';

/** An output that cannot be written where the user asked. */
export class OutputError extends Error {
  constructor(message: string) {
    super(message);
    this.name = 'OutputError';
  }
}

/** Why a file-system call failed, in words: ENOENT is "does not exist". */
export function fsReason(err: NodeJS.ErrnoException): string {
  switch (err.code) {
    case 'ENOENT': return 'no such file or directory';
    case 'EACCES':
    case 'EPERM': return 'permission denied';
    case 'EISDIR': return 'it is a directory';
    case 'ENOTDIR': return 'a part of the path is not a directory';
    case 'ENOSPC': return 'no space left on the device';
    case 'EROFS': return 'the file system is read-only';
    case 'EEXIST': return 'it exists already';
    default: return err.message;
  }
}

/** An error of a file-system call (it has a code such as ENOENT and the call's name). */
export function isFsError(err: unknown): err is NodeJS.ErrnoException & { code: string; syscall: string } {
  const e = err as NodeJS.ErrnoException;
  return err instanceof Error && typeof e.code === 'string' && typeof e.syscall === 'string';
}

/**
 * Refuses an output path whose folder does not exist or cannot be written, or that is a
 * directory where a file goes (or a file where a directory goes).
 */
export async function checkOutputPath(target: string, kind: 'file' | 'directory', option = '--out'): Promise<void> {
  const dir = path.dirname(path.resolve(target));
  let st;
  try {
    st = await fs.stat(dir);
  } catch (err) {
    throw new OutputError(`${option} ${target}: the folder ${dir} ${(err as NodeJS.ErrnoException).code === 'ENOENT' ? 'does not exist' : `cannot be used (${fsReason(err as NodeJS.ErrnoException)})`}`);
  }
  if (!st.isDirectory()) throw new OutputError(`${option} ${target}: ${dir} is not a folder`);
  try {
    await fs.access(dir, constants.W_OK);
  } catch {
    throw new OutputError(`${option} ${target}: the folder ${dir} is not writable`);
  }
  const existing = await fs.stat(target).catch(() => null);
  if (kind === 'file' && existing?.isDirectory()) throw new OutputError(`${option} ${target}: is a directory (a file is written here)`);
  if (kind === 'directory' && existing && !existing.isDirectory()) throw new OutputError(`${option} ${target}: is a file (a directory is written here)`);
}
