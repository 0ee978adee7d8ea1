// npm run bench:smoothness [-- <dataset filter>] [--size WxH]: how smoothly the map changes
// during a zoom (issue 11; DESIGN.md, "What the map is judged by"). For bgt_otterlo_1800m and
// nlcd_zion, the classic cube (ssc build --classic; before it had that option, ssc build) and the
// smooth one (ssc build --smooth, the default) are sliced by the CPU reference slicer
// on one fixed ground window, the whole extent at 1280x720, in 120 frames whose scale grows
// geometrically from the base scale to the scale at which the extent fills the window. Per
// frame: the share of the pixels showing a face in both frames whose class changes. Per cube:
// worst, p95, median, worst/median, the worst frame, the pixels that flicker (go back to a
// class they showed, bench/flicker.ts), triangles and bytes, beside the targets. Then
// the transition lengths of both cubes' events (bench/transition-lengths.ts; the smooth cube's
// merges from buildSurfaces' transitions on the same tGAP), and the horizontal surfaces above
// the floor that change class, by kind (preprocess/ssc/horizontal-changes.ts).
import { mkdtempSync, rmSync, statSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { parseArgs } from 'node:util';
import { readTgap } from '../format/tgap.js';
import { scaleInfoOf } from '../format/tgap-model.js';
import { fitView, type View } from '../preprocess/map/rasterize.js';
import { CHANGE_KINDS, horizontalChanges } from '../preprocess/ssc/horizontal-changes.js';
import { CubeReader } from '../preprocess/ssc/read-cube.js';
import { buildSurfaces } from '../preprocess/ssc/surfaces.js';
import { runSsc } from '../testing/run-ssc.js';
import { BenchBuildError, buildBenchCube, type BenchCube } from './bench-cube.js';
import { changeShare, classChange, type ClassFrame } from './class-change.js';
import { datasets, type Dataset } from './datasets.js';
import { FlickerCounter } from './flicker.js';
import { median, percentile } from './stats.js';
import { printTable } from './table.js';
import { classicTransitions, scaleRatios, smoothTransitions, transitionLengths, type Transition } from './transition-lengths.js';
import { ZOOM_FRAMES, zoomFrames, zoomZs } from './zoom-frames.js';

const FRAMES = ZOOM_FRAMES;
// Issue 11's targets.
const WORST_VS_CLASSIC = 0.5;
const WORST_OVER_MEDIAN = 3;
const COST_VS_CLASSIC = 1.3;

const { values, positionals } = parseArgs({ allowPositionals: true, options: { size: { type: 'string', default: '1280x720' } } });
const size = /^(\d+)x(\d+)$/.exec(values.size);
if (!size) throw new Error(`--size takes WxH, e.g. 640x360 (got ${values.size})`);
const width = Number(size[1]), height = Number(size[2]);
const sets = datasets(positionals[0], ['bgt_otterlo_1800m', 'nlcd_zion']);

interface CubeFigures {
  worst: number;
  p95: number;
  median: number;
  worstFrame: number;
  /** Pixels that went back to a class they showed before, away from boundaries. */
  flicker: number;
  /** Of those, or not, pixels that went back to a face (only a cube can do that). */
  faceReturns: number;
  triangles: number;
  bytes: number;
  gzipBytes: number;
  msPerFrame: number;
  zFirst: number;
  zLast: number;
}

/** The 120 frames of the zoom on `cube` and their class changes. */
async function zoom(cube: BenchCube): Promise<CubeFigures> {
  const reader = await CubeReader.open(cube.dir);
  const meta = reader.index.meta;
  const view: View = fitView(meta.extent, width, height);
  const shares: number[] = [];
  const ms: number[] = [];
  // The map's own scale -> z.
  const zs = zoomZs(meta, meta.pixelSizeMm, view, FRAMES);
  const flicker = new FlickerCounter(width, height);
  let before: ClassFrame | undefined;
  for await (const { slicer, ms: t } of zoomFrames(reader, view, zs)) {
    ms.push(t);
    if (before) shares.push(changeShare(classChange(before, slicer)));
    flicker.add(slicer);
    before = { ids: slicer.ids, classes: slicer.classes };
  }
  const worst = Math.max(...shares);
  return {
    worst, p95: percentile(shares, 0.95), median: median(shares),
    // Frame i is the change from frame i - 1 to i.
    worstFrame: shares.indexOf(worst) + 1,
    flicker: flicker.flickering,
    faceReturns: flicker.faceReturns,
    triangles: cube.leaves.reduce((s, l) => s + l.triangles, 0),
    bytes: cube.leaves.reduce((s, l) => s + l.bytes, 0),
    gzipBytes: cube.leaves.reduce((s, l) => s + statSync(path.join(cube.dir, `${l.file}.gz`)).size, 0),
    // The first frame reads and decodes the chunks; the median is the slicing.
    msPerFrame: median(ms),
    zFirst: zs[0] ?? NaN, zLast: zs[zs.length - 1] ?? NaN,
  };
}

/**
 * `ssc build` with `flag`, or undefined when the build does not know that option (yet): the
 * smooth cube comes with --smooth, and issue 11 keeps today's cube behind --classic once the
 * smooth one is the default.
 */
function buildWith(d: Dataset, dir: string, flag: string, variant: string): BenchCube | undefined {
  try {
    return buildBenchCube(d, dir, { args: [flag], variant, precompress: true });
  } catch (err) {
    if (!(err instanceof BenchBuildError) || !err.stderr.toLowerCase().includes(`unknown option '${flag}'`)) throw err;
    process.stderr.write(`  (ssc build has no ${flag})\n`);
    return undefined;
  }
}

const pct = (x: number): string => `${(100 * x).toFixed(3)}%`;
const ratio = (x: number): string => (Number.isFinite(x) ? x.toFixed(2) : 'inf');
const mb = (b: number): string => (b / 1e6).toFixed(2);
const check = (name: string, x: number, limit: number): string => `${name} ${ratio(x)}${x <= limit ? '<=' : '>'}${limit} ${x <= limit ? 'ok' : 'MISSED'}`;

/** The targets for a cube: worst/median for both, the rest against the classic cube. */
function targets(f: CubeFigures, classic?: CubeFigures): string {
  const out = [check('worst/median', f.worst / f.median, WORST_OVER_MEDIAN)];
  if (classic) {
    out.unshift(check('worst x', f.worst / classic.worst, WORST_VS_CLASSIC));
    out.push(check('bytes x', f.bytes / classic.bytes, COST_VS_CLASSIC), check('triangles x', f.triangles / classic.triangles, COST_VS_CLASSIC));
  }
  return out.join(', ');
}

const t0 = performance.now();
const dir = mkdtempSync(path.join(tmpdir(), 'ssc-bench-'));
const head = ['dataset', 'cube', 'z range', 'worst', 'p95', 'median', 'worst/median', 'worst frame', 'flicker px', 'face back px', 'ms/frame', 'triangles', 'MB', 'MB gzip', 'targets'];
const rows: string[][] = [head];
const transitionRows: string[][] = [['dataset', 'cube', 'events', 'median S(end)/S(start)', 'p10', 'frames of an x2 step at the median']];
const horizontalRows: string[][] = [['dataset', 'cube', 'class-changing horizontal triangles', ...CHANGE_KINDS, ...CHANGE_KINDS.map((k, i) => (i === 0 ? `their area: ${k}` : k))]];
const lengthsRow = (d: Dataset, cube: string, ts: Transition[], info: ReturnType<typeof scaleInfoOf>): string[] => {
  const t = transitionLengths(scaleRatios(ts, info));
  return [d.name, cube, String(t.events), t.median.toFixed(5), t.p10.toFixed(5), t.framesAtMedian.toPrecision(3)];
};
/** The horizontal class changes of the surfaces of a build. */
const horizontalRow = (d: Dataset, cube: string, built: ReturnType<typeof buildSurfaces>): string[] => {
  const h = horizontalChanges(built.surfaces, built.origins, (f) => built.tgap.faces[f]!.classIndex);
  return [d.name, cube, String(h.total), ...CHANGE_KINDS.map((k) => String(h.byKind[k])), ...CHANGE_KINDS.map((k) => h.areaByKind[k].toExponential(2))];
};
try {
  for (const d of sets) {
    // The events come from the tGAP the build makes from the same source.
    const tgapFile = path.join(dir, `${d.name}.tgap`);
    const g = runSsc(['generalize', d.file, '--style', d.style, '--out', tgapFile, '--quiet']);
    if (g.code !== 0) throw new Error(`ssc generalize ${d.name} failed (exit ${g.code}): ${g.stderr}`);
    const tgap = await readTgap(tgapFile);
    transitionRows.push(lengthsRow(d, 'classic', classicTransitions(tgap.events), scaleInfoOf(tgap)));
    horizontalRows.push(horizontalRow(d, 'classic', buildSurfaces(tgap, { smooth: false })));

    const classicDir = path.join(dir, `${d.name}-classic`);
    const classicCube = buildWith(d, classicDir, '--classic', 'classic') ?? buildBenchCube(d, classicDir, { variant: 'classic', precompress: true });
    const classic = await zoom(classicCube);
    const row = (cube: string, f: CubeFigures, vs?: CubeFigures): string[] => [
      d.name, cube, `${f.zFirst.toFixed(0)}..${f.zLast.toFixed(0)}`, pct(f.worst), pct(f.p95), pct(f.median), ratio(f.worst / f.median), String(f.worstFrame),
      String(f.flicker), String(f.faceReturns), f.msPerFrame.toFixed(0), String(f.triangles), mb(f.bytes), mb(f.gzipBytes), targets(f, vs),
    ];
    rows.push(row('classic', classic));
    rmSync(classicCube.dir, { recursive: true, force: true });

    const smoothCube = buildWith(d, path.join(dir, `${d.name}-smooth`), '--smooth', 'smooth');
    if (!smoothCube) {
      const why = 'not available: ssc build has no --smooth';
      rows.push([d.name, 'smooth', ...head.slice(2, -1).map(() => '-'), why]);
      transitionRows.push([d.name, 'smooth', '-', '-', '-', why]);
      horizontalRows.push([d.name, 'smooth', ...horizontalRows[0]!.slice(2).map(() => '-')]);
    } else {
      rows.push(row('smooth', await zoom(smoothCube), classic));
      // The smooth build's merge transitions, from the same tGAP as the cube.
      const built = buildSurfaces(tgap, { smooth: true });
      transitionRows.push(lengthsRow(d, 'smooth', smoothTransitions(built.tgap.events, built.transitions, built.splits), scaleInfoOf(tgap)));
      horizontalRows.push(horizontalRow(d, 'smooth', built));
      rmSync(smoothCube.dir, { recursive: true, force: true });
    }
  }
} finally {
  rmSync(dir, { recursive: true, force: true });
}
console.log(`bench:smoothness, ${FRAMES} frames of a geometric zoom from the base scale to the whole extent, ${width}x${height}, CPU slicer, node ${process.version}`);
console.log('share of the pixels with a face in both frames whose class changes from the frame before; MB: chunk files, and their .gz copies');
console.log(`targets (issue 11): smooth worst <= ${WORST_VS_CLASSIC}x classic worst; worst/median <= ${WORST_OVER_MEDIAN}; smooth bytes and triangles <= ${COST_VS_CLASSIC}x classic`);
printTable(rows);
console.log('flicker px: pixels that show a class, then another, then the first again, each time 1 px or more from a face boundary (target 0; the tGAP has some of its own); face back px: the same for a face, which only the cube can cause');
console.log('\ntransition lengths: S(end)/S(start) per merge or split; a classic event lasts from phase 0 to the last removal phase of its step, a smooth tilted merge from its transition\'s start to the merge');
printTable(transitionRows);
console.log('\nno sudden changes: horizontal triangles above the floor whose upper and lower faces differ in class (target 0), by the kind of event (mergeFlat, splitFlat: flat triangles inside tilted merges and split parts); area in ground units squared');
printTable(horizontalRows);
console.log(`\n${((performance.now() - t0) / 1000).toFixed(0)} s in all`);
