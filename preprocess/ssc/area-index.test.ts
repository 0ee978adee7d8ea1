import test from 'node:test';
import assert from 'node:assert/strict';
import { AreaIndex } from './area-index.js';

// Four triangles, counterclockwise: the unit square [0,1]x[0,1] (two triangles), the triangle
// (1,0) (2,0) (1,1) to its right and (0,1) (1,1) (0,2) above it.
//   (0,2)
//     | \
//   (0,1)-(1,1)
//     |  /  | \
//   (0,0)-(1,0)-(2,0)
const xs = [0, 1, 2, 0, 1, 0];
const ys = [0, 0, 0, 1, 1, 2];

test('AreaIndex: inside, on an edge, in the box but outside the triangles, outside the box', () => {
  const area = new AreaIndex([0, 1, 3, 1, 4, 3, 1, 2, 4, 3, 4, 5], xs, ys);
  assert.equal(area.contains(0.25, 0.25), true);
  assert.equal(area.contains(1.2, 0.5), true, 'the triangle (1,0) (2,0) (1,1)');
  assert.equal(area.contains(0.5, 0.5), true, 'on the diagonal shared by two triangles');
  assert.equal(area.contains(2, 0), true, 'a corner');
  assert.equal(area.contains(1.8, 0.8), false, 'in the box, right of the hypotenuse (2,0)-(1,1)');
  assert.equal(area.contains(0.8, 1.8), false, 'in the box, above (1,1)-(0,2)');
  assert.equal(area.contains(-0.1, 0.5), false);
  assert.equal(area.contains(1, 3), false);
});

test('AreaIndex: no triangles hold nothing', () => {
  assert.equal(new AreaIndex([], xs, ys).contains(0, 0), false);
});

test('AreaIndex: an area grown by more triangles holds their points too, and its box grows with them', () => {
  const area = new AreaIndex([0, 1, 3, 1, 4, 3], xs, ys);
  assert.equal(area.contains(1.2, 0.5), false);
  assert.equal(area.contains(0.2, 1.5), false);
  area.add([1, 2, 4, 3, 4, 5], xs, ys);
  assert.equal(area.contains(1.2, 0.5), true, 'the triangle (1,0) (2,0) (1,1)');
  assert.equal(area.contains(0.2, 1.5), true, 'the triangle (0,1) (1,1) (0,2), above the first box');
  assert.equal(area.contains(0.25, 0.25), true, 'the square still');
  assert.equal(area.contains(1.8, 0.8), false);
});

test('AreaIndex: a triangle overlaps the area when their insides meet, though neither its centre nor a corner lies in it', () => {
  const square = new AreaIndex([0, 1, 3, 1, 4, 3], xs, ys);
  // A long thin triangle across the square, its corners and centre outside it.
  const across = [-5, 0.4, 6, 0.4, 6, 0.6];
  assert.equal(square.contains((-5 + 6 + 6) / 3, (0.4 + 0.4 + 0.6) / 3), false, 'its centre is outside');
  assert.equal(square.overlaps(across), true);
  assert.equal(square.overlaps([1, 0, 2, 0, 1, 1]), false, 'the triangle to its right touches along an edge only');
  assert.equal(square.overlaps([1, 1, 2, 1, 1, 2]), false, 'a corner only');
  assert.equal(square.overlaps([0.9, 0.1, 3, 0.1, 0.9, 0.2]), true, 'reaching in by a tenth');
  assert.equal(square.overlaps([5, 5, 6, 5, 5, 6]), false, 'outside the box');
  assert.equal(new AreaIndex([], xs, ys).overlaps(across), false, 'no triangles');
});
