// Smooth merges on hand-made partitions, sliced through a real chunk by the CPU slicer.
//
//   +--------+----+--------+     W = [0,4] x [0,4]   area 16 (face 1)
//   |        |    |        |     L = [4,6] x [0,4]   area 8  (face 2)
//   |   W    | L  |   Z    |     Z = [6,10] x [0,4]  area 16 (face 3)
//   |        |    |        |
//   +--------+----+--------+
//
// Equal weights: L goes first (step 1), into W (a tie of shared lengths, 4 and 4, goes to the
// lower id); then Z (16 against 24) into W (step 2).
// Merge 1: nothing lies in L's area above the floor and W has always been beside it, so the
// ramp starts where the half-way rule says (see the test) on the shared side x = 4 and reaches
// zMerge = phaseZ(1, 0) = 1/9 at x = 6 (distance 2 along L's edges).
// Merge 2: W came to lie beside Z (L|Z became W|Z) at merge 1; the ramp starts at x = 6 and
// reaches zMerge = phaseZ(2, 0) = 10/9 at x = 10.
import test from 'node:test';
import assert from 'node:assert/strict';
import { decodeChunk } from '../../format/chunk.js';
import { scaleAtZ, zAtScale } from '../../format/scale.js';
import { EventKind, faceAliveAt, phaseZ, replacedFaces, scaleInfoOf, type Tgap } from '../../format/tgap-model.js';
import { fixtureStyle, fixtureTgap, rect, type FixtureFace } from '../../testing/planar-fixtures.js';
import { fitView, type View } from '../map/rasterize.js';
import { assembleChunk } from './assemble-chunk.js';
import { CpuSlicer, sliceChunk } from './cpu-slicer.js';
import { mergeConnectivity, violates } from './merge-connectivity.js';
import { buildSurfaces, SURFACE_GAP, type Surfaces } from './surfaces.js';

const W = 1, L = 2, Z = 3;
const THREE: FixtureFace[] = [
  { cls: 'a', rings: [rect(0, 0, 4, 4)] },
  { cls: 'a', rings: [rect(4, 0, 6, 4)] },
  { cls: 'a', rings: [rect(6, 0, 10, 4)] },
];

/** Every surface triangle in one chunk, decoded: slices then see what the map would. */
async function slicer(t: Tgap, s: Surfaces, view: View): Promise<(z: number) => Uint32Array> {
  const all = Uint32Array.from({ length: s.count }, (_, i) => i);
  const chunk = await decodeChunk(assembleChunk(s, all, s.xs, s.ys, (f) => t.faces[f]!.classIndex).bytes);
  return (z) => {
    const sl = new CpuSlicer(view, () => z);
    sliceChunk(sl, chunk);
    return sl.ids;
  };
}

/** Columns (pixel centre x) of the middle row, with the face at each. */
function middleRow(ids: Uint32Array, view: View): number[] {
  const j = Math.floor(view.height / 2);
  return Array.from(ids.subarray(j * view.width, (j + 1) * view.width));
}

