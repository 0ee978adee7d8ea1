import test from 'node:test';
import assert from 'node:assert/strict';
import { trianglesOverlap } from './triangles-overlap.js';

const T = [0, 0, 4, 0, 0, 4];

test('triangles sharing an edge or a vertex only touch', () => {
  assert.equal(trianglesOverlap(T, [4, 0, 4, 4, 0, 4]), false); // across the hypotenuse
  assert.equal(trianglesOverlap(T, [4, 0, 8, 0, 6, 3]), false); // at vertex (4, 0)
  assert.equal(trianglesOverlap(T, [0, 0, -4, 0, 0, -4]), false);
});

test('overlapping, nested and crossing triangles overlap, in either order', () => {
  const cases = [
    [1, 1, 2, 1, 1, 2], // inside
    [-1, -1, 10, -1, -1, 10], // around
    [1, -1, 3, -1, 2, 3], // through the bottom edge
    [2, -1, 6, 3, -2, 3], // a star of David's other half
  ];
  for (const c of cases) {
    assert.equal(trianglesOverlap(T, c), true, `${c}`);
    assert.equal(trianglesOverlap(c, T), true, `${c} reversed`);
  }
});

test('apart, or separated only by an axis of the second triangle', () => {
  assert.equal(trianglesOverlap(T, [5, 5, 6, 5, 5, 6]), false);
  // Beyond the hypotenuse x + y = 4: only T's hypotenuse normal separates them.
  assert.equal(trianglesOverlap(T, [3, 3, 5, 2.5, 2.5, 5]), false);
  // Below T's bottom edge but within its x range, pointing up at it without reaching.
  assert.equal(trianglesOverlap(T, [1, -3, 3, -3, 2, -0.5]), false);
});

test('orientation does not matter', () => {
  assert.equal(trianglesOverlap([0, 0, 0, 4, 4, 0], [1, 1, 1, 2, 2, 1]), true);
  assert.equal(trianglesOverlap([0, 0, 0, 4, 4, 0], [4, 0, 0, 4, 4, 4]), false);
});
