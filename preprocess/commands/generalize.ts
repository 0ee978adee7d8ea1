// ssc generalize <input> --out <file.tgap> [--style style.json] ...
import { parseArgs } from 'node:util';
import { writeFileAtomic } from '../io/atomic-write.js';
import { checkOutputPath } from '../io/output-path.js';
import { generalizeFile } from '../pipeline.js';
import { encodeTgap } from '../../format/tgap.js';
import { generalizeOptionSpecs, pipelineOptions, UsageError } from './args.js';
import { problemsUsage, withProblemsFile } from './problems-file.js';
import { repairsLine } from './repairs-line.js';

export const usage = `ssc generalize <input> --out <file.tgap> [options]
  input: GeoJSON (.geojson, .json), TopoJSON (.topojson), GeoPackage (.gpkg), Shapefile (.shp,
  with its .dbf, .prj and .cpg beside it) or FlatGeobuf (.fgb), each also gzipped (.gz); the
  format is read from the content, the CRS from the file (crs member, .prj, GeoPackage SRS,
  FlatGeobuf header)
  --style <style.json>      classes, colours, weights, compatibility, base scale
  --class-property <name>   property holding the class (overrides the style)
  --crs <EPSG:n>            CRS of the input when the file does not say (wins over the file's)
  --layer <name>            GeoPackage layer to read (needed when it has several); TopoJSON
                            object to read (default: all)
  --precision <units>       snapping grid and T-junction tolerance (default: a power of two,
                            at most 1/32 pixel of 0.28 mm at the base scale and at most 1,
                            7.8 mm at 1:1,000; a power of two lets the cube keep every input
                            point exactly, see docs/FORMAT.md)
  --base-scale <n>          scale denominator of the input (default: the style's, else derived)
  --sliver-width <units>    parts of a face thinner than this (2 x area / perimeter) are
                            slivers, dissolved into the neighbour with the longest shared
                            boundary and counted (default: 0.05 pixel of 0.28 mm at the base
                            scale, 1.4 cm at 1:1,000); those narrower than --precision are left
                            out before snapping, and their neighbours meet (0: no slivers, and
                            a ring the snapping collapses is refused)
  --refuse-slivers          refuse the input instead, naming every sliver
  --allow-holes             holes in the domain are enclaves, not gaps
  --group <n>               up to n independent merges or splits per step (default 1): fewer,
                            longer steps, as the seed paper suggests for smoother transitions
  --quiet                   no progress on stderr
${problemsUsage}
A refused input names all its problems (up to --max-problems), grouped by kind, and nothing
but the --problems file is written.`;

export async function run(argv: string[]): Promise<void> {
  const { values, positionals } = parseArgs({ args: argv, allowPositionals: true, options: { out: { type: 'string' }, ...generalizeOptionSpecs } });
  if (positionals.length !== 1) throw new UsageError('give one input file');
  if (!values.out) throw new UsageError('--out <file.tgap> is required');
  await checkOutputPath(values.out, 'file');
  const t0 = performance.now();
  const { tgap, report } = await withProblemsFile(values.problems, () => generalizeFile(positionals[0]!, pipelineOptions(values)));
  const bytes = encodeTgap(tgap);
  await writeFileAtomic(values.out, bytes);
  const r = report;
  process.stdout.write(
    [
      ...(r.noStyle ?? []),
      `input: ${tgap.meta.source} (${tgap.meta.crs}${tgap.meta.projectedFrom ? `, projected from ${tgap.meta.projectedFrom}` : ''})`,
      `topology: ${r.topology.faceCount} faces, ${r.topology.edges} edges, ${r.topology.nodeCount} nodes, ${r.topology.vertexCount} vertices`,
      repairsLine({ ...r.topology.repairs }),
      ...(r.topology.droppedDuplicates ? [`dropped duplicate polygons: ${r.topology.droppedDuplicates}`] : []),
      ...(r.topology.holes.length ? [`holes in the domain (enclaves): ${r.topology.holes.length}`] : []),
      `tGAP: ${r.generalize.steps} steps (${r.generalize.merges} merges${r.generalize.intoOutside ? `, ${r.generalize.intoOutside} of them faces without a neighbour leaving the map` : ''}, ${r.generalize.splits} splits, ${r.generalize.reemits} faces redrawn), ${r.generalize.facesLeft} face(s) left, ${r.generalize.removedVertices} vertices removed by simplification`,
      `scale: 1:${Math.round(tgap.meta.baseScale)} at step 0`,
      `wrote ${values.out} (${bytes.length} bytes) in ${((performance.now() - t0) / 1000).toFixed(1)} s`,
    ].join('\n') + '\n',
  );
}
