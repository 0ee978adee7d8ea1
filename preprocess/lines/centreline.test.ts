// Centrelines of hand-drawn road areas, checked against their true axes worked out by hand.
//
// Strip (6 wide, 100 long):        L (two arms 6 wide):           T of three faces:
//
//   +--------------------------+      +----+ (54..60, up to 40)    A = [-50,0] x [0,6]    B = [0,50] x [0,6]
//   |- - - - - axis y=3 - - - -|      |axis|  x = 57               +-----------A-----------+-----------B-----------+
//   +--------------------------+   +--+    |                                          |C|   C = [-3,3] x [-50,0]
//                                  |- - - -+  y = 3                                   | |
//                                  +-------+                     shared: A|B x = 0; A|C and B|C y = 0
//
// The end rule: a line stops where the area's end begins, at most one width before the end
// (for a square end, between its two corner spurs, which are pruned). The 1% bound is checked
// beyond one width from every end, port and corner.
import test from 'node:test';
import assert from 'node:assert/strict';
import { centreline, type Centreline, type Point } from './centreline.js';
import { chainMidpoint } from './chain-midpoint.js';
import { ringsBoundary } from './rings-boundary.js';

type XY = [number, number];
const W = 6;
const TOL = 0.01 * W;

/** Points along every path, at most `step` apart (vertices included). */
function samples(c: Centreline, step = 0.25): XY[] {
  const out: XY[] = [];
  for (const p of c.paths) {
    for (let i = 0; i + 2 < p.length; i += 2) {
      const ax = p[i]!, ay = p[i + 1]!, bx = p[i + 2]!, by = p[i + 3]!;
      const n = Math.max(1, Math.ceil(Math.hypot(bx - ax, by - ay) / step));
      for (let k = 0; k < n; k++) out.push([ax + ((bx - ax) * k) / n, ay + ((by - ay) * k) / n]);
    }
    out.push([p[p.length - 2]!, p[p.length - 1]!]);
  }
  return out;
}

/** Distance from p to the axis-parallel segment from a to b. */
function toAxisPiece(p: XY, a: XY, b: XY): number {
  const cx = Math.min(Math.max(p[0], Math.min(a[0], b[0])), Math.max(a[0], b[0]));
  const cy = Math.min(Math.max(p[1], Math.min(a[1], b[1])), Math.max(a[1], b[1]));
  return Math.hypot(p[0] - cx, p[1] - cy);
}

const vertices = (c: Centreline): XY[] => c.paths.flatMap((p) => Array.from({ length: p.length / 2 }, (_, i): XY => [p[2 * i]!, p[2 * i + 1]!]));
const hasVertex = (c: Centreline, q: Point): boolean => vertices(c).some(([x, y]) => x === q.x && y === q.y);

/** Ends of the paths: points that only one path piece touches. */
function pathEnds(c: Centreline): XY[] {
  const count = new Map<string, number>();
  for (const p of c.paths) {
    for (const k of [0, p.length - 2]) {
      const key = `${p[k]},${p[k + 1]}`;
      count.set(key, (count.get(key) ?? 0) + 1);
    }
  }
  return [...count].filter(([, n]) => n === 1).map(([k]) => k.split(',').map(Number) as XY);
}