test('a smooth merge tilts the loser from the shared boundary (hand-worked z and split)', async () => {
  const t = fixtureTgap(THREE, ['a']);
  assert.deepEqual(t.events.map((e) => [e.kind, e.step, e.loser, e.into]), [[EventKind.Merge, 1, L, W], [EventKind.Merge, 2, Z, W]]);
  const { surfaces: s, transitions } = buildSurfaces(t, { smooth: true });
  // Within the first two zoom levels a transition reaches back half way, in scale, to the base
  // scale: to the z of the geometric mean of the base scale and the merge's scale. L's ramp
  // starts there at x = 4; Z's there too (later than a gap above merge 1, when W came to lie
  // beside it at x = 6).
  const info = scaleInfoOf(t);
  const halfWay = (z: number): number => zAtScale(info, Math.sqrt(scaleAtZ(info, z) * info.baseScale));
  const ramps: Record<number, { x0: number; z0: number; x1: number; z1: number }> = {
    [L]: { x0: 4, z0: Math.max(SURFACE_GAP, halfWay(phaseZ(1, 0))), x1: 6, z1: phaseZ(1, 0) },
    [Z]: { x0: 6, z0: Math.max(phaseZ(1, 0) + SURFACE_GAP, halfWay(phaseZ(2, 0))), x1: 10, z1: phaseZ(2, 0) },
  };
  assert.ok(ramps[L]!.z0 > SURFACE_GAP && ramps[Z]!.z0 > phaseZ(1, 0) + SURFACE_GAP, 'the half-way rule binds in this case');
  // Each transition starts half a gap under its ramp's foot: the loser is whole there.
  assert.deepEqual(transitions.map((m) => [m.loser, m.into, m.zMerge]), [L, Z].map((f) => [f, W, ramps[f]!.z1]));
  transitions.forEach((m) => assert.ok(Math.abs(m.zStart - (ramps[m.loser]!.z0 - SURFACE_GAP / 2)) < 1e-12, `merge of ${m.loser}: zStart ${m.zStart}`));
  let tilted = 0;
  for (let i = 0; i < s.count; i++) {
    const r = ramps[s.lower[i]!];
    if (!r) continue;
    tilted++;
    assert.equal(s.upper[i], W);
    for (let j = 0; j < 3; j++) {
      const x = t.xs[s.v[3 * i + j]!]!;
      const want = r.z0 + ((r.z1 - r.z0) * (x - r.x0)) / (r.x1 - r.x0);
      assert.ok(Math.abs(s.z[3 * i + j]! - want) < 1e-12, `triangle ${i} vertex at x = ${x}: z ${s.z[3 * i + j]}, expected ${want}`);
    }
    assert.equal(s.zMin[i], Math.min(s.z[3 * i]!, s.z[3 * i + 1]!, s.z[3 * i + 2]!));
  }
  assert.equal(tilted, 4, 'two triangles per rectangle');
  // Without --smooth the same triangles lie flat at the merge.
  const classic = buildSurfaces(t).surfaces;
  assert.deepEqual(Array.from(classic.v.subarray(0, 3 * classic.count)), Array.from(s.v.subarray(0, 3 * s.count)));
  for (let i = 0; i < classic.count; i++) {
    if (classic.lower[i] === L) assert.deepEqual(Array.from(classic.z.subarray(3 * i, 3 * i + 3)), [1 / 9, 1 / 9, 1 / 9]);
  }

  // A chunk of merge 2's triangles alone: its box starts at their lowest vertex, the ramp's foot.
  const merge2 = Uint32Array.from({ length: s.count }, (_, i) => i).filter((i) => s.lower[i] === Z && s.upper[i] === W);
  const box = assembleChunk(s, merge2, s.xs, s.ys, () => 0).bbox;
  assert.ok(Math.abs(box[2] - ramps[Z]!.z0) < 1e-12, `box z0 ${box[2]}, the foot ${ramps[Z]!.z0}`);
  assert.equal(box[5], s.zEnd[merge2[0]!]);

  // 100 x 40 pixels of 0.1: column c has its centre at x = 0.05 + 0.1 c.
  const view = fitView(t.meta.extent, 100, 40);
  const slice = await slicer(t, s, view);
  const faceAt = (row: number[], x: number): number => row[Math.round((x - 0.05) / 0.1)]!;
  // A quarter of the way up merge 1's ramp: W has taken L up to x = 4 + 2/4 = 4.5.
  const row1 = middleRow(slice(ramps[L]!.z0 + (ramps[L]!.z1 - ramps[L]!.z0) / 4), view);
  for (const [x, f] of [[0.05, W], [3.95, W], [4.45, W], [4.55, L], [5.95, L], [6.05, Z], [9.95, Z]] as const) assert.equal(faceAt(row1, x), f, `x = ${x}`);
  // Half way up merge 2's ramp: W has taken Z up to x = 6 + 4/2 = 8.
  const row2 = middleRow(slice(ramps[Z]!.z0 + (ramps[Z]!.z1 - ramps[Z]!.z0) / 2), view);
  for (const [x, f] of [[5.05, W], [7.95, W], [8.05, Z], [9.95, Z]] as const) assert.equal(faceAt(row2, x), f, `x = ${x}`);
});

