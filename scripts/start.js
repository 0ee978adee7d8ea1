#!/usr/bin/env node
// npm start: builds the bundled dataset (data/bgt_otterlo_1800m.geojson) into chunks/ and
// reports what it built.
import { spawnSync } from 'node:child_process';
import { mkdirSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import path from 'node:path';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const out = path.join(root, 'chunks');
mkdirSync(out, { recursive: true });
const ssc = (args) => {
  const r = spawnSync(process.execPath, [path.join(root, 'bin/ssc.js'), ...args], { stdio: 'inherit', cwd: root });
  if (r.status !== 0) process.exit(r.status ?? 1);
};
ssc(['generalize', 'data/bgt_otterlo_1800m.geojson', '--style', 'styles/bgt.json', '--out', path.join(out, 'bgt_otterlo_1800m.tgap')]);
ssc(['map', path.join(out, 'bgt_otterlo_1800m.tgap'), '--step', '0', '--size', '1280x1280', '--out', path.join(out, 'bgt_otterlo_1800m-step0.png')]);
ssc(['map', path.join(out, 'bgt_otterlo_1800m.tgap'), '--scale', '5000', '--size', '1280x1280', '--out', path.join(out, 'bgt_otterlo_1800m-1to5000.png')]);
console.log(`\nBuilt the tGAP of the bundled dataset in ${path.relative(process.cwd(), out) || '.'}/ with two maps drawn from it.`);
