import test from 'node:test';
import assert from 'node:assert/strict';
import { generalizedDataset } from '../../testing/generalized-dataset.js';
import { tempDir } from '../../testing/temp-dir.js';
import { EventKind, faceStartZ, REEMIT_PHASE, replacedFaces, scaleInfoOf, type Tgap } from '../../format/tgap-model.js';
import { fitView, rasterizeAt } from '../map/rasterize.js';
import { skipLateReemits } from './late-reemits.js';
import { buildSurfaces, reachBackZ } from './surfaces.js';

test('bgt_otterlo_400m: skipping late re-emits changes no state of the map, only which id a face has', async (t) => {
  const { tgap } = await generalizedDataset(tempDir(t), 'bgt_otterlo_400m.geojson', 'bgt.json');
  const info = scaleInfoOf(tgap);
  const reemitsBefore = tgap.events.filter((e) => e.kind === EventKind.Reemit).length;
  const { tgap: out, skipped } = skipLateReemits(tgap, (z) => reachBackZ(info, z));
  assert.ok(skipped > 10, `${skipped} of ${reemitsBefore} re-emits skipped`);
  assert.equal(out.events.filter((e) => e.kind === EventKind.Reemit).length, reemitsBefore - skipped);
  assert.equal(tgap.events.filter((e) => e.kind === EventKind.Reemit).length, reemitsBefore, 'the input is left as it was');

  // The skipped ids, and the face each stands for: along the input's re-emit links, back to the
  // first id that is kept.
  const gone = new Set<number>();
  out.faces.forEach((f, i) => { if (i > 0 && f.stepLow === f.stepHigh && tgap.faces[i]!.stepLow < tgap.faces[i]!.stepHigh) gone.add(i); });
  assert.equal(gone.size, skipped);
  const previous = replacedFaces(tgap.faces);
  const root = (f: number): number => { let g = f; while (gone.has(g)) g = previous.get(g)!; return g; };
  // Nothing names a skipped id any more.
  for (const e of out.edges) assert.ok(!gone.has(e.left) && !gone.has(e.right));
  for (const e of out.events) assert.ok(!gone.has(e.loser) && !gone.has(e.into) && !(e.triFaces ?? []).some((f) => gone.has(f)));
  for (const f of out.faces) assert.ok(!gone.has(f.mergedInto));
  // A skipped face's area, at every state, is its root's: the same map under other ids.
  const view = fitView(tgap.meta.extent, 160, 160);
  const steps = tgap.meta.steps;
  let compared = 0;
  for (let k = 0; k <= steps; k += Math.max(1, Math.floor(steps / 40))) {
    const a = rasterizeAt(tgap, k, view).ids, b = rasterizeAt(out, k, view).ids;
    for (let p = 0; p < a.length; p++) assert.equal(b[p], root(a[p]!), `step ${k}, pixel ${p}`);
    compared++;
  }
  assert.ok(compared >= 40);

  // What it is for: a face that ends soon after a re-emit may start its transition before it.
  const { transitions, tgap: cube, surfaces: s } = buildSurfaces(tgap, { smooth: true });
  assert.equal(cube.faces.length, out.faces.length);
  const reemitZ = new Map<number, number>();
  for (const g of gone) reemitZ.set(root(g), Math.max(reemitZ.get(root(g)) ?? -Infinity, faceStartZ(tgap.faces[g]!)));
  const concerned = transitions.filter((m) => reemitZ.has(m.loser) && reemitZ.get(m.loser)! < m.zMerge);
  const earlier = concerned.filter((m) => m.zStart < reemitZ.get(m.loser)!);
  t.diagnostic(`${concerned.length} merges of faces re-emitted within reach; ${earlier.length} start before that re-emit`);
  assert.ok(concerned.length > 0 && earlier.length >= 0.5 * concerned.length, `${earlier.length} of ${concerned.length}`);

  // A merge into a kept new id may start before its re-emit: its ramp names the new id
  // throughout, and the id's record in the cube starts at the state where it first shows.
  const across = transitions.filter((m) => !m.held && m.zStart < faceStartZ(tgap.faces[m.into]!));
  let below = 0;
  for (const m of across) {
    assert.ok(!gone.has(m.into), `merge of ${m.loser} into ${m.into}: its re-emit is kept`);
    for (let i = m.first; i < m.end; i++) {
      assert.equal(s.upper[i], m.shownAs ?? m.into, `merge of ${m.loser}: triangle ${i}'s upper face`);
      if (s.zMin[i]! >= faceStartZ(tgap.faces[m.into]!)) continue;
      below++;
      assert.ok(faceStartZ(cube.faces[s.upper[i]!]!) <= s.zMin[i]!, `merge of ${m.loser}: face ${s.upper[i]} is alive at z ${s.zMin[i]}`);
    }
  }
  t.diagnostic(`${across.length} merges start before their winner's re-emit, ${below} triangles below it`);
  assert.ok(across.length > 10 && below > across.length, `${across.length} merges, ${below} triangles`);
});

