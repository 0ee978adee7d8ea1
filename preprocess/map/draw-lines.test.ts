// The CPU line pass on hand-made lines. An L: the pixels drawn are exactly those whose centre
// lies within half the width of the polyline of the slice's z (distances measured here against
// a densely sampled copy of the polyline); a vertex gone at z cuts its corner; a line outside
// its z range, or where a non-flat surface leaves its range, is not drawn. A horizontal line at
// 1:10,000 (2.8 m per pixel): its width in mm covers the pixel rows worked out by hand, its
// casing shows on both sides, every casing lies under every fill, and outside its rule's scale
// range it is not drawn. Lines grow over the first half zoom level of their range and shrink over
// the last, by widths worked out by hand.
import assert from 'node:assert/strict';
import test from 'node:test';
import type { LineRecord } from '../../format/line-record.js';
import type { LineRule } from '../../format/line-style.js';
import { zAtScale, type ScaleInfo } from '../../format/scale.js';
import { drawLines, linePaintColour, type LineDepth } from './draw-lines.js';
import type { View } from './rasterize.js';

/** A rule of class 0 drawn at every scale unless said otherwise. */
const rule = (r: Partial<LineRule>): LineRule => ({ classIndex: 0, by: null, values: null, width: 1, color: '#ff0000', casing: null, weight: 1, ...r });
/** Rule 1 of these draws the L: `px` pixels wide (0.28 mm each). */
const widthPx = (px: number): LineRule[] => [rule({ width: 0 }), rule({ width: px * 0.28 })];
/**
 * Scales that double with each step: 1:5,000 at z 0, 1:10,000 at z 1, 1:20,000 at z 2 and so on
 * to z 12 (faces alive fall 4x a step, linear between steps).
 */
const info: ScaleInfo = { baseScale: 5000, baseFaces: 4 ** 12, zMax: 12, scaleTable: Array.from({ length: 13 }, (_, z): [number, number] => [z, 4 ** (12 - z)]) };
const flat = (z: number): LineDepth => ({ zAt: () => z, info });

