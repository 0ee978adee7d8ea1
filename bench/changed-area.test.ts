import assert from 'node:assert/strict';
import { test } from 'node:test';
import { fitView } from '../preprocess/map/rasterize.js';
import { CpuSlicer } from '../preprocess/ssc/cpu-slicer.js';
import { Surfaces } from '../preprocess/ssc/surfaces.js';
import { changedArea, shareBelow } from './changed-area.js';
import { changeShare, classChange } from './class-change.js';

// The unit square: face 1 (class 0) below the diagonal, face 2 (class 1) above it. Face 2
// merges into face 1 on a tilted surface z = 1 + x + y; at z = 4 both become face 3 (class 0,
// no change seen); at z = 5 the lower half becomes face 4 (class 1).
const CLASS = [0, 0, 1, 0, 1];
function scene(): Surfaces {
  const s = new Surfaces(Float64Array.from([0, 1, 1, 0]), Float64Array.from([0, 0, 1, 1]));
  s.add(0, 1, 2, 0, 1, 0);
  s.add(0, 2, 3, 0, 2, 0);
  s.addTilted(0, 2, 3, 1, 3, 2, 1, 2, 'm');
  s.add(0, 1, 2, 4, 3, 1);
  s.add(0, 2, 3, 4, 3, 1);
  s.add(0, 1, 2, 5, 4, 3);
  return s;
}
const ZS = [0.5, 1.5, 2, 2.5, 3.5, 4.5, 5.5];

test('shareBelow is the share of a linearly tilted triangle below a slice', () => {
  // z = x on the triangle (0,0) (1,0) (0,1): below x = 0.5 lies 0.375 of its 0.5.
  assert.equal(shareBelow(0, 1, 0, 0.5), 0.75);
  assert.equal(shareBelow(1, 0, 0, 0.5), 0.75);
  assert.equal(shareBelow(0, 1, 0, 0), 0);
  assert.equal(shareBelow(0, 1, 0, 1), 1);
  // Flat: all or nothing.
  assert.equal(shareBelow(2, 2, 2, 1.999), 0);
  assert.equal(shareBelow(2, 2, 2, 2.001), 1);
});

test('changedArea gives each frame the area whose class changes, by triangle', () => {
  const c = changedArea(scene(), (f) => CLASS[f]!, ZS);
  assert.equal(c.domain, 1);
  // The ramp over {0 <= x <= y <= 1}: below x + y = 0.5 lies 1/16, below x + y = 1 a quarter,
  // below x + y = 1.5 all but 1/16; the same-class change at 4 counts nothing; at 5 half the square.
  const expected = [0, 1 / 16, 3 / 16, 3 / 16, 1 / 16, 0, 0.5];
  c.perFrame.forEach((a, f) => assert.ok(Math.abs(a - expected[f]!) < 1e-12, `frame ${f}: ${a}`));
  assert.deepEqual([...c.perTriangle.keys()], [2, 5]);
  assert.equal(c.perTriangle.get(5)!.get(6), 0.5);
});

test('changedArea agrees with the CPU slicer frame by frame', () => {
  const s = scene();
  const view = fitView([0, 0, 1, 1], 300, 300);
  const frames = ZS.map((z) => {
    const sl = new CpuSlicer(view, () => z);
    for (let t = 0; t < s.count; t++) {
      const [a, b, c] = [s.v[3 * t]!, s.v[3 * t + 1]!, s.v[3 * t + 2]!];
      sl.triangle(s.xs[a]!, s.ys[a]!, s.z[3 * t]!, s.xs[b]!, s.ys[b]!, s.z[3 * t + 1]!, s.xs[c]!, s.ys[c]!, s.z[3 * t + 2]!, s.upper[t]!, s.lower[t]!, CLASS[s.upper[t]!]);
    }
    return sl;
  });
  const c = changedArea(s, (f) => CLASS[f]!, ZS);
  for (let f = 1; f < ZS.length; f++) {
    const sliced = changeShare(classChange(frames[f - 1]!, frames[f]!));
    assert.ok(Math.abs(sliced - c.perFrame[f]! / c.domain) < 0.01, `frame ${f}: sliced ${sliced}, analytic ${c.perFrame[f]! / c.domain}`);
  }
});
