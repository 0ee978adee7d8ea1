// The CPU line pass on a hand-made L: the pixels drawn are exactly those whose centre lies within
// half the width of the polyline of the slice's z (distances measured here against a densely
// sampled copy of the polyline), in the line's class; a vertex gone at z cuts its corner; a line
// outside its z range, or where a non-flat surface leaves its range, is not drawn.
import assert from 'node:assert/strict';
import test from 'node:test';
import type { LineRecord } from '../../format/line-chunk.js';
import { drawLines } from './draw-lines.js';
import type { View } from './rasterize.js';

// 1 m per pixel; rows from the top, so pixel (i, j) has its centre at (i + 0.5, 99.5 - j).
const view: View = { width: 100, height: 100, bbox: [0, 0, 100, 100] };
const L: LineRecord = {
  classIndex: 2, feature: 5, zStart: 1, zEnd: 10,
  paths: [Float64Array.of(10.2, 20.3, 80.7, 20.3, 80.7, 90.1)],
  leaveZ: [Float64Array.of(10, 5, 10)],
};

/** Distance from (x, y) to the polyline through `pts`, by points every 1 cm along it. */
function distance(pts: number[], x: number, y: number): number {
  let d = Infinity;
  for (let k = 0; k + 3 < pts.length; k += 2) {
    const len = Math.hypot(pts[k + 2]! - pts[k]!, pts[k + 3]! - pts[k + 1]!), n = Math.ceil(len / 0.01);
    for (let s = 0; s <= n; s++) d = Math.min(d, Math.hypot(pts[k]! + ((pts[k + 2]! - pts[k]!) * s) / n - x, pts[k + 1]! + ((pts[k + 3]! - pts[k + 1]!) * s) / n - y));
  }
  return d;
}

/** Checks that the pixels drawn are those within `half` of the polyline `pts` (1 cm of slack for the sampling), where `where` holds. */
function assertAlong(drawn: Uint16Array, pts: number[], half: number, where: (i: number, j: number) => boolean, what: string): void {
  let lit = 0;
  for (let j = 0; j < 100; j++) {
    for (let i = 0; i < 100; i++) {
      const d = distance(pts, i + 0.5, 99.5 - j), v = drawn[j * 100 + i]!;
      if (v) lit++;
      if (v) assert.ok(v === 3 && where(i, j) && d <= half + 0.01, `${what}: pixel (${i}, ${j}) drawn (${v}) at ${d.toFixed(3)} m from the line`);
      else assert.ok(!where(i, j) || d >= half - 0.01, `${what}: pixel (${i}, ${j}) not drawn at ${d.toFixed(3)} m from the line`);
    }
  }
  assert.ok(lit > 50, `${what}: ${lit} pixels drawn`);
}

test('a line is drawn along its polyline at the slice\'s z, its width in pixels, in its class', () => {
  assertAlong(drawLines(view, [L], () => 2, 3), [10.2, 20.3, 80.7, 20.3, 80.7, 90.1], 1.5, () => true, 'z 2, 3 px');
  assertAlong(drawLines(view, [L], () => 2, 6), [10.2, 20.3, 80.7, 20.3, 80.7, 90.1], 3, () => true, 'z 2, 6 px');
});

test('above a vertex\'s leave z the line cuts its corner; outside its z range it is not drawn', () => {
  const cut = drawLines(view, [L], () => 5, 3);
  assertAlong(cut, [10.2, 20.3, 80.7, 90.1], 1.5, () => true, 'z 5: the corner vertex has gone');
  assert.equal(cut[(99 - 20) * 100 + 80], 0, 'the corner is not drawn');
  for (const z of [0.5, 10, 12]) assert.ok(drawLines(view, [L], () => z, 3).every((v) => v === 0), `nothing at z ${z}`);
});

test('on a surface whose z varies, each pixel is tested against the z there', () => {
  // z 2 in the west half (the L), 7 in the east half (the chord), 11 in the top rows (nothing).
  const zAt = (p: number): number => (Math.floor(p / 100) < 20 ? 11 : p % 100 < 50 ? 2 : 7);
  const drawn = drawLines(view, [L], zAt, 3);
  const west = new Uint16Array(drawn.length), east = new Uint16Array(drawn.length);
  drawn.forEach((v, p) => ((p % 100 < 50 ? west : east)[p] = v));
  assertAlong(west, [10.2, 20.3, 80.7, 20.3], 1.5, (i) => i < 50, 'west of x 50: the L');
  assertAlong(east, [10.2, 20.3, 80.7, 90.1], 1.5, (i, j) => i >= 50 && j >= 20, 'east of x 50: the chord, below the top rows');
});