// 1 m per pixel; rows from the top, so pixel (i, j) has its centre at (i + 0.5, 99.5 - j).
const view: View = { width: 100, height: 100, bbox: [0, 0, 100, 100] };
const L: LineRecord = {
  classIndex: 2, rule: 1, feature: 5, zStart: 1, zEnd: 10,
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
function assertAlong(drawn: Uint32Array, pts: number[], half: number, where: (i: number, j: number) => boolean, what: string): void {
  let lit = 0;
  for (let j = 0; j < 100; j++) {
    for (let i = 0; i < 100; i++) {
      const d = distance(pts, i + 0.5, 99.5 - j), v = drawn[j * 100 + i]!;
      if (v) lit++;
      if (v) assert.ok(v === 4 && where(i, j) && d <= half + 0.01, `${what}: pixel (${i}, ${j}) drawn (${v}) at ${d.toFixed(3)} m from the line`);
      else assert.ok(!where(i, j) || d >= half - 0.01, `${what}: pixel (${i}, ${j}) not drawn at ${d.toFixed(3)} m from the line`);
    }
  }
  assert.ok(lit > 50, `${what}: ${lit} pixels drawn`);
}

test('a line is drawn along its polyline at the slice\'s z, its width in mm, by its rule', () => {
  assertAlong(drawLines(view, [L], widthPx(3), flat(2)), [10.2, 20.3, 80.7, 20.3, 80.7, 90.1], 1.5, () => true, 'z 2, 3 px');
  assertAlong(drawLines(view, [L], widthPx(6), flat(2)), [10.2, 20.3, 80.7, 20.3, 80.7, 90.1], 3, () => true, 'z 2, 6 px');
});

test('above a vertex\'s leave z the line cuts its corner; outside its z range it is not drawn', () => {
  const cut = drawLines(view, [L], widthPx(3), flat(5));
  assertAlong(cut, [10.2, 20.3, 80.7, 90.1], 1.5, () => true, 'z 5: the corner vertex has gone');
  assert.equal(cut[(99 - 20) * 100 + 80], 0, 'the corner is not drawn');
  for (const z of [0.5, 10, 12]) assert.ok(drawLines(view, [L], widthPx(3), flat(z)).every((v) => v === 0), `nothing at z ${z}`);
});

test('a vertex glides onto the chord of its neighbours over the half zoom level before it goes', () => {
  // The corner (80.7, 20.3) goes at z 5. Its nearest point on the chord from (10.2, 20.3) to
  // (80.7, 90.1): t = 70.5² / (70.5² + 69.8²) along it.
  const t = 70.5 ** 2 / (70.5 ** 2 + 69.8 ** 2);
  const foot = [10.2 + t * 70.5, 20.3 + t * 69.8];
  // It starts at 1:5,000 x 2^5 / sqrt 2 (2^15 faces: 2/3 of the way from z 4, 4^8, to z 5, 4^7).
  const from = 4 + 2 / 3;
  assertAlong(drawLines(view, [L], widthPx(3), flat(from - 1e-9)), [10.2, 20.3, 80.7, 20.3, 80.7, 90.1], 1.5, () => true, 'before its glide: the corner');
  const mid = [80.7 + 0.5 * (foot[0]! - 80.7), 20.3 + 0.5 * (foot[1]! - 20.3)];
  assertAlong(drawLines(view, [L], widthPx(3), flat((from + 5) / 2)), [10.2, 20.3, ...mid, 80.7, 90.1], 1.5, () => true, 'half-way: half-way to the chord');
  assertAlong(drawLines(view, [L], widthPx(3), flat(5 - 1e-9)), [10.2, 20.3, ...foot, 80.7, 90.1], 1.5, () => true, 'as it goes: on the chord');
});

test('on a surface whose z varies, each pixel is tested against the z there', () => {
  // z 2 in the west half (the L), 7 in the east half (the chord), 11 in the top rows (nothing).
  const zAt = (p: number): number => (Math.floor(p / 100) < 20 ? 11 : p % 100 < 50 ? 2 : 7);
  const drawn = drawLines(view, [L], widthPx(3), { zAt, info });
  const west = new Uint32Array(drawn.length), east = new Uint32Array(drawn.length);
  drawn.forEach((v, p) => ((p % 100 < 50 ? west : east)[p] = v));
  assertAlong(west, [10.2, 20.3, 80.7, 20.3], 1.5, (i) => i < 50, 'west of x 50: the L');
  assertAlong(east, [10.2, 20.3, 80.7, 90.1], 1.5, (i, j) => i >= 50 && j >= 20, 'east of x 50: the chord, below the top rows');
});

// 1:10,000 at 0.28 mm per pixel: 2.8 m per pixel. Pixel row j has its centre at y = 280 - 2.8 (j + 0.5).
const at10k: View = { width: 100, height: 100, bbox: [0, 0, 280, 280] };
const rowY = (j: number): number => 280 - 2.8 * (j + 0.5);
const across = (y: number, rule = 0, x0 = 20, x1 = 260): LineRecord => ({ classIndex: 0, rule, feature: 0, zStart: 0, zEnd: 10, paths: [Float64Array.of(x0, y, x1, y)], leaveZ: [Float64Array.of(10, 10)] });
/** The colour painted in each row of column 50, from row 40 to 60 (rows without paint left out). */
function column(paint: Uint32Array, rules: LineRule[], i = 50): Record<number, string> {
  const out: Record<number, string> = {};
  for (let j = 40; j <= 60; j++) {
    const c = linePaintColour(rules, paint[j * 100 + i]!);
    if (c) out[j] = c;
  }
  return out;
}

test('a line 1 mm wide at 1:10,000 covers the pixel rows within 0.5 mm of its axis', () => {
  // 1 mm = 3.57 px: half of it, 1.79 px, reaches the centres of the rows one away but not two.
  const rules = [rule({ width: 1 })];
  assert.deepEqual(column(drawLines(at10k, [across(rowY(50))], rules, flat(1)), rules), { 49: '#ff0000', 50: '#ff0000', 51: '#ff0000' }, 'on a row centre');
  // Half-way between rows 49 and 50: the centres 0.5 and 1.5 px away, not 2.5.
  assert.deepEqual(column(drawLines(at10k, [across(rowY(49.5))], rules, flat(1)), rules), { 48: '#ff0000', 49: '#ff0000', 50: '#ff0000', 51: '#ff0000' }, 'between rows');
  // 2 mm = 7.14 px: half, 3.57 px, reaches three rows each side.
  const wide = [rule({ width: 2 })];
  assert.deepEqual(Object.keys(column(drawLines(at10k, [across(rowY(50))], wide, flat(1)), wide)).map(Number), [47, 48, 49, 50, 51, 52, 53]);
});

test('a casing shows on both sides of the line, its width beyond each side', () => {
  // Fill half 1.79 px (rows 49..51); casing 0.56 mm = 2 px more each side: 3.79 px (rows 47..53).
  const rules = [rule({ width: 1, color: '#ffffff', casing: { width: 0.56, color: '#808080' } })];
  assert.deepEqual(column(drawLines(at10k, [across(rowY(50))], rules, flat(1)), rules), {
    47: '#808080', 48: '#808080', 49: '#ffffff', 50: '#ffffff', 51: '#ffffff', 52: '#808080', 53: '#808080',
  });
});

test('every casing lies under every fill, and a later rule\'s fill over an earlier one\'s', () => {
  const rules = [
    rule({ width: 1, color: '#0000ff', casing: { width: 0.56, color: '#000080' } }),
    rule({ width: 1, color: '#ffffff', casing: { width: 0.56, color: '#808080' } }),
  ];
  // Rule 1 runs down column 50; rule 0 across row 50.
  const down: LineRecord = { ...across(0, 1), paths: [Float64Array.of(2.8 * 50.5, 20, 2.8 * 50.5, 260)] };
  const paint = drawLines(at10k, [down, across(rowY(50), 0)], rules, flat(1));
  // Column 47 lies in rule 1's casing (3.79 px from its axis), outside its fill: there rule 0's
  // fill shows (rows 49..51), not rule 1's casing, which covers the rest of the column.
  const want: Record<number, string> = {};
  for (let j = 40; j <= 60; j++) want[j] = j >= 49 && j <= 51 ? '#0000ff' : '#808080';
  assert.deepEqual(column(paint, rules, 47), want);
  // Away from the crossing, rule 0 has its own casing on both sides.
  assert.deepEqual(column(paint, rules, 20), { 47: '#000080', 48: '#000080', 49: '#0000ff', 50: '#0000ff', 51: '#0000ff', 52: '#000080', 53: '#000080' });
  // Column 50 is rule 1's fill throughout, over rule 0's.
  assert.ok(Object.values(column(paint, rules, 50)).every((c) => c === '#ffffff'));
});

test('a line is drawn only where the scale of the z at the pixel lies in its rule\'s scale range', () => {
  const line = across(rowY(50));
  const drawnAt = (r: Partial<LineRule>, scale: number): number => drawLines(at10k, [line], [rule(r)], flat(zAtScale(info, scale))).filter((v) => v > 0).length;
  assert.ok(drawnAt({}, 10000) > 200, 'no range: drawn');
  assert.ok(drawnAt({ minScale: 5000, maxScale: 25000 }, 10000) > 200, 'inside the range');
  assert.equal(drawnAt({ minScale: 15000 }, 10000), 0, 'above the scale');
  assert.equal(drawnAt({ maxScale: 5000 }, 10000), 0, 'below the scale');
  assert.equal(drawnAt({ width: 0, casing: { width: 1, color: '#000000' } }, 10000), 0, 'width 0: neither line nor casing');
  // Per pixel: z 1 (1:10,000) in the west half, z 2 (1:20,000) in the east; drawn up to 1:15,000.
  const paint = drawLines(at10k, [line], [rule({ maxScale: 15000 })], { zAt: (p) => (p % 100 < 50 ? 1 : 2), info });
  const cols = new Set<number>();
  paint.forEach((v, p) => v && cols.add(p % 100));
  // The west end at x 20 m (7.14 px) with its round cap reaches column 5 (centre 1.64 px away).
  assert.deepEqual([Math.min(...cols), Math.max(...cols)], [5, 49], 'from the line\'s west end to the middle');
});

test('a line grows over the first half zoom level of its range and shrinks over the last', () => {
  // 2 mm wide (half 3.57 px: rows 47..53 at full width), on the map for 1 <= z < 10.
  const rules = [rule({ width: 2 })];
  const line: LineRecord = { ...across(rowY(50)), zStart: 1, zEnd: 10 };
  const rows = (z: number): number => Object.keys(column(drawLines(at10k, [line], rules, flat(z)), rules)).length;
  // Full width half a zoom level in, at 1:10,000 x sqrt 2: 4^12 (5,000 / 14,142)^2 = 4^10.5 faces,
  // which the table reaches 2/3 of the way from z 1 (4^11) to z 2 (4^10). Half of it (1.79 px:
  // rows 49..51) half-way there.
  assert.equal(rows(1), 0, 'nothing as it appears');
  assert.equal(rows(1 + 1 / 3), 3, 'half the width a quarter zoom level in');
  assert.equal(rows(1 + 2 / 3 + 1e-9), 7, 'the whole width from half a zoom level in');
  assert.equal(rows(5), 7);
  // It shrinks from 1:20,000 x 2^9 / sqrt 2 (32 faces: 2/3 of the way from z 9, 64, to z 10, 16).
  assert.equal(rows(9 + 2 / 3 - 1e-9), 7, 'the whole width until half a zoom level before it goes');
  assert.equal(rows(9 + 5 / 6), 3, 'half the width a quarter zoom level before it goes');
  assert.ok(rows(10 - 1e-9) <= 1, 'nothing but the row on its axis as it goes');
  assert.equal(rows(10), 0, 'nothing once gone');
  // A rule's scale range ramps the same way: this one ends at 1:20,000 (z 2), so the line is full
  // up to 1:14,142 (z 1 2/3) and half wide at z 1 5/6.
  const ends = [rule({ width: 2, maxScale: 20000 })];
  const endRows = (z: number): number => Object.keys(column(drawLines(at10k, [across(rowY(50))], ends, flat(z)), ends)).length;
  assert.deepEqual([endRows(1.5), endRows(1 + 5 / 6), Math.min(1, endRows(2 - 1e-9)), endRows(2)], [7, 3, 1, 0]);
});
