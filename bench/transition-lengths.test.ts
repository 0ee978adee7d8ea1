import assert from 'node:assert/strict';
import { test } from 'node:test';
import type { ScaleInfo } from '../format/scale.js';
import { EventKind } from '../format/tgap-model.js';
import { classicTransitions, scaleRatios, smoothTransitions, transitionLengths } from './transition-lengths.js';

// S(z) = 1000 sqrt(100 / alive(z)), alive linear between the knots: S(0) = 1000, S(1) = 2000,
// S(2) = 5000; alive(0.5) = 62.5.
const info: ScaleInfo = { baseScale: 1000, baseFaces: 100, scaleTable: [[0, 100], [1, 25], [2, 4]], zMax: 2 };

test('a classic merge or split lasts from phase 0 to the last removal phase of its step; re-draws are no events', () => {
  const ts = classicTransitions([
    { kind: EventKind.Merge, step: 1 },
    { kind: EventKind.Reemit, step: 2 },
    { kind: EventKind.Split, step: 3 },
  ]);
  assert.equal(ts.length, 2);
  // z(k, phase) = k - 1 + (phase + 1) / 9: phases 0 and 6.
  assert.ok(Math.abs(ts[0]!.zStart - 1 / 9) < 1e-12 && Math.abs(ts[0]!.zEnd - 7 / 9) < 1e-12);
  assert.ok(Math.abs(ts[1]!.zStart - (2 + 1 / 9)) < 1e-12 && Math.abs(ts[1]!.zEnd - (2 + 7 / 9)) < 1e-12);
});

test('scaleRatios gives S(end)/S(start) with the map\'s scale of z', () => {
  const r = scaleRatios([{ zStart: 0, zEnd: 1 }, { zStart: 1, zEnd: 2 }, { zStart: 0, zEnd: 2 }, { zStart: 0.5, zEnd: 1 }], info);
  const want = [2, 2.5, 5, Math.sqrt(62.5 / 25)];
  r.forEach((x, i) => assert.ok(Math.abs(x - want[i]!) < 1e-12, `ratio ${i}: ${x}, want ${want[i]}`));
});

test('a classic event of step 1 from 90 faces to none: alive 80 to 20 over its phases, x2 in scale', () => {
  // alive(1/9) = 80, alive(7/9) = 20: S ratio sqrt(80 / 20) = 2, one default zoom step of 10 frames.
  const steep: ScaleInfo = { baseScale: 1000, baseFaces: 90, scaleTable: [[0, 90], [1, 0]], zMax: 1 };
  const [r] = scaleRatios(classicTransitions([{ kind: EventKind.Merge, step: 1 }]), steep);
  assert.ok(r !== undefined && Math.abs(r - 2) < 1e-12);
  assert.ok(Math.abs(transitionLengths([r]).framesAtMedian - 10) < 1e-9);
});

test('transitionLengths: median, nearest-rank 10th percentile, frames of an x2 step at the median', () => {
  // Sorted 1.5, 2, 2, 4, 8: median 2; the 10th percentile is the first (ceil(0.5) = 1st) value.
  assert.deepEqual(transitionLengths([4, 2, 1.5, 8, 2]), { events: 5, median: 2, p10: 1.5, framesAtMedian: 10 });
  // Sorted 1.1, 1.25, 1.25, 1.5: median 1.25, 10 log2(1.25) = 3.22 frames; p10 the 1st value.
  const t = transitionLengths([1.25, 1.1, 1.5, 1.25]);
  assert.equal(t.median, 1.25);
  assert.equal(t.p10, 1.1);
  assert.ok(Math.abs(t.framesAtMedian - 3.219280948873623) < 1e-12);
  const none = transitionLengths([]);
  assert.equal(none.events, 0);
  assert.ok(Number.isNaN(none.median) && Number.isNaN(none.framesAtMedian));
});

test('a smooth cube\'s tilted merge lasts from its start to the merge; flat merges and splits as in the classic cube', () => {
  const events = [
    { kind: EventKind.Merge, step: 2, loser: 5 },
    { kind: EventKind.Split, step: 3, loser: 6 },
    { kind: EventKind.Merge, step: 4, loser: 7 },
    { kind: EventKind.Reemit, step: 4, loser: 8 },
  ];
  const merges = [
    { step: 2, loser: 5, into: 1, zStart: 0.25, zMerge: 1 + 1 / 9, tilted: true, first: 0, end: 2 },
    { step: 4, loser: 7, into: 1, zStart: 3 + 1 / 9, zMerge: 3 + 1 / 9, tilted: false, first: 2, end: 4 },
  ];
  const ts = smoothTransitions(events, merges, [{ step: 3, loser: 6, zStart: 2 + 1 / 9, zSplit: 2 + 1 / 9 }]);
  assert.deepEqual(ts[0], { zStart: 0.25, zEnd: 1 + 1 / 9 });
  // z(k, phase) = k - 1 + (phase + 1) / 9: phases 0 and 6 of steps 3 and 4.
  const classic = [[2 + 1 / 9, 2 + 7 / 9], [3 + 1 / 9, 3 + 7 / 9]];
  assert.equal(ts.length, 3);
  ts.slice(1).forEach((t, i) => assert.ok(Math.abs(t.zStart - classic[i]![0]!) < 1e-12 && Math.abs(t.zEnd - classic[i]![1]!) < 1e-12, `event ${i + 1}: ${t.zStart}..${t.zEnd}`));
  // With S(z) of the test's scale table, the tilted merge 0.25 -> 10/9 spans more scale than a classic step 2 event.
  const [smoothRatio] = scaleRatios([ts[0]], info);
  const [classicRatio] = scaleRatios(classicTransitions([events[0]!]), info);
  assert.ok(smoothRatio! > classicRatio!, `${smoothRatio} vs ${classicRatio}`);
  assert.throws(() => smoothTransitions(events, [{ ...merges[0]!, step: 3 }], []), /merge of face 5 is at step 2, its transition at step 3/);
});

test('a smooth split lasts from where its first part starts to the split', () => {
  const events = [{ kind: EventKind.Split, step: 3, loser: 6 }];
  assert.deepEqual(smoothTransitions(events, [], [{ step: 3, loser: 6, zStart: 1.5, zSplit: 2 + 1 / 9 }]), [{ zStart: 1.5, zEnd: 2 + 1 / 9 }]);
  assert.throws(() => smoothTransitions(events, [], [{ step: 4, loser: 6, zStart: 1.5, zSplit: 3 + 1 / 9 }]), /split of face 6 is at step 3, its transition at step 4/);
});
