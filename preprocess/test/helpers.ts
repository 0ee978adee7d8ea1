// Shared by the preprocessing tests: running the CLI, temporary folders, the shared data.
import { spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

export const repoRoot = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../../..');

/** A dataset from data/ in the repo, else from ../shared/data (the workplace copy). */
export function dataset(name: string): string {
  const own = path.join(repoRoot, 'data', name);
  if (existsSync(own)) return own;
  return path.resolve(repoRoot, '../shared/data', name);
}

export function styleFile(name: string): string {
  return path.join(repoRoot, 'styles', name);
}

export function runSsc(args: string[]): { code: number; stdout: string; stderr: string } {
  const r = spawnSync(process.execPath, [path.join(repoRoot, 'bin/ssc.js'), ...args], { encoding: 'utf8', maxBuffer: 64 << 20 });
  return { code: r.status ?? -1, stdout: r.stdout, stderr: r.stderr };
}

export function tempDir(t: { after: (fn: () => void) => void }): string {
  const dir = mkdtempSync(path.join(tmpdir(), 'ssc-test-'));
  t.after(() => rmSync(dir, { recursive: true, force: true }));
  return dir;
}

/** A raw face-id file (ssc map/slice --ids): little-endian uint32 per pixel. */
export function readIds(file: string): Uint32Array {
  const b = readFileSync(file);
  return new Uint32Array(b.buffer.slice(b.byteOffset, b.byteOffset + b.byteLength));
}
