// ssc generalize + ssc map on bgt_otterlo_400m, checked against the input itself and against
// a per-face drawing made here from the tGAP's edges.
import test from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { dataset, styleFile } from '../testing/paths.js';
import { readIds } from '../testing/ids-file.js';
import { runSsc } from '../testing/run-ssc.js';
import { tempDir } from '../testing/temp-dir.js';
import { compareIds, rasterizeFeatures } from './helpers/reference-raster.js';
import { readTgap } from '../format/tgap.js';
import { EventKind, resolveFace, type Tgap } from '../format/tgap-model.js';
import { fitView } from '../preprocess/map/rasterize.js';

const W = 400, H = 300;

/** Oriented boundary segments of every face alive at step s (face on the left). */
function faceBoundaries(t: Tgap, s: number): Map<number, number[]> {
  const out = new Map<number, number[]>();
  const add = (f: number, ax: number, ay: number, bx: number, by: number): void => {
    if (f === 0) return;
    let l = out.get(f);
    if (!l) out.set(f, (l = []));
    l.push(ax, ay, bx, by);
  };
  for (const e of t.edges) {
    if (e.stepLow > s || e.stepHigh <= s) continue;
    const l = resolveFace(t.faces, e.left, s), r = resolveFace(t.faces, e.right, s);
    assert.notEqual(l, r, `edge with ${l} on both sides at step ${s}`);
    for (let i = 0; i + 1 < e.verts.length; i++) {
      const ax = t.xs[e.verts[i]!]!, ay = t.ys[e.verts[i]!]!, bx = t.xs[e.verts[i + 1]!]!, by = t.ys[e.verts[i + 1]!]!;
      add(l, ax, ay, bx, by);
      add(r, bx, by, ax, ay);
    }
  }
  return out;
}

function area2(segs: number[], rx: number, ry: number): number {
  let s = 0;
  for (let i = 0; i < segs.length; i += 4) s += (segs[i]! - rx) * (segs[i + 3]! - ry) - (segs[i + 2]! - rx) * (segs[i + 1]! - ry);
  return s;
}