test('a smooth cube is a partition at every z and equals the classic one at the floor and the top', async () => {
  // A 4 x 3 grid of rectangles of uneven sizes and two classes.
  const xsCut = [0, 3, 4, 8, 9], ysCut = [0, 2, 5, 6];
  const faces: FixtureFace[] = [];
  for (let j = 0; j < 3; j++) {
    for (let i = 0; i < 4; i++) faces.push({ cls: (i + j) % 2 ? 'a' : 'b', rings: [rect(xsCut[i]!, ysCut[j]!, xsCut[i + 1]!, ysCut[j + 1]!)] });
  }
  const t = fixtureTgap(faces, ['a', 'b']);
  const smooth = buildSurfaces(t, { smooth: true });
  assert.ok(smooth.stats.tiltedMerges >= 5, `${smooth.stats.tiltedMerges} merges tilted`);
  // The faces the cube names: a merge held back (a class coming back) ends its loser later.
  const cubeFaces = smooth.tgap.faces;
  const view = fitView(t.meta.extent, 90, 60);
  const slice = await slicer(t, smooth.surfaces, view);
  const zMax = t.meta.steps;
  for (let k = 0; k < 200; k++) {
    const z = (zMax * k) / 199;
    const ids = slice(z);
    for (let p = 0; p < ids.length; p++) {
      const f = ids[p]!;
      assert.ok(f > 0, `z ${z}: pixel ${p} shows no face`);
      assert.ok(faceAliveAt(cubeFaces[f]!, z, zMax), `z ${z}: pixel ${p} shows face ${f}, not alive`);
    }
  }
  const classic = await slicer(t, buildSurfaces(t).surfaces, view);
  // A re-emit the smooth cube skips leaves the face its old id (never-alive new id).
  const previous = replacedFaces(t.faces);
  const root = (f: number): number => {
    let g = f;
    while (cubeFaces[g]!.stepLow === cubeFaces[g]!.stepHigh && previous.has(g)) g = previous.get(g)!;
    return g;
  };
  assert.deepEqual(slice(0), classic(0));
  assert.deepEqual(slice(zMax), classic(zMax).map(root));
});

// A cascade that would send an area back to its class:
//
//   +--+--------+----------------+-----------+-- ... --+-+
//   |X |   Y    |       Z        |  filler   |         |c|   X = [0,1]   class a, area 4
//   |a |   b    |       a        |     c     |  c ...  |c|   Y = [1,5]   class b, area 16
//   |  |        |                |           |         |c|   Z = [5,13]  class a, area 32
//   +--+--------+----------------+-----------+-- ... --+-+   6 fillers of 40, 4 squares of 1
//
// The squares go first (steps 1 to 4: early on a transition reaches back half way to the base
// scale). X's only neighbour is Y: X merges into Y (step 5), then Y (20) into Z (step 6), within
// a transition's reach. X's pixels would show a, b, a; the smooth cube holds X back until Y's
// ramp carries it to Z, so they show a throughout.
function cascade(zClass: string): { t: Tgap; X: number; Y: number; Z: number } {
  const faces: FixtureFace[] = [
    { cls: 'a', rings: [rect(0, 0, 1, 4)] },
    { cls: 'b', rings: [rect(1, 0, 5, 4)] },
    { cls: zClass, rings: [rect(5, 0, 13, 4)] },
  ];
  for (let i = 0; i < 6; i++) faces.push({ cls: 'c', rings: [rect(13 + 10 * i, 0, 23 + 10 * i, 4)] });
  for (let j = 0; j < 4; j++) faces.push({ cls: 'c', rings: [rect(73, j, 74, j + 1)] });
  return { t: fixtureTgap(faces, ['a', 'b', 'c']), X: 1, Y: 2, Z: 3 };
}

test('a smooth cube holds back a merge whose area would go back to its class: it never shows the winner in between', async () => {
  const { t, X, Y, Z } = cascade('a');
  assert.deepEqual([X, Y].map((f) => t.events.find((e) => e.loser === f)).map((e) => [e?.step, e?.into]), [[5, Y], [6, Z]]);
  const built = buildSurfaces(t, { smooth: true });
  const { surfaces: s, transitions, tgap: cube } = built;
  const m = transitions.find((x) => x.loser === X)!;
  const carrier = transitions.find((x) => x.loser === Y)!;
  assert.equal(m.held, true);
  assert.ok(carrier.tilted, 'Y tilts into Z');
  // X's transition is Y's ramp, and X lives (in the faces the cube names) until Y's merge, into Z.
  assert.deepEqual([m.zStart, m.zMerge], [carrier.zStart, carrier.zMerge]);
  assert.deepEqual([cube.faces[X]!.stepHigh, cube.faces[X]!.mergedInto], [6, Z]);
  assert.deepEqual([t.faces[X]!.stepHigh, t.faces[X]!.mergedInto], [5, Y], 'the tGAP itself unchanged');
  // Below Y's ramp lies Y, or X where a triangle's centre lies in X's part.
  for (let i = carrier.first; i < carrier.end; i++) assert.ok([X, Y].includes(s.lower[i]!), `ramp triangle ${i}: lower ${s.lower[i]}`);
  // Sliced through a real chunk at 300 z up to past the cascade: X's columns show X, then Z;
  // every pixel shows one face, alive in the cube's faces.
  const view = fitView(t.meta.extent, 730, 40);
  const slice = await slicer(t, s, view);
  const colOf = (x: number): number => Math.floor((x - view.bbox[0]) / ((view.bbox[2] - view.bbox[0]) / view.width));
  const seen = new Set<number>();
  for (let k = 0; k <= 300; k++) {
    const z = (7 * k) / 300;
    const row = middleRow(slice(z), view);
    for (let c = 0; c < colOf(1); c++) seen.add(row[c]!);
    row.forEach((f, p) => assert.ok(f > 0 && faceAliveAt(cube.faces[f]!, z, t.meta.steps), `z ${z}: column ${p} shows face ${f}`));
  }
  assert.deepEqual([...seen].sort(), [X, Z]);
});

