// ssc map <tgap> --step s | --scale n --size WxH [--bbox] [--no-lines] --out map.png [--ids ids.bin]
import { parseArgs } from 'node:util';
import { writeFileAtomic } from '../io/atomic-write.js';
import { fitView, rasterizeAt } from '../map/rasterize.js';
import { pngWithLines } from '../map/png-with-lines.js';
import { readTgap } from '../../format/tgap.js';
import { scaleInfoOf } from '../../format/tgap-model.js';
import { zAtScale } from '../../format/scale.js';
import { UsageError, viewArgs, viewOptionSpecs } from './args.js';
import { classColours } from './style-colours.js';
import { drawLines } from '../map/draw-lines.js';
import { cubeLines } from '../ssc/cube-lines.js';
import { parseStyle } from '../style.js';

export const usage = `ssc map <file.tgap> (--step <s> | --scale <denominator>) --size WxH --out map.png [options]
  --bbox x0,y0,x1,y1   ground area to draw (default: the whole extent), widened to the image's shape
  --ids <file>         also write the face id of every pixel (uint32 little-endian, rows from the top)
  --no-lines           the faces alone, without the lines of linear classes
The map of state s is the partition after s steps; --scale picks the last step at or below that scale.
Lines of linear classes (collapsed, pruned and simplified as ssc build makes them) are drawn over it
as the style's line rules say (widths in mm at 0.28 mm per pixel).`;

export async function run(argv: string[]): Promise<void> {
  const { values, positionals } = parseArgs({ args: argv, allowPositionals: true, options: viewOptionSpecs });
  const v = viewArgs(values, positionals, 'tGAP file');
  const tgap = await readTgap(v.input);
  let step: number;
  if (v.step !== undefined) {
    if (!Number.isInteger(v.step)) throw new UsageError('--step must be a whole step for a map (ssc slice takes fractional z)');
    if (v.step > tgap.meta.steps) throw new UsageError(`--step must be at most ${tgap.meta.steps} (the last step)`);
    step = v.step;
  } else {
    step = Math.floor(zAtScale(scaleInfoOf(tgap), v.scale!));
  }
  const view = fitView(tgap.meta.extent, v.width, v.height, v.bbox);
  const raster = rasterizeAt(tgap, step, view);
  const colours = classColours(tgap.meta.style);
  const style = parseStyle(tgap.meta.style, `${v.input}: its style`);
  const lines = v.lines && style.lineRules.length > 0 ? cubeLines(tgap, style) : [];
  const info = scaleInfoOf(tgap);
  const linePaint = drawLines(view, lines, style.lineRules, { zAt: () => step, info });
  const png = pngWithLines(raster.ids, linePaint, style.lineRules, v.width, v.height, (f) => colours[tgap.faces[f]!.classIndex]);
  await writeFileAtomic(v.out, png);
  if (values.ids) await writeFileAtomic(values.ids, new Uint8Array(raster.ids.buffer));
  process.stdout.write(`step ${step} of ${tgap.meta.steps}: ${v.width}x${v.height} px over ${view.bbox.map((x) => x.toFixed(3)).join(',')}${raster.inconsistencies ? ` (${raster.inconsistencies} boundary inconsistencies!)` : ''}\n`);
}
