// ssc map <tgap> --step s | --scale n --size WxH [--bbox] --out map.png [--ids ids.bin]
import { parseArgs } from 'node:util';
import { writeFileAtomic } from '../io/atomic-write.js';
import { fitView, rasterizeAt } from '../map/rasterize.js';
import { idsToPng } from '../map/render-png.js';
import { readTgap } from '../tgap/format.js';
import { stepAtScale } from '../tgap/model.js';
import { parseBbox, parseNumber, parseSize, requireOne, UsageError } from './args.js';
import { classColours } from './style-colours.js';

export const usage = `ssc map <file.tgap> (--step <s> | --scale <denominator>) --size WxH --out map.png [options]
  --bbox x0,y0,x1,y1   ground area to draw (default: the whole extent), widened to the image's shape
  --ids <file>         also write the face id of every pixel (uint32 little-endian, rows from the top)
The map of state s is the partition after s steps; --scale picks the last step at or below that scale.`;

export async function run(argv: string[]): Promise<void> {
  const { values, positionals } = parseArgs({
    args: argv,
    allowPositionals: true,
    options: {
      step: { type: 'string' },
      scale: { type: 'string' },
      size: { type: 'string' },
      bbox: { type: 'string' },
      out: { type: 'string' },
      ids: { type: 'string' },
    },
  });
  if (positionals.length !== 1) throw new UsageError('give one tGAP file');
  if (!values.out) throw new UsageError('--out <map.png> is required');
  requireOne(values, ['step', 'scale']);
  const { width, height } = parseSize(values.size);
  const bbox = parseBbox(values.bbox);
  const tgap = await readTgap(positionals[0]!);
  let step: number;
  if (values.step !== undefined) {
    step = parseNumber(values.step, '--step', { min: 0, integer: true })!;
    if (step > tgap.meta.steps) throw new UsageError(`--step must be at most ${tgap.meta.steps} (the last step)`);
  } else {
    step = Math.floor(stepAtScale(tgap.meta, parseNumber(values.scale, '--scale', { min: 1 })!));
  }
  const view = fitView(tgap.meta.extent, width, height, bbox);
  const raster = rasterizeAt(tgap, step, view);
  const colours = classColours(tgap.meta.style);
  const png = idsToPng(raster.ids, width, height, (f) => colours[tgap.faces[f]!.classIndex] ?? '#ff00ff');
  await writeFileAtomic(values.out, png);
  if (values.ids) await writeFileAtomic(values.ids, new Uint8Array(raster.ids.buffer));
  process.stdout.write(`step ${step} of ${tgap.meta.steps}: ${width}x${height} px over ${view.bbox.map((v) => v.toFixed(3)).join(',')}${raster.inconsistencies ? ` (${raster.inconsistencies} boundary inconsistencies!)` : ''}\n`);
}
