// Vertices glide onto their neighbours' chord before simplification takes them: on a zigzag
// whose vertices leave one after another, the line drawn just before each leave z lies on the
// line drawn after it (no jump), and before each glide the vertices stand where they are stored.
import assert from 'node:assert/strict';
import test from 'node:test';
import { linePathsAtZ, type LineRecord } from './line-record.js';
import { glideShare, glidingSegments, lineGlides, segmentAt } from './line-glide.js';
import type { ScaleInfo } from './scale.js';

/** Scales doubling each step (1:1,000 at z 0): half a zoom level before step L is L - 1/3. */
const info: ScaleInfo = { baseScale: 1000, baseFaces: 4 ** 10, zMax: 10, scaleTable: Array.from({ length: 11 }, (_, z): [number, number] => [z, 4 ** (10 - z)]) };

const zig: LineRecord = {
  classIndex: 0, rule: 0, feature: 0, zStart: 1, zEnd: 9,
  paths: [Float64Array.from({ length: 14 }, (_, i) => (i % 2 === 0 ? i : (i % 4) * 3))],
  leaveZ: [Float64Array.of(9, 4, 2, 6, 3, 5, 9)],
};

/** The segments drawn at z, ends where they are at z. */
const drawnAt = (z: number): number[][] => glidingSegments(zig, info).filter((s) => s.z0 <= z && z < s.z1).map((s) => segmentAt(s, z));

/** Largest distance from a point of polyline set `a` (sampled finely) to the nearest segment of `b`. */
function farthest(a: number[][], b: number[][]): number {
  let worst = 0;
  for (const [ax, ay, bx, by] of a) {
    for (let k = 0; k <= 100; k++) {
      const x = ax! + ((bx! - ax!) * k) / 100, y = ay! + ((by! - ay!) * k) / 100;
      let d = Infinity;
      for (const [cx, cy, dx, dy] of b) {
        const ex = dx! - cx!, ey = dy! - cy!, l2 = ex * ex + ey * ey;
        const t = l2 > 0 ? Math.max(0, Math.min(1, ((x - cx!) * ex + (y - cy!) * ey) / l2)) : 0;
        d = Math.min(d, Math.hypot(x - cx! - t * ex, y - cy! - t * ey));
      }
      worst = Math.max(worst, d);
    }
  }
  return worst;
}

test('a vertex\'s target is the nearest point of the chord between the neighbours that stay after it', () => {
  const [g] = lineGlides(zig, info);
  // The zigzag: (0, 3), (2, 9), (4, 3), (6, 9), (8, 3), (10, 9), (12, 3).
  // Vertex 2 (4, 3) goes first (z 2): its neighbours then are vertices 1 (2, 9) and 3 (6, 9), and
  // the nearest point of their chord is (4, 9).
  assert.deepEqual([g!.tx[2], g!.ty[2]], [4, 9]);
  // Vertex 3 (6, 9) goes last (z 6), after vertices 2, 4, 1 and 5: its neighbours then are the
  // ends (0, 3) and (12, 3), so it glides straight down to (6, 3).
  assert.deepEqual([g!.tx[3], g!.ty[3]], [6, 3]);
  // The ends stay and glide nowhere; each glide starts half a zoom level before its vertex goes.
  assert.deepEqual([g!.tx[0], g!.ty[0], g!.tx[6], g!.ty[6]], [0, 3, 12, 3]);
  for (const [v, leave] of [[2, 2], [4, 3], [1, 4], [5, 5], [3, 6]] as const) assert.ok(Math.abs(g!.from[v]! - (leave - 1 / 3)) < 1e-9, `vertex ${v} glides from ${g!.from[v]}`);
});

test('just before a vertex goes, the line lies on the line after it: no jump', () => {
  for (const leave of [2, 3, 4, 5, 6]) {
    const before = drawnAt(leave - 1e-9), after = drawnAt(leave);
    assert.ok(farthest(before, after) < 1e-6 && farthest(after, before) < 1e-6, `at z ${leave}: ${farthest(before, after)}, ${farthest(after, before)}`);
  }
});

test('outside the glides the vertices stand where they are stored; half-way through, half-way to the target', () => {
  for (const z of [1, 1.5, 2.5, 3.5, 4.5, 5.5, 8.9]) {
    const want = linePathsAtZ(zig, z).flatMap((p) => Array.from({ length: p.length / 2 - 1 }, (_, i) => [...p.subarray(2 * i, 2 * i + 4)].join(' ')));
    assert.deepEqual(drawnAt(z).map((s) => s.join(' ')).sort(), want.sort(), `z ${z}`);
  }
  // Vertex 2 (4, 3), gliding to (4, 9) from z 1 2/3 to 2, is at (4, 6) half-way.
  const mid = drawnAt(2 - 1 / 6).find((s) => s[0] === 2 && s[1] === 9)!;
  assert.ok(Math.abs(mid[2]! - 4) < 1e-9 && Math.abs(mid[3]! - 6) < 1e-9, `vertex 2 at ${mid.slice(2)}`);
  assert.deepEqual([glideShare(1, 2, 0.5), glideShare(1, 2, 1.5), glideShare(1, 2, 3), glideShare(2, 2, 1), glideShare(2, 2, 2)], [0, 0.5, 1, 0, 1]);
});
