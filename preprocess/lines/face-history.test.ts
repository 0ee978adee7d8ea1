// A face's boundary at a state through FaceHistory (the faces merged into it, their edges)
// against a scan of every edge version of the tGAP, on a hand-drawn partition generalized to
// the end: every face at every state of its life.
import test from 'node:test';
import assert from 'node:assert/strict';
import { resolveFace } from '../../format/tgap-model.js';
import { fixtureStyle, fixtureTgap, rect, type FixtureFace } from '../../testing/planar-fixtures.js';
import { FaceHistory } from './face-history.js';

// A road between two fields, a pond in one of them and a shed beside the road: merges,
// re-emits and a split.
const FACES: FixtureFace[] = [
  { cls: 'field', rings: [rect(0, 0, 40, 20), rect(5, 5, 10, 10)] },
  { cls: 'road', rings: [rect(0, 20, 40, 24)] },
  { cls: 'field', rings: [[[0, 24], [40, 24], [40, 50], [0, 50], [0, 30], [6, 30], [6, 24 + 0.5], [0, 24 + 0.5]]] },
  { cls: 'pond', rings: [rect(5, 5, 10, 10)] },
  { cls: 'shed', rings: [[[0, 24], [0, 24 + 0.5], [6, 24 + 0.5], [6, 30], [0, 30]]] },
];

// Four squares: X (least important) merges into W, and its edge with Y lives on unchanged
// (both its ends keep three edges), still naming X: W's boundary takes it from X.
//   W | X        W = [0,10] x [5,10]   X = [10,20] x [5,10]
//   --+--        Z = [0,10] x [0,5]    Y = [10,20] x [0,5]
//   Z | Y
const GRID: FixtureFace[] = [
  { cls: 'a', rings: [rect(0, 5, 10, 10)] },
  { cls: 'x', rings: [rect(10, 5, 20, 10)] },
  { cls: 'b', rings: [rect(0, 0, 10, 5)] },
  { cls: 'b', rings: [rect(10, 0, 20, 5)] },
];

test('the edges around a face at a state are those whose sides resolve to it then', () => {
  const cases = [
    fixtureTgap(FACES, ['field', 'road', 'pond', 'shed'], fixtureStyle([{ key: 'field', weight: 3 }, { key: 'road', linear: true }, { key: 'pond' }, { key: 'shed' }])),
    fixtureTgap(GRID, ['a', 'x', 'b'], fixtureStyle([{ key: 'a', weight: 4 }, { key: 'x', weight: 0.1 }, { key: 'b', weight: 4 }], { x: { b: 0.2 } })),
  ];
  // The grid's first event: X into W, keeping its edge with Y.
  const grid = cases[1]!;
  assert.deepEqual([grid.events[0]!.loser, grid.events[0]!.into], [2, 1]);
  assert.ok(grid.edges.some((e) => e.stepLow === 0 && e.stepHigh > 1 && [e.left, e.right].sort().join() === '2,4'), 'X|Y lives on');
  for (const tgap of cases) {
    const history = new FaceHistory(tgap);
    let checked = 0;
    tgap.faces.forEach((face, f) => {
      if (f === 0) return;
      for (let s = face.stepLow; s < Math.min(face.stepHigh, tgap.meta.steps + 1); s++) {
        const expected: string[] = [];
        tgap.edges.forEach((e, i) => {
          if (e.stepLow > s || e.stepHigh <= s) return;
          const l = resolveFace(tgap.faces, e.left, s), r = resolveFace(tgap.faces, e.right, s);
          if (l === f && r !== f) expected.push(`${i} fwd ${r}`);
          if (r === f && l !== f) expected.push(`${i} back ${l}`);
        });
        const got = history.boundaryAt(f, s).map((x) => `${x.edge} ${x.forward ? 'fwd' : 'back'} ${x.other}`);
        assert.deepEqual(got, expected, `face ${f} at state ${s}`);
        assert.ok(got.length > 0, `face ${f} at state ${s} has a boundary`);
        checked++;
      }
    });
    assert.ok(checked >= tgap.faces.length - 1, `${checked} face states`);
  }
});
