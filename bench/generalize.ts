// npm run bench:generalize [-- <name filter>] [runs=N]: topology + tGAP for the four datasets,
// each run in a fresh process; medians of the runs.
import { spawnSync } from 'node:child_process';
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { benchArgs, datasets, median, root } from './datasets.js';

const { runs, filter } = benchArgs(3);
// Before any work: a missing dataset or a filter matching none is an error at once.
const sets = datasets(filter);
const dir = mkdtempSync(path.join(tmpdir(), 'ssc-bench-'));
console.log(`bench:generalize, ${runs} runs each (median), node ${process.version}`);
console.log('dataset             faces    steps    wall s   topology s  tGAP s   peak MB  faces/s');
for (const d of sets) {
  const rs: { ms: number; maxRssMB: number; faces: number; steps: number; timings: Record<string, number> }[] = [];
  for (let i = 0; i < runs; i++) {
    const r = spawnSync(process.execPath, [path.join(root, 'dist/bench/child-run.js'), 'generalize', d.file, d.style, path.join(dir, 'x.tgap')], { encoding: 'utf8' });
    if (r.status !== 0) throw new Error(`${d.name}: ${r.stderr}`);
    rs.push(JSON.parse(r.stdout.trim().split('\n').pop()!));
  }
  const wall = median(rs.map((r) => r.ms)) / 1000;
  const topo = median(rs.map((r) => (r.timings.read ?? 0) + (r.timings.topology ?? 0))) / 1000;
  const gen = median(rs.map((r) => r.timings.generalize ?? 0)) / 1000;
  const mem = median(rs.map((r) => r.maxRssMB));
  const faces = rs[0]!.faces;
  console.log(`${d.name.padEnd(19)} ${String(faces).padEnd(8)} ${String(rs[0]!.steps).padEnd(8)} ${wall.toFixed(2).padEnd(8)} ${topo.toFixed(2).padEnd(11)} ${gen.toFixed(2).padEnd(8)} ${mem.toFixed(0).padEnd(8)} ${Math.round(faces / wall)}`);
}
rmSync(dir, { recursive: true, force: true });