test('a straight strip: one line on its mid-axis, from within one width of each end, no spur into the corners', () => {
  // Axis-aligned, and turned by 0.3 rad with national grid coordinates (rounding shows there).
  const a = 0.3, ox = 190000.5, oy = 450000.25;
  const cases = [
    { name: 'axis-aligned', at: (u: number, v: number): XY => [u, v] },
    { name: 'turned', at: (u: number, v: number): XY => [ox + u * Math.cos(a) - v * Math.sin(a), oy + u * Math.sin(a) + v * Math.cos(a)] },
  ];
  for (const { name, at } of cases) {
    const c = centreline(ringsBoundary([[at(0, 0), at(100, 0), at(100, W), at(0, W)]]), [], name);
    // Back to strip coordinates: u along, v across.
    const uv = ([x, y]: XY): XY => {
      const dx = x - at(0, 0)[0], dy = y - at(0, 0)[1];
      const ex = at(1, 0)[0] - at(0, 0)[0], ey = at(1, 0)[1] - at(0, 0)[1];
      return [dx * ex + dy * ey, -dx * ey + dy * ex];
    };
    assert.equal(c.paths.length, 1, `${name}: one line, no branch`);
    const pts = samples(c).map(uv);
    const us = pts.map(([u]) => u);
    assert.ok(Math.min(...us) <= W && Math.max(...us) >= 100 - W, `${name}: runs from ${Math.min(...us)} to ${Math.max(...us)}`);
    for (const [u, v] of pts) {
      if (u > W && u < 100 - W) assert.ok(Math.abs(v - W / 2) <= TOL, `${name}: (${u}, ${v}) is ${Math.abs(v - W / 2)} off the axis`);
      // A spur into a corner would come within a quarter width of a long side.
      assert.ok(Math.abs(v - W / 2) < W / 4, `${name}: (${u}, ${v}) heads for a side`);
    }
  }
});

test('an L-shaped strip: one connected polyline on the bent axis away from the corner', () => {
  const c = centreline(ringsBoundary([[[0, 0], [60, 0], [60, 40], [54, 40], [54, 6], [0, 6]]]), [], 'L');
  assert.equal(c.paths.length, 1);
  const axis: XY[] = [[0, 3], [57, 3], [57, 40]];
  const pts = samples(c);
  assert.ok(pts.some(([x]) => x <= W) && pts.some(([, y]) => y >= 40 - W), 'reaches within one width of both ends');
  for (const p of pts) {
    if (p[0] <= W || p[1] >= 40 - W || Math.hypot(p[0] - 57, p[1] - 3) <= 2 * W) continue; // ends and the corner
    const d = Math.min(toAxisPiece(p, axis[0]!, axis[1]!), toAxisPiece(p, axis[1]!, axis[2]!));
    assert.ok(d <= TOL, `(${p[0]}, ${p[1]}) is ${d} off the axis`);
  }
});

test('a T of three road faces: each finds the same port on a shared boundary and the lines meet there exactly', () => {
  const A: XY[] = [[-50, 0], [0, 0], [0, W], [-50, W]];
  const B: XY[] = [[0, 0], [50, 0], [50, W], [0, W]];
  const C: XY[] = [[-3, -50], [3, -50], [3, 0], [0, 0], [-3, 0]];
  // Each face walks the shared chain its own way round (its boundary counterclockwise).
  const port = (...chain: XY[]): Point => chainMidpoint(chain.flat());
  const ab = port([0, 0], [0, W]), ba = port([0, W], [0, 0]);
  const ac = port([-3, 0], [0, 0]), ca = port([0, 0], [-3, 0]);
  const bc = port([0, 0], [3, 0]), cb = port([3, 0], [0, 0]);
  assert.deepEqual([ab, ac, bc], [ba, ca, cb], 'the same point from either side');
  assert.deepEqual([ab, ac, bc], [{ x: 0, y: 3 }, { x: -1.5, y: 0 }, { x: 1.5, y: 0 }]);

  const a = centreline(ringsBoundary([A]), [ab, ac], 'A');
  const b = centreline(ringsBoundary([B]), [ba, bc], 'B');
  const c = centreline(ringsBoundary([C]), [ca, cb], 'C');
  for (const [l, name] of [[a, 'A'], [b, 'B'], [c, 'C']] as const) assert.ok(l.reached.every(Boolean), `${name} reaches its ports`);
  assert.ok(hasVertex(a, ab) && hasVertex(b, ab), 'A and B meet at their port');
  assert.ok(hasVertex(a, ac) && hasVertex(c, ac), 'A and C meet at their port');
  assert.ok(hasVertex(b, bc) && hasVertex(c, bc), 'B and C meet at their port');
  // Beyond one width from the junction and the dead ends, on the true axes.
  for (const p of samples(a)) if (p[0] > -50 + W && p[0] < -W) assert.ok(Math.abs(p[1] - 3) <= TOL, `A: (${p}) off y = 3`);
  for (const p of samples(b)) if (p[0] < 50 - W && p[0] > W) assert.ok(Math.abs(p[1] - 3) <= TOL, `B: (${p}) off y = 3`);
  for (const p of samples(c)) if (p[1] > -50 + W && p[1] < -W) assert.ok(Math.abs(p[0]) <= TOL, `C: (${p}) off x = 0`);
  assert.ok(samples(a).some(([x]) => x <= -50 + W) && samples(c).some(([, y]) => y <= -50 + W), 'the dead ends are reached within a width');
});