test('a cascade that does not come back to the loser\'s class is not held back: the loser\'s area shows the winner on the way', async () => {
  const { t, X, Y, Z } = cascade('c');
  assert.deepEqual([X, Y].map((f) => t.events.find((e) => e.loser === f)).map((e) => [e?.step, e?.into]), [[5, Y], [6, Z]]);
  const { surfaces: s, transitions, tgap: cube } = buildSurfaces(t, { smooth: true });
  assert.equal(transitions.find((x) => x.loser === X)!.held, undefined);
  assert.equal(cube.faces[X]!.stepHigh, 5);
  const view = fitView(t.meta.extent, 730, 40);
  const slice = await slicer(t, s, view);
  const seen = new Set<number>();
  for (let k = 0; k <= 300; k++) seen.add(middleRow(slice((7 * k) / 300), view)[0]!);
  assert.deepEqual([...seen].sort(), [X, Y, Z]);
});

//   +--+--------+----------------+---- ... ----+--- ... ---+-+   X = [0,1]   class a, area 4
//   |a |   b    |   b or d       |      a      |  c ...    |c|   Y = [1,5]   class b, area 16
//   |  |        |                |             |           |c|   Z = [5,13]  class b or d, 32
//   +--+--------+----------------+---- ... ----+--- ... ---+-+   V = [13,53] class a, 160
//                                                                6 fillers of 60, 4 squares of 1
//
// X merges into Y (step 5), Y into Z (step 6), Z into V (step 7): X's area would show a, b, (d,)
// a. The winner's line, Y then Z, comes back to X's class only at Z's merge: X waits until then,
// and so does Y, which holds X (Y's area shows b, then a: it changes once).
function longCascade(zClass: string): Tgap {
  const faces: FixtureFace[] = [
    { cls: 'a', rings: [rect(0, 0, 1, 4)] },
    { cls: 'b', rings: [rect(1, 0, 5, 4)] },
    { cls: zClass, rings: [rect(5, 0, 13, 4)] },
    { cls: 'a', rings: [rect(13, 0, 53, 4)] },
  ];
  for (let i = 0; i < 6; i++) faces.push({ cls: 'c', rings: [rect(53 + 15 * i, 0, 68 + 15 * i, 4)] });
  for (let j = 0; j < 4; j++) faces.push({ cls: 'c', rings: [rect(143, j, 144, j + 1)] });
  return fixtureTgap(faces, ['a', 'b', 'c', 'd']);
}

for (const zClass of ['b', 'd']) {
  test(`a merge is held back along the winner's whole line (Z of class ${zClass}) until the line comes back to its class`, async () => {
    const t = longCascade(zClass);
    const X = 1, Y = 2, Z = 3, V = 4;
    assert.deepEqual([X, Y, Z].map((f) => t.events.find((e) => e.loser === f)).map((e) => [e?.step, e?.into]), [[5, Y], [6, Z], [7, V]]);
    const { surfaces: s, transitions, tgap: cube } = buildSurfaces(t, { smooth: true });
    const carrier = transitions.find((x) => x.loser === Z)!;
    for (const f of [X, Y]) {
      const m = transitions.find((x) => x.loser === f)!;
      assert.equal(m.held, true, `face ${f} held`);
      assert.deepEqual([m.zStart, m.zMerge], [carrier.zStart, carrier.zMerge], `face ${f} moves on with Z's ramp`);
      assert.deepEqual([cube.faces[f]!.stepHigh, cube.faces[f]!.mergedInto], [7, V]);
    }
    const view = fitView(t.meta.extent, 1440, 40);
    const slice = await slicer(t, s, view);
    const colOf = (x: number): number => Math.floor((x - view.bbox[0]) / ((view.bbox[2] - view.bbox[0]) / view.width));
    // Columns well inside X and inside Y (a pixel away from their sides), at 401 z from 0 to past Z's merge (step 7).
    const shown = [new Set<number>(), new Set<number>()];
    for (let k = 0; k <= 400; k++) {
      const row = middleRow(slice((9 * k) / 400), view);
      for (let c = colOf(0) + 1; c < colOf(1) - 1; c++) shown[0]!.add(row[c]!);
      for (let c = colOf(1) + 2; c < colOf(5) - 1; c++) shown[1]!.add(row[c]!);
    }
    assert.deepEqual([...shown[0]!].sort(), [X, V], 'X\'s pixels: a, then a again, never b or Z\'s class');
    assert.deepEqual([...shown[1]!].sort(), [Y, V], 'Y\'s pixels: b, then a, never Z\'s class');
  });
}

