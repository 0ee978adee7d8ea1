// The four benchmark datasets and their styles. Found by testing/paths.ts's rule (data/ in the
// repository, else ../shared/data), so the benchmarks run from source (tsx) and from dist/ alike.
// A dataset a benchmark asks for that is missing is an error naming the file: a benchmark never
// reports on fewer datasets than it says.
import { dataset, repoRoot, styleFile } from '../testing/paths.js';

// The benchmarks have long imported median from here.
export { median } from './stats.js';

export const root = repoRoot;

export interface Dataset {
  name: string;
  file: string;
  style: string;
}

const ALL = [
  { name: 'bgt_otterlo_400m', file: 'bgt_otterlo_400m.geojson', style: 'bgt.json' },
  { name: 'bgt_otterlo_1800m', file: 'bgt_otterlo_1800m.geojson', style: 'bgt.json' },
  { name: 'nlcd_zion', file: 'nlcd_zion.geojson.gz', style: 'nlcd.json' },
  { name: 'as18_17', file: 'as18_17.geojson.gz', style: 'as18.json' },
] as const;

export type DatasetName = (typeof ALL)[number]['name'];

/**
 * The datasets among `names` (all four unless given) whose name contains `filter`. Throws when
 * the filter matches none of them, or when one of those chosen is missing.
 */
export function datasets(filter?: string, names: readonly DatasetName[] = ALL.map((d) => d.name)): Dataset[] {
  const chosen = ALL.filter((d) => names.includes(d.name) && (!filter || d.name.includes(filter)));
  if (chosen.length === 0) throw new Error(`no dataset matches "${filter}": this benchmark runs on ${names.join(', ')}`);
  return chosen.map((d) => ({ name: d.name, file: dataset(d.file), style: styleFile(d.style) }));
}

/** A benchmark's arguments: a dataset filter and runs=N (`defaultRuns` when not given). */
export function benchArgs(defaultRuns: number): { runs: number; filter: string | undefined } {
  const args = process.argv.slice(2);
  const runs = Number(args.find((a) => a.startsWith('runs='))?.slice(5) ?? defaultRuns);
  if (!Number.isInteger(runs) || runs < 1) throw new Error(`runs= takes a whole number >= 1`);
  return { runs, filter: args.find((a) => !a.startsWith('runs=')) };
}
