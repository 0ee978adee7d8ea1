// The ring repairs on hand-made rings of point ids.
import test from 'node:test';
import assert from 'node:assert/strict';
import { cleanRing, repairRings } from './ring-repairs.js';
import type { Ring, TopologyRepairs } from './topology-types.js';

const noRepairs = (): TopologyRepairs => ({ closedRings: 0, duplicatePoints: 0, reorientedRings: 0, tJunctions: 0, snappedPoints: 0, mergedPoints: 0, spikes: 0, slivers: 0 });

test('cleanRing drops repeated points and zero-width spikes, also across the closing point', () => {
  const cases: { ids: number[]; out: number[]; duplicatePoints: number; spikes: number }[] = [
    { ids: [1, 1, 2, 3], out: [1, 2, 3], duplicatePoints: 1, spikes: 0 },
    // 2 -> 3 -> 2: the tip 3 goes, and the second 2 with it.
    { ids: [1, 2, 3, 2, 4], out: [1, 2, 4], duplicatePoints: 0, spikes: 1 },
    { ids: [1, 2, 3, 1], out: [1, 2, 3], duplicatePoints: 1, spikes: 0 },
    // Read around: ... 4 -> 1 -> 2 -> 1 -> 3: the spike's tip 2 is the first point.
    { ids: [2, 1, 3, 4, 1], out: [1, 3, 4], duplicatePoints: 0, spikes: 1 },
    // ... 3 -> 4 -> 1 -> 4 -> 2 ...: the tip 1 is the first point, 4 its base on both sides.
    { ids: [1, 4, 2, 3, 4], out: [4, 2, 3], duplicatePoints: 0, spikes: 1 },
  ];
  for (const c of cases) {
    const r = noRepairs();
    assert.deepEqual([...cleanRing(Int32Array.from(c.ids), r)], c.out, `ring ${c.ids.join(' ')}`);
    assert.equal(r.duplicatePoints, c.duplicatePoints, `duplicates in ${c.ids.join(' ')}`);
    assert.equal(r.spikes, c.spikes, `spikes in ${c.ids.join(' ')}`);
  }
  const clean = Int32Array.of(1, 2, 3);
  assert.equal(cleanRing(clean, noRepairs()), clean, 'a clean ring is kept as it is');
});

// Two squares side by side; the right one has a point (2,1) on the left one's side, and the
// left one has (2.0004,1.9996), within the precision 0.001 of the right one's corner (2,2).
//   0 (0,0)  1 (2,0)  2 (2,2)  3 (0,2)  4 (4,0)  5 (4,2)  6 (2,1)  7 (2.0004,1.9996)
const xs = Float64Array.of(0, 2, 2, 0, 4, 4, 2, 2.0004);
const ys = Float64Array.of(0, 0, 2, 2, 0, 2, 1, 1.9996);

test('repairRings merges points closer than the precision and puts T-junctions into the segment they lie on', () => {
  const rings: Ring[] = [
    { face: 1, outer: true, ids: Int32Array.of(0, 1, 7, 3), part: 0, ring: 0 },
    { face: 2, outer: true, ids: Int32Array.of(1, 4, 5, 2, 6), part: 0, ring: 0 },
  ];
  const r = noRepairs();
  const out = repairRings(rings, xs, ys, 0.001, r);
  // 7 becomes 2 (the lower id of the two); 6 goes between 1 and 2 on the left square's side.
  assert.deepEqual([...out[0]!.ids], [0, 1, 6, 2, 3]);
  assert.deepEqual([...out[1]!.ids], [1, 4, 5, 2, 6]);
  assert.equal(r.mergedPoints, 1);
  assert.equal(r.tJunctions, 1);
});

test('with precision 0 nothing is merged, and only points exactly on a segment are T-junctions', () => {
  const rings: Ring[] = [
    { face: 1, outer: true, ids: Int32Array.of(0, 1, 2, 3), part: 0, ring: 0 },
    { face: 2, outer: true, ids: Int32Array.of(1, 4, 5, 7, 2, 6), part: 0, ring: 0 },
  ];
  const r = noRepairs();
  const out = repairRings(rings, xs, ys, 0, r);
  assert.deepEqual([...out[0]!.ids], [0, 1, 6, 2, 3]);
  assert.equal(r.mergedPoints, 0);
  assert.equal(r.tJunctions, 1);
});