test('a junction square between two arms and a stem joins its three ports through its inside', () => {
  const J: XY[] = [[-3, 0], [3, 0], [3, W], [-3, W]];
  const ports: Point[] = [{ x: -3, y: 3 }, { x: 3, y: 3 }, { x: 0, y: 0 }];
  const j = centreline(ringsBoundary([J]), ports, 'J');
  assert.deepEqual(j.reached, [true, true, true]);
  for (const q of ports) assert.ok(hasVertex(j, q), `reaches (${q.x}, ${q.y})`);
  assert.deepEqual(pathEnds(j).sort(), ports.map((q): XY => [q.x, q.y]).sort(), 'ends at the ports only: no dead end');
  for (const [x, y] of vertices(j)) assert.ok(x >= -3 && x <= 3 && y >= 0 && y <= W, `(${x}, ${y}) inside`);
  // One connected piece: every path shares a point with another.
  const keys = j.paths.map((p) => new Set(Array.from({ length: p.length / 2 }, (_, i) => `${p[2 * i]},${p[2 * i + 1]}`)));
  for (let i = 1; i < keys.length; i++) assert.ok(keys.some((k, m) => m !== i && [...keys[i]!].some((v) => k.has(v))), `path ${i} joins the rest`);
  // An arm ends at its port exactly.
  const arm = centreline(ringsBoundary([[[-50, 0], [-3, 0], [-3, W], [-50, W]]]), [ports[0]!], 'west arm');
  assert.ok(pathEnds(arm).some(([x, y]) => x === -3 && y === 3));
  for (const p of samples(arm)) if (p[0] > -50 + W) assert.ok(Math.abs(p[1] - 3) <= TOL, `arm: (${p}) off y = 3`);
});

test('a side road longer than the road is wide keeps its branch; a lay-by shallower than that is pruned', () => {
  // A strip 100 x 6 with a side road 6 wide running 20 up from x = 47..53, and a lay-by 8 long
  // and 3 deep at x = 16..24: the branch runs up the side road's axis x = 50; no branch goes
  // into the lay-by (the line only shifts to the middle of the wider road there).
  const c = centreline(ringsBoundary([[[0, 0], [100, 0], [100, W], [53, W], [53, 26], [47, 26], [47, W], [24, W], [24, 9], [16, 9], [16, W], [0, W]]]), [], 'road with a side road');
  const pts = samples(c);
  assert.ok(pts.some(([x, y]) => Math.abs(x - 50) <= TOL && y >= 26 - W), 'the branch reaches within a width of the side road\'s end');
  for (const [x, y] of pts) {
    // Across the lay-by the road is 9 wide and its axis at y = 4.5; a spur would go deeper.
    if (y > 4.5 + TOL && x > 10 && x < 30) assert.fail(`(${x}, ${y}) heads into the lay-by`);
    if (y >= 2 * W && y <= 26 - W) assert.ok(Math.abs(x - 50) <= TOL, `(${x}, ${y}) off the side road's axis`);
  }
  assert.equal(pathEnds(c).length, 3, 'three ends: both ends of the road and the side road\'s');
});

