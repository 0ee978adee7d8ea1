// Runs the ssc command line from source (tsx), so CLI tests need no build.
import { execFile, spawn, spawnSync } from 'node:child_process';
import { createInterface } from 'node:readline';
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

export interface SscSession {
  run(args: string[]): Promise<SscResult>;
  close(): void;
}

/**
 * One ssc process that runs many commands in turn (testing/ssc-session-child.ts): the same
 * main() and output as a fresh `ssc` each time, without starting tsx each time.
 */
export function startSscSession(): SscSession {
  const child = spawn(process.execPath, ['--import', 'tsx', path.join(repoRoot, 'testing/ssc-session-child.ts')], { stdio: ['pipe', 'pipe', 'inherit'] });
  const waiting: { resolve: (r: SscResult) => void; reject: (e: Error) => void }[] = [];
  const lines = createInterface({ input: child.stdout });
  lines.on('line', (line) => waiting.shift()?.resolve(JSON.parse(line) as SscResult));
  child.on('exit', (code) => {
    for (const w of waiting.splice(0)) w.reject(new Error(`the ssc session ended (exit ${code}) before answering`));
  });
  return {
    run: (args) =>
      new Promise<SscResult>((resolve, reject) => {
        waiting.push({ resolve, reject });
        child.stdin.write(JSON.stringify(args) + '\n');
      }),
    close: () => child.stdin.end(),
  };
}
