// Rings that cross themselves, small (every pair compared) and large (the sweep along x).
import test from 'node:test';
import assert from 'node:assert/strict';
import { ProblemList } from '../io/problems.js';
import { Refusal } from './refusal.js';
import { checkRingSelfCrossings } from './ring-self-crossings.js';

/** The problems found in one ring of face 1: points, and the ring as their ids (default: each point once, in order). */
function problemsOf(points: [number, number][], ids = Int32Array.from(points.keys())): ProblemList {
  const xs = Float64Array.from(points.map((p) => p[0])), ys = Float64Array.from(points.map((p) => p[1]));
  const problems = new ProblemList('t.geojson');
  const refusal = new Refusal([{ ref: { index: 0, id: 'r' }, properties: {}, polygons: [] }], problems);
  checkRingSelfCrossings([{ face: 1, outer: true, ids, part: 0, ring: 0 }], xs, ys, refusal);
  return problems;
}

/** n points on a circle of radius 100, counterclockwise. */
const circle = (n: number): [number, number][] => Array.from({ length: n }, (_, i) => [100 * Math.cos((2 * Math.PI * i) / n), 100 * Math.sin((2 * Math.PI * i) / n)]);

test('a simple ring passes, small or large', () => {
  assert.equal(problemsOf(circle(8)).count, 0);
  assert.equal(problemsOf(circle(500)).count, 0);
  // Touching itself at a shared point (a pinch) is not a crossing.
  assert.equal(problemsOf([[0, 0], [10, 0], [5, 5], [10, 10], [0, 10]], Int32Array.of(0, 1, 2, 3, 4, 2)).count, 0);
});

test('a bow-tie is named at its crossing', () => {
  const p = problemsOf([[0, 0], [10, 10], [10, 0], [0, 10]]);
  assert.equal(p.count, 1);
  assert.deepEqual(p.items[0], { kind: 'selfIntersection', message: 'is self-intersecting: its outer ring crosses itself', feature: { index: 0, id: 'r' }, location: [5, 5] });
});

test('a large ring with two points swapped crosses itself between them', () => {
  // Points 100 and 101 of 500 swapped: segments 99-101 and 100-102 cross near the circle.
  const pts = circle(500);
  [pts[100], pts[101]] = [pts[101]!, pts[100]!];
  const p = problemsOf(pts);
  assert.equal(p.count, 1);
  const [x, y] = p.items[0]!.location!;
  assert.ok(Math.abs(Math.hypot(x, y) - 100) < 0.1, `at ${x}, ${y}`);
  const mid = (2 * Math.PI * 100.5) / 500;
  assert.ok(Math.hypot(x - 100 * Math.cos(mid), y - 100 * Math.sin(mid)) < 2, 'between the swapped points');
});
