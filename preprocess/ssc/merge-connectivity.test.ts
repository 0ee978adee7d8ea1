// No spurious multi-parts: hand-made tilted surfaces where the winner's gain must (or must not)
// come apart, the hand-worked smooth merges of three rectangles, and every merge of
// bgt_otterlo_400m's smooth surfaces.
//
// A strip of three unit squares, loser L = [0,3] x [0,1], sharing x = 0 with the winner:
//
//   4----5----6----7      y = 1       vertex ids: bottom 0..3 at x = 0..3, top 4..7
//   | \  | \  | \  |
//   0----1----2----3      y = 0       triangles (a, b, b+4), (a, b+4, a+4) per square
import test from 'node:test';
import assert from 'node:assert/strict';
import { fixtureTgap, rect, type FixtureFace } from '../../testing/planar-fixtures.js';
import { generalizedDataset } from '../../testing/generalized-dataset.js';
import { tempDir } from '../../testing/temp-dir.js';
import { fitView } from '../map/rasterize.js';
import { surfacesSlicer } from '../../testing/surfaces-slicer.js';
import { detachedParts, mergeConnectivity, samplesInside, violates } from './merge-connectivity.js';
import { buildSurfaces, Surfaces } from './surfaces.js';

const STRIP = [0, 1, 5, 0, 5, 4, 1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6];
const SHARED = new Set([0, 4]);
/** Corner z of the strip's triangles from z per column x = 0..3. */
const stripZ = (zx: number[]): number[] => STRIP.map((v) => zx[v % 4]!);

test('a ramp rising from the shared boundary keeps the gain attached at every slice', () => {
  const tris = { v: STRIP, z: stripZ([1, 2, 3, 4]) };
  for (const zs of [1.5, 2.5, 3.5, 4.5]) assert.equal(detachedParts(tris, SHARED, zs), 0, `z ${zs}`);
});

test('a surface rising then falling: the far end is taken before the middle, an island', () => {
  // z 1, 3, 3, 2 along x: at 2.5 the winner holds x <= 1/4 and, apart, x >= 2 + 1/2.
  const tris = { v: STRIP, z: stripZ([1, 3, 3, 2]) };
  assert.equal(detachedParts(tris, SHARED, 1.5), 0);
  assert.equal(detachedParts(tris, SHARED, 2.5), 1);
  assert.equal(detachedParts(tris, SHARED, 3.5), 0, 'all taken: one part again');
  // Two islands: columns 1 and 3 low, 0 and 2 high (x = 0 is on the shared boundary).
  assert.equal(detachedParts({ v: STRIP, z: stripZ([5, 1, 5, 1]) }, SHARED, 2), 2);
});

/** Connected parts (8-neighbours) of the pixels showing face f. */
function pixelParts(ids: Uint32Array, w: number, h: number, f: number): number {
  const seen = new Uint8Array(ids.length);
  let parts = 0;
  for (let p0 = 0; p0 < ids.length; p0++) {
    if (ids[p0] !== f || seen[p0]) continue;
    parts++;
    const stack = [p0];
    seen[p0] = 1;
    while (stack.length > 0) {
      const p = stack.pop()!;
      const i = p % w, j = Math.floor(p / w);
      for (let dj = -1; dj <= 1; dj++) for (let di = -1; di <= 1; di++) {
        const ii = i + di, jj = j + dj, q = jj * w + ii;
        if (ii < 0 || jj < 0 || ii >= w || jj >= h || seen[q] || ids[q] !== f) continue;
        seen[q] = 1;
        stack.push(q);
      }
    }
  }
  return parts;
}

test('sliced as the map sees it, the rising-then-falling strip shows the winner in two parts exactly when an island is found', async () => {
  // The winner W (face 1) is the square [-1,0] x [0,1] west of the strip (vertices 8, 9); the
  // strip is the loser L (face 2). Both on the floor; the merge tilted over L, z 1, 3, 3, 2 along x.
  const xs = Float64Array.of(0, 1, 2, 3, 0, 1, 2, 3, -1, -1), ys = Float64Array.of(0, 0, 0, 0, 1, 1, 1, 1, 0, 1);
  const s = new Surfaces();
  s.add(8, 0, 4, 0, 1, 0);
  s.add(8, 4, 9, 0, 1, 0);
  for (let i = 0; i < STRIP.length; i += 3) s.add(STRIP[i]!, STRIP[i + 1]!, STRIP[i + 2]!, 0, 2, 0);
  const z = stripZ([1, 3, 3, 2]);
  for (let i = 0; i < STRIP.length; i += 3) s.addTilted(STRIP[i]!, STRIP[i + 1]!, STRIP[i + 2]!, z[i]!, z[i + 1]!, z[i + 2]!, 1, 2, 'merge');
  s.zEnd.fill(10);
  const view = fitView([-1, 0, 3, 1], 160, 40);
  const slice = await surfacesSlicer(s, xs, ys, () => 0, view);
  for (const zs of [1.5, 2.25, 2.5, 2.75, 3.5]) {
    const islands = detachedParts({ v: STRIP, z }, SHARED, zs);
    assert.equal(pixelParts(slice(zs).ids, 160, 40, 1), 1 + islands, `z ${zs}: ${islands} islands found`);
  }
  assert.equal(detachedParts({ v: STRIP, z }, SHARED, 2.5), 1, 'the raster case above does have an island');
});

