// Outlines of a value's pixels, on hand-made rasters: a square, a ring with a hole, two pixels
// touching at a corner, and the area of every outline equal to the count of its pixels.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { pixelOutline, type Ring } from './pixel-outline.js';

/** Shoelace area on a y-up map (y negated): outer rings positive, holes negative. */
function upArea(ring: Ring): number {
  let a = 0;
  for (let k = 0; k + 1 < ring.length; k++) a += ring[k]![0] * -ring[k + 1]![1] - ring[k + 1]![0] * -ring[k]![1];
  return a / 2;
}

/** A raster from rows of characters; '.' is 0, a digit its value. */
function raster(rows: string[]): { data: number[]; width: number; height: number } {
  return { data: rows.flatMap((r) => [...r].map((c) => (c === '.' ? 0 : Number(c)))), width: rows[0]!.length, height: rows.length };
}

describe('pixel outline', () => {
  test('a 2 x 2 block is one square ring with its four corners', () => {
    const r = raster(['....', '.11.', '.11.', '....']);
    const rings = pixelOutline(r.data, r.width, r.height, 1);
    assert.equal(rings.length, 1);
    const ring = rings[0]!;
    assert.deepEqual(ring[0], ring.at(-1), 'closed');
    assert.deepEqual(new Set(ring.slice(0, -1).map((p) => p.join(','))), new Set(['1,1', '3,1', '3,3', '1,3']));
    assert.equal(upArea(ring), 4);
  });

  test('a block with a hole: an outer ring counter-clockwise and a hole clockwise (y up)', () => {
    const r = raster(['11111', '12221', '12.21', '12221', '11111']);
    const rings = pixelOutline(r.data, r.width, r.height, 2);
    const areas = rings.map(upArea).sort((a, b) => a - b);
    assert.deepEqual(areas, [-1, 9]);
    // The raster's edge counts as the region's edge.
    const outer = pixelOutline(r.data, r.width, r.height, 1).map(upArea).sort((a, b) => a - b);
    assert.deepEqual(outer, [-9, 25]);
  });

  test('two pixels meeting at a corner are two rings', () => {
    const r = raster(['1.', '.1']);
    const rings = pixelOutline(r.data, r.width, r.height, 1);
    assert.equal(rings.length, 2);
    for (const ring of rings) assert.equal(ring.length, 5, `a unit square: ${JSON.stringify(ring)}`);
    assert.deepEqual(rings.map(upArea), [1, 1]);
  });

  test('the signed areas add up to the pixel count of any shape', () => {
    const r = raster(['1101011', '1111010', '0101111', '1110101', '1011111']);
    const count = r.data.filter((v) => v === 1).length;
    const total = pixelOutline(r.data, r.width, r.height, 1).reduce((s, ring) => s + upArea(ring), 0);
    assert.equal(total, count);
    assert.deepEqual(pixelOutline(r.data, r.width, r.height, 7), []);
  });

  test('a raster of the wrong size is refused', () => {
    assert.throws(() => pixelOutline([1, 2, 3], 2, 2, 1), /3 pixels for 2 x 2/);
  });
});
