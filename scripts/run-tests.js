#!/usr/bin/env node
// Runs the tests with node's test runner.
//   node scripts/run-tests.js unit   every *.test.ts outside e2e/, from source through tsx: no
//                                    build needed, seconds
//   node scripts/run-tests.js e2e    e2e/**/*.test.ts as compiled by `npm run build` (tsc): the
//                                    functions they hand to Chromium must be plain JavaScript,
//                                    and tsx (esbuild) would wrap them in helpers the page lacks
//   node scripts/run-tests.js        both
// Node 20 does not expand globs, so the files are listed here; SSC_TEST_FILTER=<substring>
// runs a subset.
import { existsSync, readdirSync, statSync } from 'node:fs';
import { join, relative, sep } from 'node:path';
import { spawnSync } from 'node:child_process';

const root = new URL('..', import.meta.url).pathname;
const filter = process.env.SSC_TEST_FILTER ?? '';
const which = process.argv[2] ?? 'all';
if (!['unit', 'e2e', 'all'].includes(which)) {
  console.error(`run-tests: unknown suite "${which}" (unit, e2e or nothing for both)`);
  process.exit(2);
}
const skipDirs = new Set(['node_modules', 'dist', '.git', 'chunks']);

function find(dir, out) {
  for (const name of readdirSync(dir).sort()) {
    if (skipDirs.has(name)) continue;
    const p = join(dir, name);
    if (statSync(p).isDirectory()) find(p, out);
    else if (name.endsWith('.test.ts')) out.push(relative(root, p));
  }
  return out;
}

const all = find(root, []).filter((f) => f.includes(filter));
const isE2e = (f) => f.startsWith(`e2e${sep}`);
const suites = [];
if (which !== 'e2e') suites.push({ name: 'unit', files: all.filter((f) => !isE2e(f)), concurrency: 2, loader: ['--import', 'tsx'] });
if (which !== 'unit') {
  const compiled = all.filter(isE2e).map((f) => join('dist', f.replace(/\.ts$/, '.js')));
  const missing = compiled.filter((f) => !existsSync(join(root, f)));
  if (missing.length > 0) {
    console.error(`run-tests: ${missing[0]} and ${missing.length - 1} more are missing: run \`npm run build\` first`);
    process.exit(1);
  }
  // One file at a time: browser tests are heavy and this machine has two cores.
  suites.push({ name: 'e2e', files: compiled, concurrency: 1, loader: [] });
}

let status = 0;
for (const s of suites) {
  if (s.files.length === 0) {
    console.error(`run-tests: no ${s.name} test files found${filter ? ` matching "${filter}"` : ''}`);
    process.exit(1);
  }
  const r = spawnSync(
    process.execPath,
    [...s.loader, '--test', `--test-concurrency=${s.concurrency}`, '--test-timeout=600000', ...s.files],
    { stdio: 'inherit', cwd: root },
  );
  if (r.status !== 0) status = r.status ?? 1;
}
process.exit(status);
