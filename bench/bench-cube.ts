// A cube built for a benchmark by the CLI from source (ssc build) in a folder of the caller's,
// with its whole index read back: index.json and every sub-index file, and all its chunks.
import { readdirSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { parseIndex, parseSubIndex, type ChunkLeaf, type CubeIndex, type InnerNode } from '../format/cube-index.js';
import { queryIndex } from '../format/index-query.js';
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

/** Builds `d` into `dir` (no .gz/.br copies: nothing here serves them). */
export function buildBenchCube(d: Dataset, dir: string, chunkBytes?: number): BenchCube {
  const label = chunkBytes ? `${d.name} ${chunkBytes / 1024} KiB` : d.name;
  process.stderr.write(`building ${label}... `);
  const t0 = performance.now();
  const args = ['build', d.file, '--style', d.style, '--out', dir, '--no-precompress', '--quiet'];
  const r = runSsc(chunkBytes ? [...args, '--chunk-bytes', String(chunkBytes)] : args);
  if (r.code !== 0) throw new Error(`ssc build ${d.name} failed (exit ${r.code}): ${r.stderr}`);
  process.stderr.write(`${((performance.now() - t0) / 1000).toFixed(1)} s\n`);
  const json = (file: string): unknown => JSON.parse(readFileSync(path.join(dir, file), 'utf8'));
  const index = parseIndex(json('index.json'));
  const subs = new Map<string, InnerNode>();
  for (const f of readdirSync(dir)) if (/^i-.*\.json$/.test(f)) subs.set(f, parseSubIndex(json(f), f));
  const all = queryIndex(index.root, { ground: [-Infinity, -Infinity, Infinity, Infinity], zMin: -Infinity, zMax: Infinity }, (ref) => subs.get(ref));
  if (all.missing.length > 0) throw new Error(`${label}: sub-index files missing from ${dir}: ${all.missing.join(', ')}`);
  return { label, dir, index, subs, leaves: all.leaves };
}
