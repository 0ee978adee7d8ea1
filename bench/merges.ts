// npm run bench:merges [-- <dataset filter>]: how the smooth cube's merges go (issue 11, "No
// spurious multi-parts"). For each of the four datasets, its tGAP (ssc generalize) and the
// smooth surfaces built from it (buildSurfaces, as ssc build --smooth does); per tilted merge,
// at 8 z inside its transition, whether the winner's gain comes apart from the winner
// (preprocess/ssc/merge-connectivity.ts), and the steepness variation of its surface, the
// coefficient of variation of |grad z| (preprocess/ssc/merge-steepness.ts). Target: 0 violations.
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { mergeConnectivity, violates } from '../preprocess/ssc/merge-connectivity.js';
import { slopeVariation } from '../preprocess/ssc/merge-steepness.js';
import { buildSurfaces } from '../preprocess/ssc/surfaces.js';
import { generalizedDataset } from '../testing/generalized-dataset.js';
import { datasets } from './datasets.js';
import { median, percentile } from './stats.js';
import { printTable } from './table.js';

const SAMPLES = 8;
const sets = datasets(process.argv[2]);
const t0 = performance.now();
const dir = mkdtempSync(path.join(tmpdir(), 'ssc-bench-'));
const rows: string[][] = [['dataset', 'merges', 'tilted', 'violating merges', 'violating slices', 'CV median', 'CV p90', 'CV max', 'worst merge', 's']];
const examples: string[] = [];
try {
  for (const d of sets) {
    process.stderr.write(`${d.name}... `);
    const t1 = performance.now();
    const { tgap } = await generalizedDataset(dir, path.basename(d.file), path.basename(d.style));
    const { surfaces, transitions, tgap: cube } = buildSurfaces(tgap, { smooth: true });
    const checks = mergeConnectivity(cube, surfaces, transitions, SAMPLES);
    const bad = checks.filter(violates);
    for (const c of bad.slice(0, 3)) examples.push(`${d.name}: face ${c.transition.loser} into ${c.transition.into} (step ${c.transition.step}), detached parts at the ${SAMPLES} z: ${c.detached.join(' ')}`);
    const cvs = checks.map((c) => ({ c, cv: slopeVariation(surfaces, c.triangles, surfaces.xs, surfaces.ys) })).filter((x) => Number.isFinite(x.cv));
    const values = cvs.map((x) => x.cv);
    const worst = cvs.reduce((a, b) => (b.cv > a.cv ? b : a), cvs[0]!);
    rows.push([
      d.name, String(transitions.length), String(checks.length), String(bad.length),
      String(checks.reduce((n, c) => n + c.detached.filter((x) => x > 0).length, 0)),
      median(values).toFixed(3), percentile(values, 0.9).toFixed(3), worst.cv.toFixed(3),
      `face ${worst.c.transition.loser} into ${worst.c.transition.into} (${worst.c.triangles.length} triangles)`,
      ((performance.now() - t1) / 1000).toFixed(1),
    ]);
    process.stderr.write('done\n');
  }
} finally {
  rmSync(dir, { recursive: true, force: true });
}
console.log(`bench:merges, smooth surfaces (buildSurfaces { smooth: true }), ${SAMPLES} z strictly inside each tilted merge's transition, node ${process.version}`);
console.log('violating: a part of the loser\'s area already taken by the winner touches no vertex of their shared boundary (exact, on the triangles); target 0');
console.log('CV: area-weighted coefficient of variation of |grad z| over a merge\'s triangles (0: one even slope)');
printTable(rows);
if (examples.length > 0) console.log(`\nfirst violations:\n${examples.join('\n')}`);
console.log(`\n${((performance.now() - t0) / 1000).toFixed(0)} s in all`);
