// ssc slice <dir> (--step s | --scale n) --size WxH [--bbox] [--surface spec] [--no-lines] --out slice.png [--ids ids.bin]
import { parseArgs } from 'node:util';
import { zAtScale } from '../../format/scale.js';
import { parseSurface, type Surface } from '../../format/slicing-surface.js';
import { writeFileAtomic } from '../io/atomic-write.js';
import { lineOfChunk } from '../../format/line-chunk.js';
import type { LineRecord } from '../../format/line-record.js';
import { drawLines, type LinePaint } from '../map/draw-lines.js';
import type { LineRule } from '../../format/line-style.js';
import { fitView } from '../map/rasterize.js';
import { pngWithLines } from '../map/png-with-lines.js';
import type { CpuSlicer } from '../ssc/cpu-slicer.js';
import { CubeReader } from '../ssc/read-cube.js';
import { UsageError, viewArgs, viewOptionSpecs } from './args.js';
import { sliceCube } from './slice-cube.js';

export const usage = `ssc slice <cube dir> (--step <z> | --scale <denominator>) --size WxH --out slice.png [options]
  --bbox x0,y0,x1,y1   ground area (default: the whole extent), widened to the image's shape
  --surface <spec>     slicing surface around the base z (default flat), e.g.
                         tilted:cx=..,cy=..,dzdx=..,dzdy=..   sine:amplitude=..,wavelength=..,angle=..
                         lens:cx=..,cy=..,radius=..,depth=..   idw:power=2,points=x y z;x y z
  --ids <file>         also write the face id of every pixel (uint32 little-endian, rows from the top)
  --no-lines           the faces alone, without the lines of linear classes
The CPU reference slicer: at each pixel centre the nearest surface at or below the slicing
surface gives the face, read through the index from the chunk files like the map does; lines
are drawn over the faces, as the style's line rules say (widths in mm at 0.28 mm per pixel),
where the surface's z at the pixel lies in their z range and its scale in their rule's.`;

export async function run(argv: string[]): Promise<void> {
  const { values, positionals } = parseArgs({ args: argv, allowPositionals: true, options: { ...viewOptionSpecs, surface: { type: 'string' } } });
  const v = viewArgs(values, positionals, 'cube directory');
  const cube = await CubeReader.open(v.input);
  const meta = cube.index.meta;
  const base = v.step ?? zAtScale(meta, v.scale!);
  if (base > meta.zMax) throw new UsageError(`--step must be at most ${meta.zMax}`);
  let surface: Surface;
  try {
    surface = { base, spec: values.surface ? parseSurface(values.surface) : { kind: 'flat' } };
  } catch (err) {
    throw new UsageError(`--surface: ${(err as Error).message}`);
  }
  const view = fitView(meta.extent, v.width, v.height, v.bbox);
  const { slicer, zMin, zMax, chunks, triangles } = await sliceCube(cube, meta.zMax, view, surface);
  const lines: LineRecord[] = [];
  for (const leaf of v.lines ? cube.lineChunks({ ground: view.bbox, zMin, zMax }) : []) {
    const c = await cube.lineChunk(leaf);
    for (let i = 0; i < c.lineCount; i++) lines.push(lineOfChunk(c, i));
  }
  const linePaint = drawLines(view, lines, meta.style.lines, { zAt: (p) => slicer.zs[p]!, info: meta });
  await writeFileAtomic(v.out, pngByClass(slicer, linePaint, meta.style.lines, meta.style.classes.map((c) => c.color)));
  if (values.ids) await writeFileAtomic(values.ids, new Uint8Array(slicer.ids.buffer));
  process.stdout.write(`z ${base.toFixed(3)} (${surface.spec.kind}, ${zMin.toFixed(2)}..${zMax.toFixed(2)}): ${chunks} chunks, ${triangles} triangles, ${v.width}x${v.height} px\n`);
}

/** Colours by the line painted, else by the class of the surface, at each pixel (the chunks hold both; no face table needed). */
function pngByClass(sl: CpuSlicer, linePaint: LinePaint, rules: readonly LineRule[], colours: string[]): Uint8Array {
  const { width, height } = sl.view;
  const byClass = new Uint32Array(width * height);
  for (let p = 0; p < byClass.length; p++) byClass[p] = sl.ids[p] === 0 ? 0 : sl.classes[p]! + 1;
  return pngWithLines(byClass, linePaint, rules, width, height, (c) => colours[c - 1]);
}
