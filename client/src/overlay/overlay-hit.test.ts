// Hit testing of overlay features on hand-made geometry: lines within half their width plus
// the tolerance, points within their radius plus it, polygons inside but not in their holes,
// and the topmost feature first.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import type { Parts, XY } from './geojson-read.js';
import { HitIndex, type HitReach } from './overlay-hit.js';

const parts = (p: Partial<Parts>): Parts => ({ points: [], lines: [], polygons: [], ...p });
const reach = (r: Partial<HitReach> = {}): HitReach => ({ resolution: 1, lineHalfWidth: 2, circleRadius: 5, tolerance: 3, outlines: false, ...r });

describe('overlay hit testing', () => {
  const line = parts({ lines: [[[0, 0], [100, 0], [100, 100]]] });

  test('a line is hit within half its width plus the tolerance, in CSS px at the resolution', () => {
    const h = new HitIndex([line]);
    assert.deepEqual(h.at([50, 4.9], reach()), [0]);
    assert.deepEqual(h.at([50, -5.1], reach()), []);
    assert.deepEqual(h.at([104.9, 50], reach()), [0], 'the second segment');
    assert.deepEqual(h.at([104, 104], reach()), [], 'beyond the last position, more than 5 away');
    assert.deepEqual(h.at([50, 9.9], reach({ resolution: 2 })), [0], '5 px are 10 ground units at 2 units a pixel');
    assert.deepEqual(h.at([50, 10.1], reach({ resolution: 2 })), []);
  });

  test('a point is hit within its radius plus the tolerance', () => {
    const h = new HitIndex([parts({ points: [[10, 10]] })]);
    assert.deepEqual(h.at([10 + 7.9, 10], reach()), [0]);
    assert.deepEqual(h.at([10 + 8.1 / Math.SQRT2, 10 + 8.1 / Math.SQRT2], reach()), []);
  });

  test('a polygon is hit inside its outer ring but not in its hole; its outline only when drawn', () => {
    const outer: XY[] = [[0, 0], [20, 0], [20, 20], [0, 20]];
    const hole: XY[] = [[4, 4], [16, 4], [16, 16], [4, 16]];
    const h = new HitIndex([parts({ polygons: [[outer, hole]] })]);
    assert.deepEqual(h.at([1, 1], reach()), [0]);
    assert.deepEqual(h.at([10, 10], reach()), [], 'in the hole');
    assert.deepEqual(h.at([10, 10], reach({ outlines: true })), [], 'in the hole, 6 from its edge: beyond the outline');
    assert.deepEqual(h.at([21, 5], reach()), [], 'outside, no outline');
    assert.deepEqual(h.at([24.9, 5], reach({ outlines: true })), [0], 'near the outline (2 + 3 px reach)');
    assert.deepEqual(h.at([14, 10], reach({ outlines: true })), [0], 'in the hole, near its edge');
  });

  test('the topmost feature comes first: circles over lines over fills, later features over earlier', () => {
    const square: XY[] = [[0, 0], [10, 0], [10, 10], [0, 10]];
    const h = new HitIndex([parts({ points: [[5, 5]] }), parts({ polygons: [[square]] }), parts({ polygons: [[square]] }), parts({ lines: [[[0, 5], [10, 5]]] })]);
    const small = reach({ circleRadius: 1, lineHalfWidth: 0.5 });
    assert.deepEqual(h.at([5, 5], small), [0, 3, 2, 1]);
    assert.deepEqual(h.at([1, 1], small), [2, 1], 'only the fills, 4 from the circle and the line');
  });

  test('lines and points of size 0 are not drawn, and not hit', () => {
    const h = new HitIndex([parts({ points: [[0, 0]] }), parts({ lines: [[[0, 0], [5, 0]]] })]);
    assert.deepEqual(h.at([1, 0], reach({ circleRadius: 0 })), [1]);
    assert.deepEqual(h.at([1, 0], reach({ lineHalfWidth: 0 })), [0]);
  });

  test('a feature with several parts is listed once', () => {
    const h = new HitIndex([parts({ points: [[0, 0], [1, 0]], lines: [[[0, 0], [5, 0]]] })]);
    assert.deepEqual(h.at([0.5, 0], reach()), [0]);
  });
});
