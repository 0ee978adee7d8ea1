// Nothing half-written: every output goes to a temporary sibling first and is renamed into place.
import { promises as fs } from 'node:fs';
import path from 'node:path';
import { fsReason, isFsError, OutputError } from './output-path.js';

function tempSibling(target: string): string {
  const dir = path.dirname(target);
  return path.join(dir, `.${path.basename(target)}.tmp-${process.pid}-${Date.now().toString(36)}`);
}

export async function writeFileAtomic(target: string, data: Uint8Array | string): Promise<void> {
  const tmp = tempSibling(target);
  try {
    await fs.writeFile(tmp, data);
    await fs.rename(tmp, target);
  } catch (err) {
    await fs.rm(tmp, { force: true });
    throw writeError(target, err);
  }
}

/**
 * Fill a fresh temporary directory with `fill`, then swap it in for `target`
 * (an existing target is replaced only after the new one is complete).
 */
export async function writeDirAtomic(target: string, fill: (dir: string) => Promise<void>): Promise<void> {
  const tmp = tempSibling(target);
  try {
    await fs.mkdir(tmp, { recursive: true });
  } catch (err) {
    throw writeError(target, err);
  }
  try {
    await fill(tmp);
    const old = `${tmp}.old`;
    let hadOld = false;
    try {
      await fs.rename(target, old);
      hadOld = true;
    } catch (err) {
      if ((err as NodeJS.ErrnoException).code !== 'ENOENT') throw err;
    }
    await fs.rename(tmp, target);
    if (hadOld) await fs.rm(old, { recursive: true, force: true });
  } catch (err) {
    await fs.rm(tmp, { recursive: true, force: true });
    throw writeError(target, err);
  }
}

/** A file-system failure named by the target the user gave (not the temporary sibling). */
function writeError(target: string, err: unknown): unknown {
  if (!isFsError(err)) return err;
  return new OutputError(`cannot write ${target}: ${err.code === 'ENOENT' ? `the folder ${path.dirname(path.resolve(target))} does not exist` : fsReason(err)}`);
}
