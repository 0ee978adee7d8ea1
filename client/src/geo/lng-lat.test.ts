// LngLat and LngLatBounds take what MapLibre's take, and name what is wrong otherwise.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { LngLat, type LngLatLike } from './lng-lat.js';
import { LngLatBounds } from './lng-lat-bounds.js';

describe('LngLat', () => {
  test('from an array, { lng, lat } and { lon, lat }', () => {
    const likes: LngLatLike[] = [[5.8, 52.1], { lng: 5.8, lat: 52.1 }, { lon: 5.8, lat: 52.1 }, new LngLat(5.8, 52.1)];
    for (const like of likes) {
      assert.deepEqual(LngLat.convert(like).toArray(), [5.8, 52.1]);
    }
  });

  test('a latitude beyond the poles, a number that is not, or another shape is refused by name', () => {
    assert.throws(() => new LngLat(5, 91), /latitude must be between -90 and 90/);
    assert.throws(() => LngLat.convert([NaN, 52]), /must be finite numbers/);
    assert.throws(() => LngLat.convert({ x: 5, y: 52 } as unknown as [number, number]), /Invalid LngLatLike .*"x":5/);
    assert.throws(() => LngLat.convert([5, 52, 3] as unknown as [number, number]), /Invalid LngLatLike \[5,52,3\]/);
  });
});

describe('LngLatBounds', () => {
  test('[west, south, east, north] and [[west, south], [east, north]] are the same box', () => {
    const a = LngLatBounds.convert([5.7, 52.0, 5.9, 52.2]);
    const b = LngLatBounds.convert([[5.7, 52.0], [5.9, 52.2]]);
    assert.deepEqual(a.toArray(), [[5.7, 52.0], [5.9, 52.2]]);
    assert.deepEqual(b.toArray(), a.toArray());
    assert.deepEqual([a.getWest(), a.getSouth(), a.getEast(), a.getNorth()], [5.7, 52.0, 5.9, 52.2]);
    assert.deepEqual(a.getNorthWest().toArray(), [5.7, 52.2]);
    assert.ok(a.contains([5.8, 52.1]) && !a.contains([5.8, 52.3]));
  });

  test('a box upside down, or of another shape, is refused by name', () => {
    assert.throws(() => LngLatBounds.convert([5.7, 52.2, 5.9, 52.0]), /south \(52.2\) is north of the north \(52\)/);
    assert.throws(() => LngLatBounds.convert([1, 2, 3] as unknown as [number, number, number, number]), /Invalid LngLatBoundsLike \[1,2,3\]/);
  });
});
