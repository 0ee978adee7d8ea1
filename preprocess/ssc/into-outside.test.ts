// A face with no neighbour leaves the map when its turn comes: it merges into the outside
// (face 0), in the tGAP, in the cube (classic and smooth) and through the tGAP file.
//
//   +--------+----+--------+          W = [0,4] x [0,4]   area 16 (face 1)
//   |   W    | L  |   Z    |   +--+   L = [4,6] x [0,4]   area 8  (face 2)
//   +--------+----+--------+   +--+   Z = [6,10] x [0,4]  area 16 (face 3)
//                                     I = [12,13] x [0,1] area 1  (face 4), alone in the outside
//
// Equal weights: I is the least important, so it goes first (step 1), into the outside; then L
// into W (step 2) and Z into W (step 3), as without I.
import test from 'node:test';
import assert from 'node:assert/strict';
import { decodeTgap, encodeTgap } from '../../format/tgap.js';
import { EventKind, faceAliveAt, faceEndZ, phaseZ, resolveFace } from '../../format/tgap-model.js';
import { fixtureTgap, rect, type FixtureFace } from '../../testing/planar-fixtures.js';
import { surfacesSlicer } from '../../testing/surfaces-slicer.js';
import { fitView } from '../map/rasterize.js';
import { mergeConnectivity, violates } from './merge-connectivity.js';
import { mergeTriangles } from './merge-surface.js';
import { buildSurfaces } from './surfaces.js';

const W = 1, L = 2, Z = 3, I = 4;
const FACES: FixtureFace[] = [
  { cls: 'a', rings: [rect(0, 0, 4, 4)] },
  { cls: 'a', rings: [rect(4, 0, 6, 4)] },
  { cls: 'a', rings: [rect(6, 0, 10, 4)] },
  { cls: 'a', rings: [rect(12, 0, 13, 1)] },
];

test('an isolated face merges into the outside when its turn comes, and the last face stays', () => {
  const t = fixtureTgap(FACES, ['a']);
  assert.deepEqual(t.events.map((e) => [e.kind, e.step, e.loser, e.into]), [
    [EventKind.Merge, 1, I, 0],
    [EventKind.Merge, 2, L, W],
    [EventKind.Merge, 3, Z, W],
  ]);
  assert.deepEqual(t.meta.facesAlive, [4, 3, 2, 1]);
  const i = t.faces[I]!;
  assert.equal(i.stepHigh, 1);
  assert.equal(i.mergedInto, 0);
  assert.ok(faceEndZ(i, t.meta.steps) < t.meta.steps + 1, 'it ends before the top of the cube');
  assert.equal(resolveFace(t.faces, I, 1), 0, 'from step 1 its area is the outside');
  // Its edges end with it; no edge alive after step 1 has it, or the outside, on both sides.
  for (const e of t.edges) {
    const touches = [e.left, e.right].includes(I);
    if (touches) assert.ok(e.stepHigh <= 1, 'an edge of I outlives it');
  }
  // The file keeps it: the tGAP round-trips with the outside as the winner.
  const back = decodeTgap(encodeTgap(t), 'isolated.tgap');
  assert.equal(back.faces[I]!.mergedInto, 0);
  assert.deepEqual(back.events.map((e) => e.into), [0, W, W]);
});

for (const smooth of [false, true]) {
  test(`${smooth ? 'smooth' : 'classic'} cube: the isolated face shows until its merge, then the outside; a partition at every z`, async () => {
    const t = fixtureTgap(FACES, ['a']);
    const { surfaces: s, tgap, transitions } = buildSurfaces(t, { smooth });
    // The outside takes I as a winner takes a loser (upper face 0 over I's area), and in a
    // smooth cube what it has taken stays attached to it at every z of the transition.
    const intoOutside = transitions.filter((m) => m.into === 0);
    assert.deepEqual(intoOutside.map((m) => m.loser), [I]);
    const taken = mergeTriangles(s, intoOutside, tgap)[0]!;
    assert.ok(taken.length >= 2 && taken.every((i) => s.upper[i] === 0 && s.lower[i] === I), 'I\'s area turns to the outside');
    if (smooth) {
      assert.ok(intoOutside[0]!.tilted, 'the smooth cube tilts it');
      assert.ok(!mergeConnectivity(tgap, s, intoOutside).some(violates), 'what the outside takes stays attached to it');
    }
    // 130 x 40 pixels of 0.1 over the data's extent, [0,13] x [0,4].
    const view = fitView(t.meta.extent, 130, 40);
    const slice = await surfacesSlicer(s, s.xs, s.ys, (f) => tgap.faces[f]!.classIndex, view);
    const zTop = t.meta.steps + 1;
    const zEnd = faceEndZ(tgap.faces[I]!, t.meta.steps);
    assert.equal(zEnd, phaseZ(1, 0));
    // Pixel of a point of the data (x, y).
    const px = (x: number, y: number): number => {
      const c = Math.floor(((x - view.bbox[0]) / (view.bbox[2] - view.bbox[0])) * view.width);
      const r = Math.floor(((view.bbox[3] - y) / (view.bbox[3] - view.bbox[1])) * view.height);
      return r * view.width + c;
    };
    const inI = px(12.5, 0.5), inW = px(2, 2), between = px(11, 0.5);
    for (let k = 0; k <= 200; k++) {
      const z = (zTop * k) / 200 - 1e-9;
      if (z < 0) continue;
      const ids = slice(z).ids;
      // Every pixel shows a face alive at z, or the outside.
      for (let p = 0; p < ids.length; p++) {
        const f = ids[p]!;
        if (f === 0) continue;
        assert.ok(faceAliveAt(tgap.faces[f]!, z, t.meta.steps), `z ${z}: pixel ${p} shows face ${f}, not alive`);
      }
      assert.ok(ids[inW]! > 0, `z ${z}: W's area shows no face`);
      assert.equal(ids[between], 0, `z ${z}: between the two parts lies the outside`);
      // Under a smooth cube I's area goes as a ramp from its sides; its centre is gone at the merge.
      if (z < zEnd - 0.5 && !smooth) assert.equal(ids[inI], I, `z ${z}: I still shows`);
      if (z >= zEnd) assert.equal(ids[inI], 0, `z ${z}: I has left the map`);
    }
    assert.equal(slice(0).ids[inI], I, 'I shows at the floor');
  });
}