// A corner that simplification hands to a road which is then split, giving the corner back:
//
//   +--------+----+--------+-- ... --+-+    W = [0,4] x [0,4], class a, with a spike into R:
//   |        |    |        |         |b|        (4,0) (3.5,1.8) (3.8,2) (3.5,2.2) (4,4)
//   |   W   >|  R |   B    |  b ...  |b|    R = [4,5] x [0,4] and W's dent, class r (linear)
//   |        |    |        |         |b|    B = [5,9] x [0,4], class b; 3 fillers of 40 and
//   +--------+----+--------+-- ... --+-+    4 squares of 1, class b, go first (steps 1 to 4)
//
// At step 4 the W|R line loses the spike's tip (its corner goes to R), at step 5 R is split and
// the corner goes back to W. The corner's pixels would show a, r, a; the smooth cube leaves the
// removal out, and R's part for W goes round the corner.
test('a corner that a split hands back is left its own: it never shows the road, and the road\'s part goes round it', async () => {
  const spike: [number, number][] = [[3.5, 1.8], [3.8, 2], [3.5, 2.2]];
  const road: [number, number][] = [[4, 0], [5, 0], [5, 4], [4, 4], ...[...spike].reverse()];
  const faces: FixtureFace[] = [
    { cls: 'a', rings: [[[0, 0], [4, 0], ...spike, [4, 4], [0, 4]]] },
    { cls: 'r', rings: [road] },
    { cls: 'b', rings: [rect(5, 0, 9, 4)] },
  ];
  for (let i = 0; i < 3; i++) faces.push({ cls: 'b', rings: [rect(9 + 10 * i, 0, 19 + 10 * i, 4)] });
  for (let j = 0; j < 4; j++) faces.push({ cls: 'b', rings: [rect(39, j, 40, j + 1)] });
  const names = ['a', 'r', 'b'];
  const t = fixtureTgap(faces, names, fixtureStyle([{ key: 'a' }, { key: 'r', linear: true }, { key: 'b' }]));
  const R = 2;
  assert.deepEqual([1, R, 3].map((f) => names[t.faces[f]!.classIndex]), ['a', 'r', 'b']);
  const split = t.events.find((e) => e.kind === EventKind.Split)!;
  const tip = t.xs.findIndex((x, i) => x === 3.8 && t.ys[i] === 2);
  const removal = t.edges.find((e) => Array.from(e.removed).includes(tip))!;
  assert.deepEqual([split.loser, split.step, removal.stepLow, removal.removed.length], [R, 5, 4, 1], 'the fixture: the tip goes alone at step 4, R is split at step 5');
  const classic = buildSurfaces(t);
  const smooth = buildSurfaces(t, { smooth: true });
  assert.equal(smooth.stats.skippedRemovals, 1);
  // R's split parts cover R's area as it was at the start (its ring), without the corner; the
  // classic cube's cover it with the corner (0.4 x 0.3 / 2).
  let ringArea = 0;
  road.forEach(([x0, y0], i) => {
    const [x1, y1] = road[(i + 1) % road.length]!;
    ringArea += (x0 * y1 - x1 * y0) / 2;
  });
  const partArea = (b: ReturnType<typeof buildSurfaces>): number => {
    const { xs, ys, v } = b.surfaces;
    let sum = 0;
    for (const o of b.origins.filter((x) => x.kind === 'split')) {
      for (let i = o.first; i < o.end; i++) {
        const [p, q, r] = [v[3 * i]!, v[3 * i + 1]!, v[3 * i + 2]!];
        sum += ((xs[q]! - xs[p]!) * (ys[r]! - ys[p]!) - (xs[r]! - xs[p]!) * (ys[q]! - ys[p]!)) / 2;
      }
    }
    return sum;
  };
  assert.ok(Math.abs(partArea(classic) - (ringArea + 0.06)) < 1e-9, `classic: ${partArea(classic)} of ${ringArea} + 0.06`);
  assert.ok(Math.abs(partArea(smooth) - ringArea) < 1e-9, `smooth: ${partArea(smooth)} of ${ringArea}`);
  // Sliced at 400 z: the pixels of the corner's middle row show a (W), then b once W has gone
  // into b's face; never r. In the classic cube they show r between the removal and the split.
  // A view on the corner: 250 px across x 3.4 to 4.4.
  const view = fitView([3.4, 1.6, 4.4, 2.4], 250, 200);
  const cols: number[] = [];
  for (let c = 0; c < view.width; c++) {
    const x = view.bbox[0] + ((c + 0.5) * (view.bbox[2] - view.bbox[0])) / view.width;
    if (x > 3.55 && x < 3.75) cols.push(c);
  }
  assert.ok(cols.length >= 5, `the corner is ${cols.length} pixels wide`);
  /** Per column of the corner, the classes it shows in order (each run once). */
  const runs = async (b: ReturnType<typeof buildSurfaces>): Promise<string[][]> => {
    const slice = await slicer(b.tgap, b.surfaces, view);
    const seen = cols.map((): string[] => []);
    for (let k = 0; k <= 400; k++) {
      const row = middleRow(slice(((t.meta.steps + 1) * k) / 400), view);
      cols.forEach((c, i) => {
        const cls = names[b.tgap.faces[row[c]!]!.classIndex]!;
        if (seen[i]!.at(-1) !== cls) seen[i]!.push(cls);
      });
    }
    return seen;
  };
  for (const r of await runs(smooth)) assert.deepEqual(r, ['a', 'b']);
  assert.ok((await runs(classic)).every((r) => r.join() === 'a,r,a,b'), 'the classic cube shows the road in the corner, then W again');
});