/** Checks, at each sampled step, that the map is a partition whose areas add up (see the test). */
function checkPartitions(tgap: Tgap, tgapFile: string, dir: string, samples: number[]): void {
  const view = fitView(tgap.meta.extent, 160, 120);
  const [vx0, , vx1, vy1] = view.bbox;
  const px = (vx1 - vx0) / 160, py = (view.bbox[3] - view.bbox[1]) / 120;
  const rx = tgap.meta.extent[0], ry = tgap.meta.extent[1];
  let domainArea2 = -1;
  for (const s of samples) {
    const faces = faceBoundaries(tgap, s);
    const alive = tgap.faces.map((f, i) => (i > 0 && f.stepLow <= s && s < f.stepHigh ? i : -1)).filter((i) => i > 0);
    assert.deepEqual([...faces.keys()].sort((a, b) => a - b), alive, `faces on the boundary at step ${s} are exactly the alive faces`);
    assert.equal(alive.length, tgap.meta.facesAlive[s], `facesAlive[${s}]`);
    // Areas: each face from its own closed boundary; the domain from the edges along the outside.
    let sum = 0;
    for (const [f, segs] of faces) {
      const a = area2(segs, rx, ry);
      assert.ok(a > 0, `face ${f} has positive area at step ${s}`);
      sum += a;
    }
    const outside: number[] = [];
    for (const e of tgap.edges) {
      if (e.stepLow > s || e.stepHigh <= s) continue;
      const l = resolveFace(tgap.faces, e.left, s), r = resolveFace(tgap.faces, e.right, s);
      if (l !== 0 && r !== 0) continue;
      for (let i = 0; i + 1 < e.verts.length; i++) {
        const a = e.verts[i]!, b = e.verts[i + 1]!;
        if (l !== 0) outside.push(tgap.xs[a]!, tgap.ys[a]!, tgap.xs[b]!, tgap.ys[b]!);
        else outside.push(tgap.xs[b]!, tgap.ys[b]!, tgap.xs[a]!, tgap.ys[a]!);
      }
    }
    const domain = area2(outside, rx, ry);
    assert.ok(Math.abs(sum - domain) <= 1e-9 * domain, `step ${s}: faces add up to ${sum / 2}, domain is ${domain / 2}`);
    if (domainArea2 < 0) domainArea2 = domain;
    // Per-face drawing: every pixel centre inside the domain lies in exactly one face.
    const count = new Uint8Array(160 * 120);
    for (const segs of faces.values()) {
      for (let j = 0; j < 120; j++) {
        const y = vy1 - (j + 0.5) * py;
        const xsCross: number[] = [];
        for (let k = 0; k < segs.length; k += 4) {
          const ay = segs[k + 1]!, by = segs[k + 3]!;
          if (ay > y !== by > y) xsCross.push(segs[k]! + ((y - ay) * (segs[k + 2]! - segs[k]!)) / (by - ay));
        }
        xsCross.sort((a, b) => a - b);
        for (let k = 0; k + 1 < xsCross.length; k += 2) {
          for (let i = Math.max(0, Math.ceil((xsCross[k]! - vx0) / px - 0.5)); i < 160 && vx0 + (i + 0.5) * px < xsCross[k + 1]!; i++) count[j * 160 + i]!++;
        }
      }
    }
    const map = runSsc(['map', tgapFile, '--step', String(s), '--size', '160x120', '--out', path.join(dir, `s${s}.png`), '--ids', path.join(dir, `s${s}.ids`)]);
    assert.equal(map.code, 0, map.stderr);
    assert.doesNotMatch(map.stdout, /inconsistenc/, `the map of step ${s} is consistent`);
    const ids = readIds(path.join(dir, `s${s}.ids`));
    let overlap = 0, gaps = 0;
    const aliveSet = new Set(alive);
    for (let p = 0; p < ids.length; p++) {
      if (count[p]! > 1) overlap++;
      if (ids[p] !== 0 && count[p] === 0) gaps++;
      if (ids[p] !== 0) assert.ok(aliveSet.has(ids[p]!), `step ${s}: pixel shows face ${ids[p]}, which is not alive`);
    }
    assert.equal(overlap, 0, `step ${s}: pixels in more than one face`);
    assert.ok(gaps <= 2, `step ${s}: ${gaps} map pixels in no face`);
  }
}

test('bgt_otterlo_400m: generalize, map at step 0 and at sampled steps', async (t) => {
  const dir = tempDir(t);
  const input = dataset('bgt_otterlo_400m.geojson');
  const out = path.join(dir, 'o.tgap');
  const gen = runSsc(['generalize', input, '--style', styleFile('bgt.json'), '--out', out, '--quiet']);
  assert.equal(gen.code, 0, gen.stderr);
  const tgap = await readTgap(out);
  const geo = JSON.parse(readFileSync(input, 'utf8')) as { features: { geometry: { type: string; coordinates: number[][][] | number[][][][] } }[] };
  const nb = geo.features.length;
  assert.equal(tgap.meta.baseFaces, nb);

  await t.test('step 0 reproduces the input (independent rasterization)', () => {
    const view = fitView(tgap.meta.extent, W, H);
    const m = runSsc(['map', out, '--step', '0', '--size', `${W}x${H}`, '--out', path.join(dir, 'm0.png'), '--ids', path.join(dir, 'm0.ids')]);
    assert.equal(m.code, 0, m.stderr);
    const ids = readIds(path.join(dir, 'm0.ids'));
    const polys = geo.features.map((f) => (f.geometry.type === 'Polygon' ? [f.geometry.coordinates as number[][][]] : (f.geometry.coordinates as number[][][][])));
    const ref = rasterizeFeatures(polys, view);
    // Face f at step 0 is input feature f - 1.
    const c = compareIds(ids, ref, W, H);
    assert.ok(c.equal / (W * H) >= 0.995, `only ${(100 * c.equal / (W * H)).toFixed(2)}% of pixels equal`);
    assert.equal(c.offBoundary, 0, `${c.offBoundary} differing pixels are not on a boundary`);
    let covered = 0;
    for (const v of ids) if (v) covered++;
    assert.ok(covered > 0.6 * W * H, 'the map covers the domain');
  });

  await t.test('every sampled step is a partition whose areas add up', () => {
    const steps = tgap.meta.steps;
    assert.equal(steps, tgap.events.filter((e) => e.kind !== EventKind.Reemit).length, 'one merge or split per step');
    checkPartitions(tgap, out, dir, [0, 1, 2, 5, 10, 25, 50, 100, 150, 200, 250, 300, 350, 400, 430, 460, steps - 1, steps].filter((s) => s <= steps));
  });

  await t.test('faces decrease by one per step and never come back', () => {
    const fa = tgap.meta.facesAlive;
    for (let s = 1; s < fa.length; s++) assert.equal(fa[s - 1]! - fa[s]!, 1, `step ${s}`);
    for (const [i, f] of tgap.faces.entries()) {
      if (i === 0) continue;
      assert.ok(f.stepLow < f.stepHigh, `face ${i} lives for at least one step`);
      if (f.mergedInto > 0) {
        const into = tgap.faces[f.mergedInto]!;
        const later = into.stepHigh > f.stepHigh || (into.stepHigh === f.stepHigh && into.endPhase > f.endPhase);
        assert.ok(into.stepLow <= f.stepHigh && later, `face ${i} is merged into a face alive after it`);
      }
    }
    // No edge refers to a face outside the face's life.
    for (const e of tgap.edges) {
      for (const f of [e.left, e.right]) {
        if (f === 0) continue;
        assert.ok(tgap.faces[f]!.stepLow <= e.stepLow, 'an edge never refers to a face made after it');
      }
    }
  });

  await t.test('two runs give byte-identical output', () => {
    const again = path.join(dir, 'again.tgap');
    const r = runSsc(['generalize', input, '--style', styleFile('bgt.json'), '--out', again, '--quiet']);
    assert.equal(r.code, 0, r.stderr);
    assert.ok(readFileSync(out).equals(readFileSync(again)), 'the two tGAP files differ');
  });
});

