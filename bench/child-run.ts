// One measured run in a fresh process (so peak memory is this run's alone): generalize, or
// generalize and build. Prints a JSON line with the wall time and the peak resident memory.
import { generalizeFile } from '../preprocess/pipeline.js';
import { buildCube } from '../preprocess/ssc/build-cube.js';
import { encodeTgap } from '../format/tgap.js';
import { writeFileAtomic } from '../preprocess/io/atomic-write.js';

const [mode, input, style, out, chunkBytes] = process.argv.slice(2);
if (!mode || !input || !style || !out) throw new Error('usage: child-run generalize|build <input> <style> <out> [chunkBytes]');
const t0 = performance.now();
const { tgap, report } = await generalizeFile(input, { style });
const tGen = performance.now() - t0;
let tBuild = 0;
if (mode === 'build') {
  const t1 = performance.now();
  await buildCube(tgap, out, { ...(chunkBytes ? { chunkBytes: Number(chunkBytes) } : {}) });
  tBuild = performance.now() - t1;
} else {
  await writeFileAtomic(out, encodeTgap(tgap));
}
process.stdout.write(JSON.stringify({
  ms: performance.now() - t0,
  generalizeMs: tGen,
  buildMs: tBuild,
  maxRssMB: process.resourceUsage().maxRSS / 1024,
  faces: report.topology.faceCount,
  steps: report.generalize.steps,
  timings: report.timings,
}) + '\n');