// A face whose only neighbour is a face held back: the cascade above with a pond P (class d,
// weighted 8, so that it goes after X) in X's middle, x 0.25..0.75, y 1.5..2.5. X merges into Y
// (held back: Y then merges into Z, of X's class), then P into Y: all of P's boundary with Y is
// X's, and X is what shows there until Y's ramp carries it on.
test('a face merged into a winner beside which only a held-back face shows goes to that face, tilted, and moves on with it', async () => {
  const hole: [number, number][] = [[0.25, 1.5], [0.25, 2.5], [0.75, 2.5], [0.75, 1.5]];
  const faces: FixtureFace[] = [
    { cls: 'a', rings: [rect(0, 0, 1, 4), hole] },
    { cls: 'b', rings: [rect(1, 0, 5, 4)] },
    { cls: 'a', rings: [rect(5, 0, 13, 4)] },
    { cls: 'd', rings: [[...hole].reverse()] },
  ];
  for (let i = 0; i < 6; i++) faces.push({ cls: 'c', rings: [rect(13 + 10 * i, 0, 23 + 10 * i, 4)] });
  for (let j = 0; j < 4; j++) faces.push({ cls: 'c', rings: [rect(73, j, 74, j + 1)] });
  const names = ['a', 'b', 'c', 'd'];
  const t = fixtureTgap(faces, names, fixtureStyle([{ key: 'a' }, { key: 'b' }, { key: 'c' }, { key: 'd', weight: 8 }]));
  const X = 1, Y = 2, Z = 3, P = 4;
  assert.deepEqual([X, P, Y].map((f) => t.events.find((e) => e.loser === f)).map((e) => [e?.step, e?.into]), [[5, Y], [6, Y], [7, Z]], 'the fixture');
  const { surfaces: s, transitions, tgap: cube } = buildSurfaces(t, { smooth: true });
  const x = transitions.find((m) => m.loser === X)!, p = transitions.find((m) => m.loser === P)!, y = transitions.find((m) => m.loser === Y)!;
  assert.equal(x.held, true);
  assert.deepEqual([p.into, p.shownAs, p.tilted], [Y, X, true]);
  // X, and P's area with it, ends with Y's merge into Z.
  assert.deepEqual([x.zMerge, cube.faces[X]!.stepHigh, cube.faces[X]!.mergedInto], [y.zMerge, 7, Z]);
  for (let i = p.first; i < p.end; i++) assert.equal(s.upper[i], X, `P's ramp triangle ${i}`);
  // What X gains touches it at every z of the transition (the check knows the edges beside X
  // as X's, though the tGAP names them Y's).
  assert.deepEqual(mergeConnectivity(cube, s, transitions).filter(violates).map((c) => c.transition.loser), []);
  // Sliced at 300 z: the pond's pixels show d, then a (X, then Z); never b.
  const view = fitView([0, 1.6, 1, 2.4], 200, 160);
  const slice = await slicer(t, s, view);
  const runs = new Map<number, string[]>();
  for (let k = 0; k <= 300; k++) {
    const row = middleRow(slice((8 * k) / 300), view);
    row.forEach((f, c) => {
      const xc = (c + 0.5) / 200;
      if (xc < 0.3 || xc > 0.7) return;
      const r = runs.get(c) ?? [];
      const cls = names[cube.faces[f]!.classIndex]!;
      if (r.at(-1) !== cls) r.push(cls);
      runs.set(c, r);
    });
  }
  assert.ok(runs.size > 50);
  for (const [c, r] of runs) assert.deepEqual(r, ['d', 'a'], `column ${c}`);
});

