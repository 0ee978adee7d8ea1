// ssc style <input> [--class-property P] --out style.json: a first style scaffolded from the data.
import { parseArgs } from 'node:util';
import { writeFileAtomic } from '../io/atomic-write.js';
import { resolveCrs } from '../io/crs.js';
import { readInput } from '../io/read-input.js';
import { formatStyleJson, LINEAR_MAX_WIDTH_PX, LINEAR_MIN_ELONGATION, scaffoldStyle, type Scaffold } from '../style-scaffold/scaffold-style.js';
import { MEAN_FACE_PX } from '../style-scaffold/base-scale.js';
import { UsageError } from './args.js';

export const usage = `ssc style <input.geojson|.geojson.gz|.topojson> --out <style.json> [options]
  --class-property <name>   property holding the class (default: guessed, and the guess printed)
  --crs <EPSG:n>            CRS of the input when the file does not say
  --layer <name>            TopoJSON object to read (default: all)
Writes a style to start from (docs/STYLE.md): every class with a colour (from CORINE, NLCD or
BGT/TOP10NL where the values match, else from the class name, else a fixed palette), linear
classes suggested from the faces' shape, and a base scale from their size. Prints the classes
with their face counts and areas.`;

function formatArea(m2: number): string {
  return m2 >= 1e6 ? `${(m2 / 1e6).toFixed(2)} km2` : `${(m2 / 1e4).toFixed(2)} ha`;
}

/** The table and the choices made, as printed. */
export function describeScaffold(s: Scaffold, file: string): string {
  const out: string[] = [];
  const cp = s.classProperty;
  if (cp.name === null) out.push(`class property: none (no property is set on every feature with 2 to 256 values): one class`);
  else if (cp.given) out.push(`class property: ${cp.name} (given)`);
  else {
    const others = cp.guess!.candidates.slice(1, 4).map((c) => `${c.name} (${c.distinct})`).join(', ');
    out.push(`class property: ${cp.name} (guessed: ${cp.guess!.candidates[0]!.distinct} values${others ? `; other candidates: ${others}` : ''}; --class-property to choose)`);
  }
  out.push(`id property: ${s.style.idProperty ?? 'none'}`);
  out.push(`base scale: 1:${s.style.baseScale} (the mean face, ${s.meanFaceSide.toFixed(1)} m across, is about ${MEAN_FACE_PX} pixels of ${s.style.resolutionMm} mm there)`);
  out.push(`linear: faces at least ${LINEAR_MIN_ELONGATION}x as elongated as a square and under ${LINEAR_MAX_WIDTH_PX} pixels wide at the base scale`);
  const total = s.rows.reduce((a, r) => a + r.area, 0);
  const header = ['class', 'faces', 'area', 'share', 'width', 'elong.', 'linear', 'colour', 'from'];
  const body = s.rows.map((r) => [
    r.key === r.label ? r.key : `${r.key} (${r.label})`,
    String(r.faces),
    formatArea(r.area),
    `${((100 * r.area) / (total || 1)).toFixed(1)}%`,
    `${r.width.toFixed(1)} m`,
    r.elongation.toFixed(1),
    r.linear ? 'yes' : 'no',
    r.color,
    r.source,
  ]);
  const widths = header.map((h, i) => Math.max(h.length, ...body.map((row) => row[i]!.length)));
  const right = new Set([1, 2, 3, 4, 5]);
  for (const row of [header, ...body]) out.push(row.map((c, i) => (right.has(i) ? c.padStart(widths[i]!) : c.padEnd(widths[i]!))).join('  ').trimEnd());
  out.push(`(width: area-weighted median of 2 area / perimeter; elong.: median of perimeter^2 / (16 area), 1 for a square, by count or area)`);
  out.push(`wrote ${file}: edit it (docs/STYLE.md), then ssc build <input> --style ${file} --out cube/`);
  return out.join('\n') + '\n';
}

export async function run(argv: string[]): Promise<void> {
  const { values, positionals } = parseArgs({
    args: argv,
    allowPositionals: true,
    options: { out: { type: 'string' }, 'class-property': { type: 'string' }, crs: { type: 'string' }, layer: { type: 'string' } },
  });
  if (positionals.length !== 1) throw new UsageError('give one input file');
  if (!values.out) throw new UsageError('--out <style.json> is required');
  const raw = await readInput(positionals[0]!, values.layer ? { layer: values.layer } : {});
  // Longitude/latitude input is projected as the build projects it, so areas are in metres.
  resolveCrs(raw, values.crs);
  const scaffold = scaffoldStyle(raw, values['class-property'] ? { classProperty: values['class-property'] } : {});
  await writeFileAtomic(values.out, formatStyleJson(scaffold.style));
  process.stdout.write(describeScaffold(scaffold, values.out));
}