test('a re-emit of a face that lives to the top, or ends beyond reach, is kept', () => {
  const faces = [
    { classIndex: 0, feature: -1, stepLow: 0, stepHigh: 11, mergedInto: -1, endPhase: 0, area2: 0 },
    // 1 is re-emitted as 2 at step 3; 2 merges into 3 at step 10.
    { classIndex: 0, feature: 0, stepLow: 0, stepHigh: 3, mergedInto: 2, endPhase: REEMIT_PHASE, area2: 2 },
    { classIndex: 0, feature: 0, stepLow: 3, stepHigh: 10, mergedInto: 3, endPhase: 0, area2: 2 },
    { classIndex: 1, feature: 1, stepLow: 0, stepHigh: 11, mergedInto: -1, endPhase: 0, area2: 4 },
  ];
  const t: Tgap = {
    meta: { version: 1, crs: '', extent: [0, 0, 1, 1], baseScale: 1000, resolutionMm: 0.28, baseFaces: 2, steps: 10, facesAlive: [], holes: [], repairs: {}, source: '', style: {}, attributes: [], options: {} },
    xs: new Float64Array(0), ys: new Float64Array(0), faces, edges: [],
    events: [{ kind: EventKind.Reemit, step: 3, loser: 1, into: 2 }, { kind: EventKind.Merge, step: 10, loser: 2, into: 3 }],
  };
  // The merge (z 9.1) may reach back to z 2: before the re-emit (z 2.9), which is skipped.
  const skip = skipLateReemits(t, () => 2);
  assert.equal(skip.skipped, 1);
  assert.deepEqual(skip.tgap.events, [{ kind: EventKind.Merge, step: 10, loser: 1, into: 3 }]);
  assert.deepEqual([skip.tgap.faces[1]!.stepHigh, skip.tgap.faces[1]!.mergedInto, skip.tgap.faces[1]!.endPhase], [10, 3, 0]);
  assert.equal(skip.tgap.faces[2]!.stepLow, skip.tgap.faces[2]!.stepHigh, 'the new id is never shown');
  // It may reach back only to z 5: after the re-emit, which stays.
  assert.equal(skipLateReemits(t, () => 5).skipped, 0);
  // A merge into the new id (of 4 at step 9) that may reach back to z 2, across the re-emit:
  // its ramp names the new id throughout, so the re-emit stays.
  const into: Tgap = {
    ...t,
    faces: [...faces.map((f, i) => (i === 2 ? { ...f, stepHigh: 11, mergedInto: -1 } : f)), { classIndex: 1, feature: 2, stepLow: 0, stepHigh: 9, mergedInto: 2, endPhase: 0, area2: 1 }],
    events: [t.events[0]!, { kind: EventKind.Merge, step: 9, loser: 4, into: 2 }],
  };
  assert.equal(skipLateReemits(into, () => 2).skipped, 0);
  // Living to the top: nothing to reach back from.
  faces[2] = { ...faces[2]!, stepHigh: 11, mergedInto: -1 };
  assert.equal(skipLateReemits({ ...t, events: t.events.slice(0, 1) }, () => 0).skipped, 0);
});