//   +----- ... -----+--------+-+--+--+--------+--- ... ---+-+   V = [0,10]   class a
//   |               |        | |  |  |        |           |b|   Y = [10,14]  class c
//   |       V       |   Y    | |X |  |   B    |  b ...    |b|   R = [14,15]  class r (linear), with
//   |               |        | |  |  |        |           |b|       X = [14.1,14.45] x [0.5,3.5]
//   +----- ... -----+--------+-+--+--+--------+--- ... ---+-+       (class a) as a hole
//                                   R                           B = [15,19]  class b; 6 fillers
//                                                               of 60, 4 squares of 1, class b
// X merges into the road R (step 5), R is split (step 6), the part over X going to Y (left of
// the road's middle), and Y merges into V (step 8): X's area would show a, r, c, a. The split
// hands X's hold on to Y, whose line brings a back; X shows until Y's ramp carries it on.
test('a face held back in a road that is split stays, held back in the face a part goes to, when that face\'s line brings its class back', async () => {
  const hole: [number, number][] = [[14.1, 0.5], [14.1, 3.5], [14.45, 3.5], [14.45, 0.5]];
  const faces: FixtureFace[] = [
    { cls: 'a', rings: [rect(0, 0, 10, 4)] },
    { cls: 'c', rings: [rect(10, 0, 14, 4)] },
    { cls: 'r', rings: [rect(14, 0, 15, 4), hole] },
    { cls: 'a', rings: [[...hole].reverse()] },
    { cls: 'b', rings: [rect(15, 0, 19, 4)] },
  ];
  for (let i = 0; i < 6; i++) faces.push({ cls: 'b', rings: [rect(19 + 15 * i, 0, 34 + 15 * i, 4)] });
  for (let j = 0; j < 4; j++) faces.push({ cls: 'b', rings: [rect(109, j, 110, j + 1)] });
  const names = ['a', 'c', 'r', 'b'];
  // b and c go together reluctantly: B goes to the fillers, Y to V.
  const t = fixtureTgap(faces, names, fixtureStyle([{ key: 'a' }, { key: 'c' }, { key: 'r', linear: true }, { key: 'b' }], { b: { c: 0.5 }, c: { b: 0.5 } }));
  const V = 1, Y = 2, R = 3, X = 4;
  const split = t.events.find((e) => e.kind === EventKind.Split)!;
  assert.deepEqual([t.events.find((e) => e.loser === X)!.into, split.loser, t.events.find((e) => e.loser === Y)!.into], [R, R, V], 'the fixture');
  assert.deepEqual([X, R, Y].map((f) => t.faces[f]!.stepHigh), [5, 6, 8], 'the fixture');
  const smooth = buildSurfaces(t, { smooth: true });
  const x = smooth.transitions.find((m) => m.loser === X)!, y = smooth.transitions.find((m) => m.loser === Y)!;
  assert.equal(smooth.stats.splitFollows, 1);
  assert.equal(x.held, true);
  assert.deepEqual([x.zStart, x.zMerge, smooth.tgap.faces[X]!.stepHigh, smooth.tgap.faces[X]!.mergedInto], [y.zStart, y.zMerge, 8, V], 'X ends with Y\'s ramp, into V');
  // Sliced at 400 z up to where V's own merge (step 9) starts: per column of the road's middle
  // row, the classes shown in order (each run once).
  const zEnd = smooth.transitions.find((m) => m.loser === V)!.zStart;
  assert.ok(zEnd > y.zMerge);
  const view = fitView([13.8, 1.6, 15.2, 2.4], 280, 160);
  const runs = async (b: ReturnType<typeof buildSurfaces>): Promise<Map<number, string[]>> => {
    const slice = await slicer(b.tgap, b.surfaces, view);
    const out = new Map<number, string[]>();
    for (let k = 0; k <= 400; k++) {
      middleRow(slice((zEnd * k) / 400), view).forEach((f, c) => {
        const xc = view.bbox[0] + ((c + 0.5) * (view.bbox[2] - view.bbox[0])) / view.width;
        if (xc < 14.02 || xc > 14.98) return;
        const r = out.get(c) ?? [];
        const cls = names[b.tgap.faces[f]!.classIndex]!;
        if (r.at(-1) !== cls) r.push(cls);
        out.set(c, r);
      });
    }
    return out;
  };
  const inX = (c: number): boolean => {
    const xc = view.bbox[0] + ((c + 0.5) * (view.bbox[2] - view.bbox[0])) / view.width;
    return xc > 14.12 && xc < 14.43;
  };
  const classic = await runs(buildSurfaces(t));
  for (const [c, r] of classic) if (inX(c)) assert.deepEqual(r, ['a', 'r', 'c', 'a'], `classic column ${c}`);
  let xCols = 0;
  for (const [c, r] of await runs(smooth)) {
    // X's pixels keep a; the road's never come back to a class they left.
    if (inX(c)) {
      xCols++;
      assert.deepEqual(r, ['a'], `column ${c}, in X`);
    } else {
      assert.equal(new Set(r).size, r.length, `column ${c}, in the road: ${r.join(' ')}`);
    }
  }
  assert.ok(xCols > 50, `${xCols} columns in X`);
});