test('a ring road (a polygon with a hole) collapses to a closed loop around the hole', () => {
  const c = centreline(ringsBoundary([[[0, 0], [60, 0], [60, 60], [0, 60]], [[W, W], [60 - W, W], [60 - W, 60 - W], [W, 60 - W]]]), [], 'ring');
  assert.equal(c.paths.length, 1);
  const p = c.paths[0]!;
  assert.deepEqual([p[0], p[1]], [p[p.length - 2], p[p.length - 1]], 'closed');
  // The true axis: the square loop 3 from the outer boundary; corners left out.
  const loop: XY[] = [[3, 3], [57, 3], [57, 57], [3, 57], [3, 3]];
  for (const q of samples(c)) {
    const d = Math.min(...loop.slice(1).map((b, i) => toAxisPiece(q, loop[i]!, b)));
    const nearCorner = loop.some(([x, y]) => Math.hypot(q[0] - x, q[1] - y) <= 2 * W);
    if (!nearCorner) assert.ok(d <= TOL, `(${q}) is ${d} off the loop`);
  }
  assert.ok(Math.abs(c.length - 4 * 54) < 2 * W, `length ${c.length}, the loop is ${4 * 54}`);
});

test('a degenerate polygon is refused with the face named', () => {
  assert.throws(() => centreline(ringsBoundary([[[0, 0], [10, 0], [20, 0]]]), [], 'face 7 (feature #3)'), /^Error: face 7 \(feature #3\): the boundary encloses no area/);
  assert.throws(() => centreline(ringsBoundary([[[0, 0], [10, 0], [10, 0], [0, 5]]]), [], 'face 8'), /^Error: face 8: segment 1 has no length, at \(10, 0\)/);
  assert.throws(() => centreline(ringsBoundary([[[0, 0], [10, 0]]]), [], 'face 9'), /^Error: face 9: a boundary needs at least 3 segments, got 2/);
  assert.throws(() => centreline({ xs: [0, 10, NaN], ys: [0, 0, 5], segs: [0, 1, 1, 2, 2, 0] }, [], 'face 10'), /face 10: segment 1 has a coordinate that is not a finite number/);
  // A bow tie with lobes of different size has an area but no inside the triangulation can close.
  assert.throws(() => centreline({ xs: [0, 20, 20, 0], ys: [0, 10, 0, 4], segs: [0, 1, 1, 2, 2, 3, 3, 0] }, [], 'face 11'), /face 11: /);
});

test('a port just outside the area is reached by a bridge, one far outside not at all', () => {
  // Mean width 600 / 106 = 5.66: a bridge reaches a quarter of it, 1.41.
  const strip = ringsBoundary([[[0, 0], [100, 0], [100, W], [0, W]]]);
  const c = centreline(strip, [{ x: 50, y: 20 }, { x: 50, y: 1 }, { x: 70, y: W + 1 }], 'strip');
  assert.deepEqual(c.reached, [false, true, true]);
  assert.deepEqual(c.bridged, [false, false, true]);
  assert.ok(hasVertex(c, { x: 50, y: 1 }), 'the port inside is on the line');
  assert.ok(hasVertex(c, { x: 70, y: W + 1 }), 'the bridged port is on the line');
  assert.ok(!hasVertex(c, { x: 50, y: 20 }));
  // Only the bridged port lies outside; the bridge leaves the strip near its foot (70, 6).
  for (const [x, y] of vertices(c)) if (!(x === 70 && y === W + 1)) assert.ok(y >= 0 && y <= W, `(${x}, ${y}) outside`);
  const toBridge = samples(c).filter(([, y]) => y > W);
  for (const [x] of toBridge) assert.ok(Math.abs(x - 70) < 1, `leaves the strip at x = ${x}, not by its foot`);
});

test('the same input gives the same line', () => {
  const rings: XY[][] = [[[0, 0], [60, 0], [60, 40], [54, 40], [54, 6], [0, 6]]];
  const ports: Point[] = [{ x: 0, y: 2 }, { x: 30, y: 3 }];
  assert.deepEqual(centreline(ringsBoundary(rings), ports, 'L'), centreline(ringsBoundary(rings), ports, 'L'));
});
