// Runs the ssc command line from source (tsx), so CLI tests need no build.
import { execFile, spawnSync } from 'node:child_process';
import path from 'node:path';
import { promisify } from 'node:util';
import { repoRoot } from './paths.js';

const cli = path.join(repoRoot, 'testing/ssc-from-source.ts');
const nodeArgs = ['--import', 'tsx', cli];

/** Node's arguments that run `ssc ...args` from source, for a test that spawns it itself. */
export function sscNodeArgs(args: string[]): string[] {
  return [...nodeArgs, ...args];
}

export interface SscResult {
  code: number;
  stdout: string;
  stderr: string;
}

export function runSsc(args: string[]): SscResult {
  const r = spawnSync(process.execPath, [...nodeArgs, ...args], { encoding: 'utf8', maxBuffer: 64 << 20 });
  return { code: r.status ?? -1, stdout: r.stdout, stderr: r.stderr };
}

const execFileP = promisify(execFile);

/** The same without blocking the event loop (a server or browser may be running beside it). */
export async function runSscAsync(args: string[]): Promise<{ stdout: string; stderr: string }> {
  return execFileP(process.execPath, [...nodeArgs, ...args], { maxBuffer: 64 << 20 });
}
