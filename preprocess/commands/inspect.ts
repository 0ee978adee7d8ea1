// ssc inspect <dir> [--json]
import { parseArgs } from 'node:util';
import { inspectCube } from '../ssc/inspect-cube.js';
import { UsageError } from './args.js';

export const usage = `ssc inspect <cube dir> [--json]
Faces, steps, scale range, chunks and their sizes, overhead against one unchunked file, the
index, the floor chunks, the line chunks, and the triangles, bytes and lines a 1280x720 view at 0.28 mm per pixel
needs at 8 scales from the base scale to the whole extent.`;

export async function run(argv: string[]): Promise<void> {
  const { values, positionals } = parseArgs({ args: argv, allowPositionals: true, options: { json: { type: 'boolean' } } });
  if (positionals.length !== 1) throw new UsageError('give one cube directory');
  const r = await inspectCube(positionals[0]!);
  if (values.json) {
    process.stdout.write(JSON.stringify(r, null, 2) + '\n');
    return;
  }
  const kb = (b: number): string => `${(b / 1024).toFixed(1)} KiB`;
  const lines = [
    `${r.name}: ${r.faces} faces, ${r.steps} steps, scale 1:${Math.round(r.scaleRange[0])} .. 1:${Math.round(r.scaleRange[1])}`,
    `chunks: ${r.chunks}, ${r.triangles} triangles, ${kb(r.bytes.total)} (min ${kb(r.bytes.min)}, median ${kb(r.bytes.median)}, max ${kb(r.bytes.max)}, CV ${r.bytes.cv.toFixed(3)})`,
    `unchunked: ${kb(r.unchunkedBytes)}, chunked/unchunked ${r.overhead.toFixed(4)}`,
    `index: depth ${r.index.depth}, ${r.index.files} file(s), ${kb(r.index.bytes)}`,
    r.floor ? `floor chunks (below z ${r.floor.top.toPrecision(3)}): ${r.floor.chunks}, ${r.floor.triangles} triangles, ${kb(r.floor.bytes)}` : 'no floor chunks',
    r.lines ? `line chunks: ${r.lines.chunks}, ${r.lines.lines} lines, ${kb(r.lines.bytes)}` : 'no lines',
    'a 1280x720 view (mean over a 5 x 5 grid of places):',
    '  scale        z          chunks  triangles  bytes      lines  line bytes',
    ...r.views.map((v) => `  1:${String(Math.round(v.scale)).padEnd(10)} ${v.z.toFixed(1).padEnd(10)} ${v.chunks.toFixed(1).padEnd(7)} ${String(v.triangles).padEnd(10)} ${kb(v.bytes).padEnd(10)} ${String(v.lines).padEnd(6)} ${kb(v.lineBytes)}`),
    `max/min over the scales: triangles ${r.viewRatio.triangles.toFixed(2)}, bytes ${r.viewRatio.bytes.toFixed(2)}`,
  ];
  process.stdout.write(lines.join('\n') + '\n');
}