test('parts touching only at a corner below the slice are one part; a corner above it parts them', () => {
  // Two triangles meeting at vertex 1 only: (0, 1, 4) and (1, 2, 6). Vertex 1 low joins them.
  const v = [0, 1, 4, 1, 2, 6];
  assert.equal(detachedParts({ v, z: [1, 2, 1, 2, 5, 1] }, SHARED, 3), 0, 'joined through vertex 1 and triangle (1,2,6)\'s corner 6');
  assert.equal(detachedParts({ v, z: [1, 4, 1, 4, 5, 1] }, SHARED, 3), 1, 'vertex 1 above: the second triangle\'s corner 6 is apart');
});

test('samplesInside spaces n slices strictly inside the transition', () => {
  assert.deepEqual(samplesInside(0, 9, 8), [1, 2, 3, 4, 5, 6, 7, 8]);
});

// The three rectangles of smooth-merge.test.ts: L = [4,6] x [0,4] merges into W = [0,4] x [0,4]
// (step 1), then Z = [6,10] x [0,4] into W (step 2); both ramps rise linearly from the shared side.
const THREE: FixtureFace[] = [
  { cls: 'a', rings: [rect(0, 0, 4, 4)] },
  { cls: 'a', rings: [rect(4, 0, 6, 4)] },
  { cls: 'a', rings: [rect(6, 0, 10, 4)] },
];

test('the smooth merges of three rectangles have no violation; ramps turned round, every sample does', () => {
  const t = fixtureTgap(THREE, ['a']);
  const { surfaces: s, transitions } = buildSurfaces(t, { smooth: true });
  const checks = mergeConnectivity(t, s, transitions);
  assert.deepEqual(checks.map((c) => [c.transition.loser, c.triangles.length, c.detached]), [[2, 2, [0, 0, 0, 0, 0, 0, 0, 0]], [3, 2, [0, 0, 0, 0, 0, 0, 0, 0]]]);
  // Turn L's ramp round: x = 6 at the foot, x = 4 (the side shared with W) at the top.
  const [lo, hi] = [transitions[0]!.zStart + 1e-3, transitions[0]!.zMerge];
  for (const i of checks[0]!.triangles) for (let j = 0; j < 3; j++) s.z[3 * i + j] = t.xs[s.v[3 * i + j]!] === 4 ? hi : lo;
  const turned = mergeConnectivity(t, s, transitions);
  // Every sample lies above the foot and below the top: L's far side is W's, apart from W.
  assert.deepEqual(turned[0]!.detached, [1, 1, 1, 1, 1, 1, 1, 1]);
  assert.ok(violates(turned[0]!) && !violates(turned[1]!));
});

test('a merge marked tilted without triangles in its transition is an error naming it', () => {
  const t = fixtureTgap(THREE, ['a']);
  const { surfaces: s, transitions } = buildSurfaces(t, { smooth: true });
  const wrong = transitions.map((m) => ({ ...m, end: m.first }));
  assert.throws(() => mergeConnectivity(t, s, wrong), /merge of face 2 into 1 \(step 1\) is marked tilted but has no triangles/);
});

test('bgt_otterlo_400m: no merge\'s gain comes apart from the winner at 8 z inside its transition', async (t) => {
  const { tgap } = await generalizedDataset(tempDir(t), 'bgt_otterlo_400m.geojson', 'bgt.json');
  const { surfaces, transitions, tgap: cube } = buildSurfaces(tgap, { smooth: true });
  const checks = mergeConnectivity(cube, surfaces, transitions);
  assert.ok(checks.length > 0.5 * transitions.length, `${checks.length} of ${transitions.length} merges tilted`);
  // Every merge found its shared boundary's corners among its triangles (else all would be "detached").
  const bad = checks.filter(violates).map((c) => `${c.transition.loser}->${c.transition.into}: ${c.detached.join(' ')}`);
  assert.deepEqual(bad, []);
});
