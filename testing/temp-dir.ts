// A temporary folder removed when the test that made it ends.
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';

export function tempDir(t: { after: (fn: () => void) => void }): string {
  const dir = mkdtempSync(path.join(tmpdir(), 'ssc-test-'));
  t.after(() => rmSync(dir, { recursive: true, force: true }));
  return dir;
}
