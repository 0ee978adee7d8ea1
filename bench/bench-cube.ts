// A cube built for a benchmark by the CLI from source (ssc build) in a folder of the caller's,
// with its whole index read back: index.json and every sub-index file, and all its chunks.
import { readdirSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { parseIndex, parseSubIndex, type ChunkLeaf, type CubeIndex, type InnerNode } from '../format/cube-index.js';
import { EVERYWHERE, queryIndex } from '../format/index-query.js';
import { runSsc } from '../testing/run-ssc.js';
import type { Dataset } from './datasets.js';

export interface BenchCube {
  /** The dataset's name, and the chunk size when not the default. */
  label: string;
  dir: string;
  index: CubeIndex;
  /** Every sub-index file's node, by its name. */
  subs: Map<string, InnerNode>;
  leaves: ChunkLeaf[];
}

export interface BenchBuild {
  /** Target chunk size (the build's default when not given). */
  chunkBytes?: number;
  /** More `ssc build` options, and the words they add to the label. */
  args?: string[];
  variant?: string;
  /** Also write the .gz and .br copies (only a benchmark that weighs them needs them). */
  precompress?: boolean;
}

/** The build failed; `stderr` says why (a caller may accept some failures, e.g. an unknown option). */
export class BenchBuildError extends Error {
  constructor(readonly label: string, readonly code: number, readonly stderr: string) {
    super(`ssc build ${label} failed (exit ${code}): ${stderr}`);
  }
}

/** Builds `d` into `dir`. */
export function buildBenchCube(d: Dataset, dir: string, o: BenchBuild = {}): BenchCube {
  const label = [d.name, o.variant, o.chunkBytes ? `${o.chunkBytes / 1024} KiB` : undefined].filter((w) => w !== undefined).join(' ');
  process.stderr.write(`building ${label}... `);
  const t0 = performance.now();
  const args = ['build', d.file, '--style', d.style, '--out', dir, '--quiet', ...(o.args ?? [])];
  if (!o.precompress) args.push('--no-precompress');
  if (o.chunkBytes) args.push('--chunk-bytes', String(o.chunkBytes));
  const r = runSsc(args);
  if (r.code !== 0) {
    process.stderr.write(`failed (exit ${r.code})\n`);
    throw new BenchBuildError(label, r.code, r.stderr);
  }
  process.stderr.write(`${((performance.now() - t0) / 1000).toFixed(1)} s\n`);
  const json = (file: string): unknown => JSON.parse(readFileSync(path.join(dir, file), 'utf8'));
  const index = parseIndex(json('index.json'));
  const subs = new Map<string, InnerNode>();
  for (const f of readdirSync(dir)) if (/^i-.*\.json$/.test(f)) subs.set(f, parseSubIndex(json(f), f));
  const all = queryIndex(index.root, EVERYWHERE, (ref) => subs.get(ref));
  if (all.missing.length > 0) throw new Error(`${label}: sub-index files missing from ${dir}: ${all.missing.join(', ')}`);
  return { label, dir, index, subs, leaves: all.leaves };
}
