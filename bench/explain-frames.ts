// npm run bench:explain [-- <dataset filter>] [--size WxH] [--classic] [--worst N] [--tgap FILE] [--analytic]:
// what bench:smoothness's worst frames consist of. The zoom is bench:smoothness's (120 frames,
// the whole extent, geometric in scale), sliced by the CPU slicer straight from the surfaces the
// build makes (buildSurfaces on the tGAP of ssc generalize, before chunking's float32 rounding),
// with each pixel naming the surface triangle it shows. A pixel whose class changes from one
// frame to the next shows a triangle that came up between the two z (z only grows), so the
// change belongs to that triangle's event (buildSurfaces' origins: a merge, a part of a split,
// one edge's removals, a re-emit). For the N worst frames: the changed pixels by kind of event,
// and the events that changed the most, each with how far its transition reached back, how far
// it could have (reachBackZ), and over how many frames its pixels change; for a merge, the
// earliest z its front could leave the shared boundary (the winner beside it), and for any
// event the z from which its winner (upper face) exists. --tgap FILE keeps the
// tGAP there (generalized once, read on later runs). --analytic credits the changed area of
// each surface triangle exactly instead of slicing (bench/changed-area.ts): seconds instead of
// minutes, the same figures up to pixel rounding, but no flicker count.
import { existsSync, mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { parseArgs } from 'node:util';
import { PIXEL_SIZE_MM } from '../format/pixel-size.js';
import { scaleAtZ } from '../format/scale.js';
import { readTgap } from '../format/tgap.js';
import { faceStartZ, scaleInfoOf, type Tgap } from '../format/tgap-model.js';
import { fitView } from '../preprocess/map/rasterize.js';
import { CpuSlicer } from '../preprocess/ssc/cpu-slicer.js';
import { changedArea } from './changed-area.js';
import { buildSurfaces, reachBackZ, type MergeTransition, type SplitTransition, type SurfaceOrigin, type Surfaces } from '../preprocess/ssc/surfaces.js';
import { runSsc } from '../testing/run-ssc.js';
import { datasets } from './datasets.js';
import { FlickerCounter } from './flicker.js';
import { median, percentile } from './stats.js';
import { printTable } from './table.js';
import { zoomZs } from './zoom-frames.js';

const { values, positionals } = parseArgs({
  allowPositionals: true,
  options: { size: { type: 'string', default: '1280x720' }, classic: { type: 'boolean', default: false }, worst: { type: 'string', default: '3' }, tgap: { type: 'string' }, top: { type: 'string', default: '12' }, analytic: { type: 'boolean', default: false } },
});
const size = /^(\d+)x(\d+)$/.exec(values.size);
if (!size) throw new Error(`--size takes WxH, e.g. 640x360 (got ${values.size})`);
const width = Number(size[1]), height = Number(size[2]);
const worstN = Number(values.worst), topN = Number(values.top);
if (!(Number.isInteger(worstN) && worstN > 0 && Number.isInteger(topN) && topN > 0)) throw new Error('--worst and --top take whole numbers > 0');
const sets = datasets(positionals[0], ['bgt_otterlo_400m', 'bgt_otterlo_1800m', 'nlcd_zion']);
if (values.tgap && sets.length > 1) throw new Error('--tgap names one tGAP: give a dataset filter that matches one dataset');

/** Slices `s` at z over the view; each pixel's id is its triangle + 1 (0: none). */
function sliceSurfaces(s: Surfaces, byZ: Int32Array, classOf: (f: number) => number, view: ReturnType<typeof fitView>, z: number): CpuSlicer {
  const sl = new CpuSlicer(view, () => z);
  const { xs, ys, v } = s;
  for (const t of byZ) {
    if (s.zMin[t]! > z) break;
    const a = v[3 * t]!, b = v[3 * t + 1]!, c = v[3 * t + 2]!;
    sl.triangle(xs[a]!, ys[a]!, s.z[3 * t]!, xs[b]!, ys[b]!, s.z[3 * t + 1]!, xs[c]!, ys[c]!, s.z[3 * t + 2]!, t + 1, s.lower[t]!, classOf(s.upper[t]!));
  }
  return sl;
}

/** The origin holding triangle t (origins cover the triangles in order). */
function originOf(origins: readonly SurfaceOrigin[], t: number): number {
  let lo = 0, hi = origins.length - 1;
  while (lo < hi) {
    const mid = (lo + hi + 1) >> 1;
    if (origins[mid]!.first <= t) lo = mid;
    else hi = mid - 1;
  }
  return lo;
}

/** The frame whose z range (after the frame before) holds z: zs[f - 1] < z <= zs[f]. */
function frameOf(zs: readonly number[], z: number): number {
  let f = 0;
  while (f < zs.length && zs[f]! < z) f++;
  return f;
}

function explain(name: string, tgap: Tgap, smooth: boolean, analytic: boolean): void {
  const built = buildSurfaces(tgap, { smooth });
  const { surfaces: s, origins } = built;
  const faces = built.tgap.faces;
  const info = scaleInfoOf(tgap);
  const view = fitView(tgap.meta.extent, width, height);
  const zs = zoomZs(info, PIXEL_SIZE_MM, view);
  const classOf = (f: number): number => faces[f]!.classIndex;
  const faceStart = (f: number): number => faceStartZ(faces[f]!);
  /** Per origin touched, its changed pixels per frame. */
  const perOrigin = new Map<number, Map<number, number>>();
  const shares: number[] = [];
  const changedPx: number[] = [];
  let before: CpuSlicer | undefined;
  const t0 = performance.now();
  // Flicker (bench/flicker.ts) by the event whose triangle brings a pixel back to a class.
  const flicker = new FlickerCounter(width, height);
  const flickerBy = new Map<number, number>();
  const faceIds = new Uint32Array(width * height);
  if (analytic) {
    // Areas in pixels of the view.
    const px = ((view.bbox[2] - view.bbox[0]) / view.width) * ((view.bbox[3] - view.bbox[1]) / view.height);
    const ca = changedArea(s, classOf, zs);
    for (let f = 1; f < zs.length; f++) {
      shares.push(ca.domain === 0 ? 0 : ca.perFrame[f]! / ca.domain);
      changedPx.push(Math.round(ca.perFrame[f]! / px));
    }
    for (const [t, byFrame] of ca.perTriangle) {
      const o = originOf(origins, t);
      let m = perOrigin.get(o);
      if (!m) perOrigin.set(o, (m = new Map()));
      for (const [f, a] of byFrame) m.set(f, (m.get(f) ?? 0) + a / px);
    }
    for (const m of perOrigin.values()) for (const [f, a] of m) m.set(f, Math.round(a));
  } else {
    const byZ = Int32Array.from({ length: s.count }, (_, i) => i).sort((a, b) => s.zMin[a]! - s.zMin[b]! || a - b);
    zs.forEach((z, f) => {
      const sl = sliceSurfaces(s, byZ, classOf, view, z);
      for (let p = 0; p < faceIds.length; p++) faceIds[p] = sl.ids[p] === 0 ? 0 : s.upper[sl.ids[p]! - 1]!;
      const flickered = flicker.flickering;
      flicker.add({ ids: faceIds, classes: sl.classes });
      if (flicker.flickering > flickered) {
        for (let p = 0; p < faceIds.length; p++) {
          const i = p % width, j = Math.floor(p / width);
          if (!flicker.flickeredIn(i, j, f)) continue;
          const o = originOf(origins, sl.ids[p]! - 1);
          flickerBy.set(o, (flickerBy.get(o) ?? 0) + 1);
        }
      }
      if (before) {
        let domain = 0, changed = 0;
        for (let p = 0; p < sl.ids.length; p++) {
          if (before.ids[p] === 0 || sl.ids[p] === 0) continue;
          domain++;
          if (before.classes[p] === sl.classes[p]) continue;
          changed++;
          const o = originOf(origins, sl.ids[p]! - 1);
          let m = perOrigin.get(o);
          if (!m) perOrigin.set(o, (m = new Map()));
          m.set(f, (m.get(f) ?? 0) + 1);
        }
        shares.push(domain === 0 ? 0 : changed / domain);
        changedPx.push(changed);
      }
      before = sl;
    });
  }
  const cube = smooth ? 'smooth' : 'classic';
  const pct = (x: number): string => `${(100 * x).toFixed(3)}%`;
  const worst = Math.max(...shares);
  console.log(`\n${name} ${cube}: ${s.count} triangles, ${origins.length} events, ${analytic ? 'changed areas computed' : 'sliced'} in ${((performance.now() - t0) / 1000).toFixed(0)} s`);
  console.log(`  per frame: worst ${pct(worst)} (frame ${shares.indexOf(worst) + 1}), p95 ${pct(percentile(shares, 0.95))}, median ${pct(median(shares))}, worst/median ${(worst / median(shares)).toFixed(2)}`);
  const merges = new Map<number, MergeTransition>(built.transitions.map((m) => [m.first, m]));
  const flickerKinds = new Map<string, number>();
  for (const [o, n] of flickerBy) flickerKinds.set(origins[o]!.kind, (flickerKinds.get(origins[o]!.kind) ?? 0) + n);
  if (analytic) console.log('  flicker: not counted with --analytic (it needs the pixels)');
  else console.log(`  flicker: ${flicker.flickering} px (face back: ${flicker.faceReturns}), brought back by ${flickerBy.size} events: ${[...flickerKinds].map(([k, n]) => `${k} ${n}`).join(', ')}`);
  for (const [o, n] of [...flickerBy].sort((a, b) => b[1] - a[1]).slice(0, 5)) {
    const origin = origins[o]!;
    console.log(`    ${origin.kind} of step ${origin.step}, ${origin.face} -> ${origin.into} (classes ${faces[origin.face]?.classIndex ?? '-'} -> ${faces[origin.into]?.classIndex ?? '-'}): ${n} px`);
  }
  const splits = new Map<number, SplitTransition>(built.splits.map((p) => [p.loser, p]));
  /** The z range an origin's change spans, and the earliest it could have started. */
  const span = (o: SurfaceOrigin): { zStart: number; zEnd: number } => {
    let zStart = Infinity, zEnd = -Infinity;
    for (let t = o.first; t < o.end; t++) {
      zStart = Math.min(zStart, s.zMin[t]!);
      zEnd = Math.max(zEnd, s.z[3 * t]!, s.z[3 * t + 1]!, s.z[3 * t + 2]!);
    }
    return { zStart, zEnd };
  };
  const ranked = shares.map((x, i) => ({ frame: i + 1, x })).sort((a, b) => b.x - a.x).slice(0, worstN);
  for (const { frame, x } of ranked) {
    const z0 = zs[frame - 1]!, z1 = zs[frame]!;
    console.log(`\n  frame ${frame}: ${pct(x)} (${changedPx[frame - 1]} px), z ${z0.toFixed(2)}..${z1.toFixed(2)}, scale 1:${scaleAtZ(info, z1).toFixed(0)}`);
    const byKind = new Map<string, { px: number; events: number }>();
    const here: { o: number; px: number }[] = [];
    for (const [o, m] of perOrigin) {
      const px = m.get(frame);
      if (!px) continue;
      const origin = origins[o]!;
      const merge = origin.kind === 'merge' ? merges.get(origin.first) : undefined;
      const kind = merge && !merge.tilted ? 'merge (flat)' : origin.kind;
      const k = byKind.get(kind) ?? { px: 0, events: 0 };
      k.px += px;
      k.events++;
      byKind.set(kind, k);
      here.push({ o, px });
    }
    console.log(`  by kind: ${[...byKind].sort((a, b) => b[1].px - a[1].px).map(([k, v]) => `${k} ${v.px} px (${v.events} events)`).join(', ')}`);
    here.sort((a, b) => b.px - a.px);
    const top = here.slice(0, topN);
    console.log(`  the ${top.length} events that changed the most hold ${top.reduce((n, e) => n + e.px, 0)} px; ${here.length} events changed pixels`);
    const rows: string[][] = [['kind', 'step', 'face -> into', 'classes', 'px here', 'px in all', 'frames with px', 'z start..end', 'frames start..end', 'reach back to', 'frames it could have', 'front from', 'winner from']];
    for (const { o, px } of top) {
      const origin = origins[o]!;
      const m = perOrigin.get(o)!;
      const total = [...m.values()].reduce((a, b) => a + b, 0);
      const fs = [...m.keys()].sort((a, b) => a - b);
      const { zStart, zEnd } = span(origin);
      const merge = origin.kind === 'merge' ? merges.get(origin.first) : undefined;
      const split = origin.kind === 'split' ? splits.get(origin.face) : undefined;
      const zEventEnd = merge?.zMerge ?? split?.zSplit ?? zEnd;
      const reach = reachBackZ(info, zEventEnd);
      const cls = (f: number): string => (f > 0 ? String(faces[f]!.classIndex) : '-');
      rows.push([
        merge && !merge.tilted ? 'merge (flat)' : origin.kind, String(origin.step), `${origin.face} -> ${origin.into}`, `${cls(origin.face)} -> ${cls(origin.into)}`,
        String(px), String(total), `${fs[0]}..${fs[fs.length - 1]} (${fs.length})`,
        `${zStart.toFixed(2)}..${zEventEnd.toFixed(2)}`, `${frameOf(zs, zStart)}..${frameOf(zs, zEventEnd)}`,
        reach.toFixed(2), String(frameOf(zs, zEventEnd) - frameOf(zs, reach)),
        merge ? merge.zFront.toFixed(2) : '-', origin.into > 0 ? faceStart(origin.into).toFixed(2) : '-',
      ]);
    }
    printTable(rows.map((r) => r.map((c) => `  ${c}`)));
    // Events whose change ends in this frame: many ending together is what a front cannot spread.
    const ending = here.filter(({ o }) => {
      const origin = origins[o]!;
      const merge = origin.kind === 'merge' ? merges.get(origin.first) : undefined;
      const z = merge?.zMerge ?? span(origin).zEnd;
      return z > z0 && z <= z1;
    });
    console.log(`  of them, ${ending.length} events end in this frame, with ${ending.reduce((n, e) => n + e.px, 0)} px here`);
  }
}

const dir = mkdtempSync(path.join(tmpdir(), 'ssc-explain-'));
try {
  for (const d of sets) {
    const tgapFile = values.tgap ?? path.join(dir, `${d.name}.tgap`);
    if (!existsSync(tgapFile)) {
      const g = runSsc(['generalize', d.file, '--style', d.style, '--out', tgapFile, '--quiet']);
      if (g.code !== 0) throw new Error(`ssc generalize ${d.name} failed (exit ${g.code}): ${g.stderr}`);
    }
    const tgap = await readTgap(tgapFile);
    explain(d.name, tgap, !values.classic, values.analytic);
  }
} finally {
  rmSync(dir, { recursive: true, force: true });
}
