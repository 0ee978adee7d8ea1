import test from 'node:test';
import assert from 'node:assert/strict';
import { removalHeights } from './removal-heights.js';

test('a chain of overlapping removals of rising phase: each knows how many follow above it', () => {
  const coords = Float64Array.of(
    0, 0, 4, 0, 0, 4, // 0, phase 1
    1, 1, 5, 1, 1, 5, // 1, phase 2: overlaps 0
    2, 2, 6, 2, 2, 6, // 2, phase 3: overlaps 1 (and 0)
    4, 0, 8, 0, 4, 4, // 3, phase 1: touches 0 at a corner; overlaps 1 and 2, drawn before it: none above it
    20, 20, 24, 20, 20, 24, // 4, phase 1: far from 0..3
    24, 20, 20, 24, 24, 24, // 5, phase 2: shares 4's long edge only (touches it)
  );
  assert.deepEqual([...removalHeights(coords, [1, 2, 3, 1, 1, 2])], [2, 1, 0, 0, 0, 0]);
});

test('only later removals of a higher phase count, and one removal has none', () => {
  const two = Float64Array.of(0, 0, 4, 0, 0, 4, 1, 1, 5, 1, 1, 5);
  assert.deepEqual([...removalHeights(two, [2, 1])], [0, 0], 'the later one has the lower phase');
  assert.deepEqual([...removalHeights(two, [1, 1])], [0, 0], 'the same phase: they do not overlap in the tGAP');
  assert.deepEqual([...removalHeights(two.subarray(0, 6), [1])], [0]);
});