test('bgt_otterlo_400m with --group 8: several independent events a step, still a partition', async (t) => {
  const dir = tempDir(t);
  const out = path.join(dir, 'g.tgap');
  const gen = runSsc(['generalize', dataset('bgt_otterlo_400m.geojson'), '--style', styleFile('bgt.json'), '--group', '8', '--out', out, '--quiet']);
  assert.equal(gen.code, 0, gen.stderr);
  const tgap = await readTgap(out);
  const steps = tgap.meta.steps;
  const perStep = new Map<number, number>();
  for (const e of tgap.events) if (e.kind !== EventKind.Reemit) perStep.set(e.step, (perStep.get(e.step) ?? 0) + 1);
  let grouped = 0;
  for (let s = 1; s <= steps; s++) {
    const n = perStep.get(s) ?? 0;
    assert.ok(n >= 1 && n <= 8, `step ${s} has ${n} events`);
    assert.equal(tgap.meta.facesAlive[s - 1]! - tgap.meta.facesAlive[s]!, n, `faces drop by the events of step ${s}`);
    if (n > 1) grouped++;
  }
  assert.ok(steps < 474 / 2 && grouped > steps / 2, `${steps} steps, ${grouped} of them with several events`);
  checkPartitions(tgap, out, dir, Array.from({ length: steps + 1 }, (_, s) => s).filter((s) => s % 5 === 0 || s === steps));
  // The cube of a grouped tGAP slices to the same maps.
  const cube = path.join(dir, 'cube');
  assert.equal(runSsc(['build', out, '--out', cube, '--quiet', '--no-precompress', '--classic']).code, 0);
  for (const s of [0, Math.floor(steps / 3), Math.floor((2 * steps) / 3), steps]) {
    assert.equal(runSsc(['slice', cube, '--step', String(s), '--size', '160x120', '--out', path.join(dir, 'a.png'), '--ids', path.join(dir, 'a.ids')]).code, 0);
    assert.equal(runSsc(['map', out, '--step', String(s), '--size', '160x120', '--out', path.join(dir, 'b.png'), '--ids', path.join(dir, 'b.ids')]).code, 0);
    const a = readIds(path.join(dir, 'a.ids')), b = readIds(path.join(dir, 'b.ids'));
    let differ = 0;
    for (let p = 0; p < a.length; p++) if (a[p] !== b[p]) differ++;
    assert.ok(differ <= 0.005 * a.length, `step ${s}: ${differ} pixels differ`);
  }
});
