// The overlay's mesh against hand-made geometry: one quad per segment whose placed corners,
// cut to the half width as the fragment shader cuts them, cover exactly the band around the
// line (round joins, no gap at a sharp turn), and polygon triangles whose area is the polygon's.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import type { Parts, XY } from './geojson-read.js';
import { distanceToSegment } from './overlay-hit.js';
import { buildMesh } from './overlay-mesh.js';
import { quadCount, QUAD_FLOATS, QUAD_VERTICES } from './overlay-quads.js';

const parts = (p: Partial<Parts>): Parts => ({ points: [], lines: [], polygons: [], ...p });

interface PlacedQuad {
  corners: XY[];
  a: XY;
  b: XY;
}

/**
 * The quads as the vertex shader places them, at 1 ground unit per pixel: a corner is its end
 * of the segment plus its direction times `reach`.
 */
function placed(quads: Float32Array, origin: XY, reach: number): PlacedQuad[] {
  const out: PlacedQuad[] = [];
  for (let q = 0; q < quadCount(quads); q++) {
    const v = (k: number): number[] => Array.from(quads.subarray((q * QUAD_VERTICES + k) * QUAD_FLOATS, (q * QUAD_VERTICES + k + 1) * QUAD_FLOATS));
    const [ax, ay, bx, by] = v(0) as [number, number, number, number];
    const corners = [0, 1, 3, 2].map((k): XY => {
      const [, , , , ex, ey, end] = v(k) as [number, number, number, number, number, number, number];
      return [(end ? bx : ax) + origin[0] + ex * reach, (end ? by : ay) + origin[1] + ey * reach];
    });
    out.push({ corners, a: [ax + origin[0], ay + origin[1]], b: [bx + origin[0], by + origin[1]] });
  }
  return out;
}

/** Inside a convex polygon given in order (either orientation). */
function inConvex(p: XY, c: XY[]): boolean {
  let sign = 0;
  for (let i = 0; i < c.length; i++) {
    const a = c[i]!, b = c[(i + 1) % c.length]!;
    const s = Math.sign((b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]));
    if (s === 0) continue;
    if (sign === 0) sign = s;
    else if (s !== sign) return false;
  }
  return true;
}

/** Distance to a polyline by sampling it densely (a computation apart from the code under test). */
function sampledDistance(p: XY, line: XY[]): number {
  let d = Infinity;
  for (let i = 0; i + 1 < line.length; i++) {
    const [a, b] = [line[i]!, line[i + 1]!];
    const steps = Math.ceil(Math.hypot(b[0] - a[0], b[1] - a[1]) / 0.002) || 1;
    for (let k = 0; k <= steps; k++) d = Math.min(d, Math.hypot(p[0] - (a[0] + ((b[0] - a[0]) * k) / steps), p[1] - (a[1] + ((b[1] - a[1]) * k) / steps)));
  }
  return d;
}

describe('overlay mesh', () => {
  // A zigzag in national grid coordinates: a right angle, a sharp (about 27 degree) turn, and
  // a repeated position that makes no segment.
  const base: XY = [155000, 463000];
  const shifted = (pts: XY[]): XY[] => pts.map(([x, y]): XY => [base[0] + x, base[1] + y]);
  const line = shifted([[0, 0], [10, 0], [10, 10], [10, 10], [0, 5]]);

  test('a polyline gives one quad per segment (none for a repeated position), a point one', () => {
    const m = buildMesh([parts({ lines: [line], points: [[1, 2]] })]);
    assert.equal(quadCount(m.lines), 3);
    assert.equal(quadCount(m.points), 1);
    assert.equal(quadCount(m.rings), 0);
  });

  test('the quads, cut to the half width, cover exactly the band of that half width around the line', () => {
    const w = 2;
    // Reach as the shader: the half width and a pixel for the anti-aliased edge.
    const m = buildMesh([parts({ lines: [line] })]);
    const quads = placed(m.lines, m.origin, w + 1);
    let inBand = 0, checked = 0;
    for (let x = -4; x <= 14; x += 0.25) {
      for (let y = -4; y <= 14; y += 0.25) {
        const p: XY = [base[0] + x + 0.013, base[1] + y + 0.007];
        const d = sampledDistance(p, line);
        if (Math.abs(d - w) < 0.01) continue; // on the band's edge: too close to call by sampling
        // What the fragment shader keeps of a quad: its points within the half width of its segment.
        const drawn = quads.some((q) => inConvex(p, q.corners) && distanceToSegment(p, q.a, q.b) <= w);
        assert.equal(drawn, d <= w, `(${x}, ${y}) at ${d.toFixed(3)} from the line`);
        checked++;
        if (d <= w) inBand++;
      }
    }
    assert.ok(inBand > 500 && checked > 4000, `${inBand} of ${checked} points in the band`);
  });

  test('joins have no gap: around each inner vertex every direction within the half width is covered', () => {
    const w = 3;
    const m = buildMesh([parts({ lines: [line] })]);
    const quads = placed(m.lines, m.origin, w + 1);
    for (const v of [line[1]!, line[2]!]) {
      for (let k = 0; k < 64; k++) {
        const ang = (2 * Math.PI * k) / 64;
        const p: XY = [v[0] + 0.999 * w * Math.cos(ang), v[1] + 0.999 * w * Math.sin(ang)];
        assert.ok(quads.some((q) => inConvex(p, q.corners) && distanceToSegment(p, q.a, q.b) <= w), `covered at angle ${k}/64 around (${v[0] - base[0]}, ${v[1] - base[1]})`);
      }
    }
  });

  test('a point covers the disc of its radius', () => {
    const r = 5;
    const m = buildMesh([parts({ points: [[100, 200]] })]);
    const [q] = placed(m.points, m.origin, r + 1);
    for (let k = 0; k < 32; k++) {
      const ang = (2 * Math.PI * k) / 32;
      const p: XY = [100 + 0.999 * r * Math.cos(ang), 200 + 0.999 * r * Math.sin(ang)];
      assert.ok(inConvex(p, q!.corners) && distanceToSegment(p, q!.a, q!.b) <= r);
    }
  });

  test("a polygon with a hole: its triangles' area is the outer ring's minus the hole's, and its rings give quads", () => {
    // 10 x 8 with a 3 x 2 hole, off the origin and with open and closed rings.
    const outer = shifted([[0, 0], [10, 0], [10, 8], [0, 8]]);
    const hole = shifted([[2, 2], [2, 4], [5, 4], [5, 2]]);
    const m = buildMesh([parts({ polygons: [[outer, hole]] })]);
    const { positions: pos, indices: idx } = m.fill;
    let area = 0;
    for (let t = 0; t < idx.length; t += 3) {
      const [i, j, k] = [idx[t]!, idx[t + 1]!, idx[t + 2]!];
      area += Math.abs((pos[2 * j]! - pos[2 * i]!) * (pos[2 * k + 1]! - pos[2 * i + 1]!) - (pos[2 * k]! - pos[2 * i]!) * (pos[2 * j + 1]! - pos[2 * i + 1]!)) / 2;
    }
    assert.ok(Math.abs(area - (10 * 8 - 3 * 2)) < 1e-3, `area ${area}`);
    assert.equal(quadCount(m.rings), 8, 'four sides of each ring, closed');
    assert.deepEqual(m.origin, [base[0] + 5, base[1] + 4], 'stored relative to the middle of the data');
  });
});
