// ssc build <input|tgap> --out <dir> [--style] [--chunk-bytes N]
import { promises as fs } from 'node:fs';
import { parseArgs } from 'node:util';
import { InputError } from '../io/errors.js';
import { checkOutputPath, fsReason, isFsError } from '../io/output-path.js';
import { generalizeFile } from '../pipeline.js';
import { buildCube, DEFAULT_CHUNK_BYTES, FLOOR_CHUNK_FACTOR, LINE_CHUNK_FACTOR } from '../ssc/build-cube.js';
import { readTgap, TGAP_MAGIC } from '../../format/tgap.js';
import type { Tgap } from '../../format/tgap-model.js';
import { generalizeOptionSpecs, parseNumber, pipelineOptions, UsageError } from './args.js';
import { withProblemsFile } from './problems-file.js';
import { repairsLine } from './repairs-line.js';

export const usage = `ssc build <input|file.tgap> --out <dir> [options]
  input: polygons in any format ssc generalize reads (GeoJSON, TopoJSON, GeoPackage, Shapefile,
  FlatGeobuf), or a tGAP that ssc generalize wrote
  --style <style.json>      for polygon input: classes, colours, weights (see ssc generalize)
  --chunk-bytes <n>         target chunk size (default ${DEFAULT_CHUNK_BYTES}; floor chunks ${FLOOR_CHUNK_FACTOR} times it, line chunks ${LINE_CHUNK_FACTOR} times it)
  --sub-index-bytes <n>     largest index file before subtrees move to sub-index files (default 131072;
                            with floor chunks the cube's tree below its root always does)
  --no-precompress          do not write the .gz and .br copies
  --classic                 today's classic cube: every change a horizontal surface (for comparison);
                            the default is the smooth cube, where merges and simplification are
                            gradual (tilted surfaces; --smooth says so explicitly)
  --quiet                   no progress on stderr
Other ssc generalize options (--class-property, --crs, --layer, --precision, --base-scale,
--sliver-width, --refuse-slivers, --allow-holes, --group, --problems, --max-problems,
--drop-duplicates) apply to polygon input. The directory is replaced only when the build succeeds.`;

async function isTgap(file: string): Promise<boolean> {
  try {
    const h = await fs.open(file, 'r');
    try {
      const b = Buffer.alloc(4);
      await h.read(b, 0, 4, 0);
      return b.readUInt32LE(0) === TGAP_MAGIC;
    } finally {
      await h.close();
    }
  } catch (err) {
    throw new InputError(`cannot read input: ${isFsError(err) ? fsReason(err) : (err as Error).message}`, { file });
  }
}

export async function run(argv: string[]): Promise<void> {
  const { values, positionals } = parseArgs({
    args: argv,
    allowPositionals: true,
    options: {
      out: { type: 'string' },
      'chunk-bytes': { type: 'string' },
      'sub-index-bytes': { type: 'string' },
      'no-precompress': { type: 'boolean' },
      smooth: { type: 'boolean' },
      classic: { type: 'boolean' },
      ...generalizeOptionSpecs,
    },
  });
  if (positionals.length !== 1) throw new UsageError('give one input file (polygons or a tGAP)');
  if (!values.out) throw new UsageError('--out <dir> is required');
  if (values.smooth && values.classic) throw new UsageError('--smooth and --classic exclude each other: the cube is one or the other');
  const chunkBytes = parseNumber(values['chunk-bytes'], '--chunk-bytes', { min: 1024, integer: true });
  const subIndexBytes = parseNumber(values['sub-index-bytes'], '--sub-index-bytes', { min: 1024, integer: true });
  const options = pipelineOptions(values);
  await checkOutputPath(values.out, 'directory');
  const t0 = performance.now();
  const input = positionals[0]!;
  let tgap: Tgap;
  // Built from polygons: what was chosen without a style, and the repairs made to the input.
  let report: string[] = [];
  if (await isTgap(input)) tgap = await readTgap(input);
  else {
    const g = await withProblemsFile(values.problems, () => generalizeFile(input, options));
    tgap = g.tgap;
    report = [...(g.report.noStyle ?? []), repairsLine({ ...g.report.topology.repairs })];
  }
  const r = await buildCube(tgap, values.out, {
    ...(chunkBytes !== undefined ? { chunkBytes } : {}),
    ...(subIndexBytes !== undefined ? { subIndexBytes } : {}),
    precompress: !values['no-precompress'],
    smooth: !values.classic,
    ...(options.log ? { log: options.log } : {}),
  });
  options.log?.(`build timings (ms): ${Object.entries(r.timings).map(([k, v]) => `${k} ${v}`).join(', ')}`);
  // Without a definition the map cannot convert longitude/latitude: say so now, not in a browser later.
  if (r.proj4 === null) process.stderr.write(`warning: no proj4 definition known for the CRS "${tgap.meta.crs}": the map of this cube takes and gives projected coordinates only (getCenterProjected, jumpTo({ centerProjected }), ...)\n`);
  const range = (bytes: number[]): string => {
    const sorted = [...bytes].sort((a, b) => a - b);
    return `${sorted[0] ?? 0}..${sorted[sorted.length - 1] ?? 0} bytes`;
  };
  const lines = r.lineChunkBytes.length > 0 ? `, ${r.lines} lines in ${r.lineChunkBytes.length} line chunks (${range(r.lineChunkBytes)})` : '';
  process.stdout.write(
    report.map((l) => l + '\n').join('') +
    `cube: ${tgap.meta.steps} steps, CRS ${tgap.meta.crs}${r.proj4 ? ' (with its proj4 definition)' : ''}, ${r.triangles} triangles in ${r.chunks} chunks (${range(r.chunkBytes)}), the floor again in ${r.floorChunks}${lines}, ${r.indexFiles} index file(s)\n` +
      `wrote ${values.out}: ${r.files} files, ${r.bytesWritten} bytes with the compressed copies, in ${((performance.now() - t0) / 1000).toFixed(1)} s\n`,
  );
}
