// ssc map <tgap> --step s | --scale n --size WxH [--bbox] [--line-width px] --out map.png [--ids ids.bin]
import { parseArgs } from 'node:util';
import { writeFileAtomic } from '../io/atomic-write.js';
import { fitView, rasterizeAt } from '../map/rasterize.js';
import { idsToPng } from '../map/render-png.js';
import { readTgap } from '../../format/tgap.js';
import { scaleInfoOf } from '../../format/tgap-model.js';
import { zAtScale } from '../../format/scale.js';
import { UsageError, viewArgs, viewOptionSpecs } from './args.js';
import { classColours } from './style-colours.js';
import { drawLines, DEFAULT_LINE_WIDTH_PX } from '../map/draw-lines.js';
import { cubeLines } from '../ssc/cube-lines.js';
import { parseStyle } from '../style.js';

const LINE_KEY = 0x80000000;

export const usage = `ssc map <file.tgap> (--step <s> | --scale <denominator>) --size WxH --out map.png [options]
  --bbox x0,y0,x1,y1   ground area to draw (default: the whole extent), widened to the image's shape
  --ids <file>         also write the face id of every pixel (uint32 little-endian, rows from the top)
  --line-width <px>    width of the lines of linear classes (default ${DEFAULT_LINE_WIDTH_PX}; 0: none)
The map of state s is the partition after s steps; --scale picks the last step at or below that scale.
Lines of linear classes (collapsed, pruned and simplified as ssc build makes them) are drawn over it.`;

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
  const lines = v.lineWidth > 0 && style.classes.some((c) => c.linear) ? cubeLines(tgap, style) : [];
  const lineClass = drawLines(view, lines, () => step, v.lineWidth);
  // Pixels with a line get a key above every face id: 1 + the line's class.
  const keys = raster.ids.map((f, p) => (lineClass[p] ? LINE_KEY + lineClass[p] : f));
  const png = idsToPng(keys, v.width, v.height, (k) => (k > LINE_KEY ? colours[k - LINE_KEY - 1] : colours[tgap.faces[k]!.classIndex]) ?? '#ff00ff');
  await writeFileAtomic(v.out, png);
  if (values.ids) await writeFileAtomic(values.ids, new Uint8Array(raster.ids.buffer));
  process.stdout.write(`step ${step} of ${tgap.meta.steps}: ${v.width}x${v.height} px over ${view.bbox.map((x) => x.toFixed(3)).join(',')}${raster.inconsistencies ? ` (${raster.inconsistencies} boundary inconsistencies!)` : ''}\n`);
}
