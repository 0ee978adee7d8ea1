// One long-lived ssc process for tests that run the CLI many times: each request (a JSON
// array of arguments on one stdin line) runs the same main() as bin/ssc.js, and its exit
// code, stdout and stderr come back as one JSON line. Starting tsx once instead of per run
// is most of what a small CLI test costs.
import { createInterface } from 'node:readline';
import { main } from '../preprocess/cli.js';

const reply = process.stdout.write.bind(process.stdout);

async function runCaptured(args: string[]): Promise<{ code: number; stdout: string; stderr: string }> {
  let stdout = '';
  let stderr = '';
  const out = process.stdout.write;
  const err = process.stderr.write;
  const text = (s: string | Uint8Array): string => (typeof s === 'string' ? s : Buffer.from(s).toString('utf8'));
  process.stdout.write = (s: string | Uint8Array) => ((stdout += text(s)), true);
  process.stderr.write = (s: string | Uint8Array) => ((stderr += text(s)), true);
  try {
    return { code: await main(args), stdout, stderr };
  } catch (e) {
    // What node prints for an uncaught error, with its exit code.
    return { code: 1, stdout, stderr: stderr + (e instanceof Error ? (e.stack ?? e.message) : String(e)) + '\n' };
  } finally {
    process.stdout.write = out;
    process.stderr.write = err;
  }
}

for await (const line of createInterface({ input: process.stdin })) {
  const args = JSON.parse(line) as string[];
  reply(JSON.stringify(await runCaptured(args)) + '\n');
}