// The pond above between two held faces: X1 = [0,1] x [0,2] and X2 = [0,1] x [2,4] (class a),
// each with half of the pond P = [0.25,0.75] x [1.5,2.5] (class d, weighted 8) cut out. Both
// merge into Y (held back: Y then merges into Z, of class a), then P into Y: P's boundary with
// Y is X1's and X2's, no one face's, and Y shows beside none of it before Y's own merge.
test('a piece of a loser beside which only faces held back in the winner show goes to one of them, tilted, and stays attached to it', async () => {
  const faces: FixtureFace[] = [
    { cls: 'a', rings: [[[0, 0], [1, 0], [1, 2], [0.75, 2], [0.75, 1.5], [0.25, 1.5], [0.25, 2], [0, 2]]] },
    { cls: 'a', rings: [[[0, 2], [0.25, 2], [0.25, 2.5], [0.75, 2.5], [0.75, 2], [1, 2], [1, 4], [0, 4]]] },
    { cls: 'b', rings: [rect(1, 0, 5, 4)] },
    { cls: 'a', rings: [rect(5, 0, 13, 4)] },
    { cls: 'd', rings: [rect(0.25, 1.5, 0.75, 2.5)] },
  ];
  for (let i = 0; i < 6; i++) faces.push({ cls: 'c', rings: [rect(13 + 10 * i, 0, 23 + 10 * i, 4)] });
  for (let j = 0; j < 4; j++) faces.push({ cls: 'c', rings: [rect(73, j, 74, j + 1)] });
  const names = ['a', 'b', 'c', 'd'];
  const t = fixtureTgap(faces, names, fixtureStyle([{ key: 'a' }, { key: 'b' }, { key: 'c' }, { key: 'd', weight: 8 }]));
  const X1 = 1, X2 = 2, Y = 3, P = 5;
  assert.deepEqual([X1, X2, P].map((f) => t.events.find((e) => e.loser === f)!.into), [Y, Y, Y], 'the fixture');
  const b = buildSurfaces(t, { smooth: true });
  const p = b.transitions.find((m) => m.loser === P)!;
  assert.deepEqual([X1, X2].map((f) => b.transitions.find((m) => m.loser === f)!.held), [true, true]);
  assert.equal(p.shownAs, undefined, 'no one held face shows along all of P');
  assert.equal(p.tilted, true);
  assert.equal(p.takers?.length, 1);
  const taker = p.takers[0];
  assert.ok(taker === X1 || taker === X2);
  for (let i = p.first; i < p.end; i++) assert.equal(b.surfaces.upper[i], taker, `P's ramp triangle ${i}`);
  // What the taker gains touches it at every z of the transition (exact, on the triangles).
  assert.deepEqual(mergeConnectivity(b.tgap, b.surfaces, b.transitions).filter(violates).map((c) => c.transition.loser), []);
  // Sliced at 300 z: the pond's pixels show d, then a; never Y's b.
  const view = fitView([0, 1.6, 1, 2.4], 200, 160);
  const slice = await slicer(t, b.surfaces, view);
  const runs = new Map<number, string[]>();
  for (let k = 0; k <= 300; k++) {
    middleRow(slice((9 * k) / 300), view).forEach((f, c) => {
      const xc = (c + 0.5) / 200;
      if (xc < 0.3 || xc > 0.7) return;
      const r = runs.get(c) ?? [];
      const cls = names[b.tgap.faces[f]!.classIndex]!;
      if (r.at(-1) !== cls) r.push(cls);
      runs.set(c, r);
    });
  }
  assert.ok(runs.size > 50);
  for (const [c, r] of runs) assert.deepEqual(r, ['d', 'a'], `column ${c}`);
});
