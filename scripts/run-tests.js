#!/usr/bin/env node
// Runs every compiled test file with node's test runner. Node 20 does not expand globs, so
// the files are listed here; SSC_TEST_FILTER=<substring> runs a subset.
import { readdirSync, statSync } from 'node:fs';
import { join, relative } from 'node:path';
import { spawnSync } from 'node:child_process';

const root = new URL('..', import.meta.url).pathname;
const filter = process.env.SSC_TEST_FILTER ?? '';

function find(dir, out) {
  let entries;
  try {
    entries = readdirSync(dir);
  } catch {
    return out;
  }
  for (const name of entries.sort()) {
    const p = join(dir, name);
    if (statSync(p).isDirectory()) find(p, out);
    else if (name.endsWith('.test.js')) out.push(relative(root, p));
  }
  return out;
}

const files = find(join(root, 'dist'), []).filter((f) => f.includes(filter));
if (files.length === 0) {
  console.error('no test files found under dist/ (did the build run?)');
  process.exit(1);
}
// One file at a time: browser tests are heavy and this machine has two cores.
const r = spawnSync(process.execPath, ['--test', '--test-concurrency=1', '--test-timeout=600000', ...files], { stdio: 'inherit', cwd: root });
process.exit(r.status ?? 1);
