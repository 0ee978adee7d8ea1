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

// A's outer ring 0-1-2-3 has a sloped side 2 -> 3 from (30,20) to (0,29.123); points 5 and 6
// lie 0.076 and 0.092 mm below it, within the precision 0.001.
//   0 (0,0)  1 (30,0)  2 (30,20)  3 (0,29.123)  4 (10,10)  5 (14.005,24.864)  6 (16.001,24.257)  7 (20,10)
const sx = Float64Array.of(0, 30, 30, 0, 10, 14.005, 16.001, 20);
const sy = Float64Array.of(0, 0, 20, 29.123, 10, 24.864, 24.257, 10);

test('a vertex near a side is put into it when a neighbour has it, not when the side\'s own face has it (its hole)', () => {
  const outer = (): Ring => ({ face: 1, outer: true, ids: Int32Array.of(0, 1, 2, 3), part: 0, ring: 0 });
  // 4-5-6-7 as A's hole (clockwise), filled by B: moving 5 and 6 onto A's side would fold A's
  // outer ring onto its hole.
  const own = noRepairs();
  const hole = repairRings([outer(), { face: 1, outer: false, ids: Int32Array.of(4, 5, 6, 7), part: 0, ring: 1 }, { face: 2, outer: true, ids: Int32Array.of(7, 6, 5, 4), part: 0, ring: 0 }], sx, sy, 0.001, own);
  assert.deepEqual(hole.map((r) => [...r.ids]), [[0, 1, 2, 3], [4, 5, 6, 7], [7, 6, 5, 4]]);
  assert.equal(own.tJunctions, 0);
  // The same points as a neighbour's corners (B beside A, not in its hole): T-junctions, in
  // order along 2 -> 3 (x falling).
  const other = noRepairs();
  const side = repairRings([outer(), { face: 2, outer: true, ids: Int32Array.of(7, 6, 5, 4), part: 0, ring: 0 }], sx, sy, 0.001, other);
  assert.deepEqual([...side[0]!.ids], [0, 1, 2, 6, 5, 3]);
  assert.equal(other.tJunctions, 2);
});
