// ssc slice <dir> (--step s | --scale n) --size WxH [--bbox] [--surface spec] [--line-width px] --out slice.png [--ids ids.bin]
import { parseArgs } from 'node:util';
import { zAtScale } from '../../format/scale.js';
import { parseSurface, type Surface } from '../../format/slicing-surface.js';
import { writeFileAtomic } from '../io/atomic-write.js';
import { lineOfChunk, type LineRecord } from '../../format/line-chunk.js';
import { DEFAULT_LINE_WIDTH_PX, drawLines } from '../map/draw-lines.js';
import { fitView } from '../map/rasterize.js';
import { idsToPng } from '../map/render-png.js';
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
  --line-width <px>    width of the lines of linear classes (default ${DEFAULT_LINE_WIDTH_PX}; 0: none)
The CPU reference slicer: at each pixel centre the nearest surface at or below the slicing
surface gives the face, read through the index from the chunk files like the map does; lines
are drawn over the faces where the surface's z at the pixel lies in their range.`;

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
  for (const leaf of v.lineWidth > 0 ? cube.lineChunks({ ground: view.bbox, zMin, zMax }) : []) {
    const c = await cube.lineChunk(leaf);
    for (let i = 0; i < c.lineCount; i++) lines.push(lineOfChunk(c, i));
  }
  const lineClass = drawLines(view, lines, (p) => slicer.zs[p]!, v.lineWidth);
  await writeFileAtomic(v.out, pngByClass(slicer, lineClass, meta.style.classes.map((c) => c.color)));
  if (values.ids) await writeFileAtomic(values.ids, new Uint8Array(slicer.ids.buffer));
  process.stdout.write(`z ${base.toFixed(3)} (${surface.spec.kind}, ${zMin.toFixed(2)}..${zMax.toFixed(2)}): ${chunks} chunks, ${triangles} triangles, ${v.width}x${v.height} px\n`);
}

/** Colours by the class of the line, else of the surface, at each pixel (the chunks hold both; no face table needed). */
function pngByClass(sl: CpuSlicer, lineClass: Uint16Array, colours: string[]): Uint8Array {
  const { width, height } = sl.view;
  const byPixel = new Uint32Array(width * height);
  for (let p = 0; p < byPixel.length; p++) byPixel[p] = lineClass[p] || (sl.ids[p] === 0 ? 0 : sl.classes[p]! + 1);
  return idsToPng(byPixel, width, height, (c) => colours[c - 1] ?? '#ff00ff');
}
