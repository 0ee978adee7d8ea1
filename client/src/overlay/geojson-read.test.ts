// Reading GeoJSON for the overlay: every kind of geometry into points, lines and polygons, and
// one error that names every problem with its feature.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { GeoJsonError, readGeoJson } from './geojson-read.js';

describe('readGeoJson', () => {
  test('a FeatureCollection of every geometry type gives their points, lines and rings', () => {
    const fc = {
      type: 'FeatureCollection',
      features: [
        { type: 'Feature', id: 'a', properties: { name: 'A' }, geometry: { type: 'Point', coordinates: [5.7, 52.1, 30] } },
        { type: 'Feature', properties: null, geometry: { type: 'MultiPoint', coordinates: [[5, 52], [6, 53]] } },
        { type: 'Feature', properties: {}, geometry: { type: 'LineString', coordinates: [[5, 52], [6, 53]] } },
        { type: 'Feature', properties: {}, geometry: { type: 'MultiLineString', coordinates: [[[5, 52], [6, 53]], [[7, 52], [8, 52], [8, 53]]] } },
        // Closed outer ring, open hole: both read without the closing position.
        { type: 'Feature', properties: {}, geometry: { type: 'Polygon', coordinates: [[[0, 0], [10, 0], [10, 10], [0, 0]], [[2, 2], [3, 2], [3, 3]]] } },
        { type: 'Feature', properties: {}, geometry: { type: 'MultiPolygon', coordinates: [[[[0, 0], [1, 0], [1, 1]]], [[[5, 5], [6, 5], [6, 6]]]] } },
        { type: 'Feature', properties: {}, geometry: { type: 'GeometryCollection', geometries: [{ type: 'Point', coordinates: [1, 1] }, { type: 'LineString', coordinates: [[0, 0], [1, 1]] }] } },
        { type: 'Feature', properties: {}, geometry: null },
      ],
    };
    const r = readGeoJson(fc, true, 'test');
    assert.equal(r.length, 8);
    assert.equal(r[0]!.feature, fc.features[0], 'events give the feature passed');
    assert.deepEqual(r[0]!.parts.points, [[5.7, 52.1]]);
    assert.equal(r[1]!.parts.points.length, 2);
    assert.deepEqual(r[3]!.parts.lines.map((l) => l.length), [2, 3]);
    assert.deepEqual(r[4]!.parts.polygons, [[[[0, 0], [10, 0], [10, 10]], [[2, 2], [3, 2], [3, 3]]]]);
    assert.equal(r[5]!.parts.polygons.length, 2);
    assert.deepEqual([r[6]!.parts.points.length, r[6]!.parts.lines.length], [1, 1]);
    assert.deepEqual(r[7]!.parts, { points: [], lines: [], polygons: [] });
  });

  test('a bare geometry is one feature, a Feature is itself', () => {
    const g = { type: 'LineString', coordinates: [[0, 0], [1, 1]] };
    const [f] = readGeoJson(g, false, 'test');
    assert.deepEqual(f!.feature, { type: 'Feature', geometry: g, properties: {} });
    const feat = { type: 'Feature', properties: { k: 1 }, geometry: g };
    assert.equal(readGeoJson(feat, false, 'test')[0]!.feature, feat);
  });

  test('every problem is named at once, with its feature and where in it', () => {
    const fc = {
      type: 'FeatureCollection',
      features: [
        { type: 'Feature', properties: {}, geometry: { type: 'Point', coordinates: [5, 52] } },
        { type: 'Feature', id: 7, properties: {}, geometry: { type: 'Point', coordinates: [5, 95] } },
        { type: 'Feature', properties: {}, geometry: { type: 'Circle', coordinates: [5, 52] } },
        { type: 'Feature', properties: {}, geometry: { type: 'LineString', coordinates: [[5, 52]] } },
        { type: 'Feature', properties: {}, geometry: { type: 'Polygon', coordinates: [[[0, 0], [1, 'x'], [1, 1]]] } },
        { type: 'Feature', properties: 3, geometry: { type: 'Polygon', coordinates: [[[0, 0], [1, 1], [0, 0]]] } },
        { type: 'Fature', geometry: null },
      ],
    };
    let err: unknown;
    try {
      readGeoJson(fc, true, 'GeoJsonLayer setData');
    } catch (e) {
      err = e;
    }
    assert.ok(err instanceof GeoJsonError);
    assert.deepEqual(err.problems, [
      'features[1] (id 7): geometry.coordinates: latitude 95 is outside [-90, 90] (longitude/latitude expected; projected coordinates go to setDataProjected)',
      'features[2]: geometry.type: "Circle" is not a GeoJSON geometry type (Point, MultiPoint, LineString, MultiLineString, Polygon, MultiPolygon, GeometryCollection)',
      'features[3]: geometry.coordinates: a line needs at least two positions, not 1',
      'features[4]: geometry.coordinates[0][1]: a position\'s coordinates must be finite numbers, not [1,"x"]',
      'features[5]: "properties" must be an object or null, not 3',
      'features[5]: geometry.coordinates[0]: a ring needs at least three distinct positions, not 2',
      'features[6] must be a Feature (an object with "type": "Feature"), not an object with "type" "Fature"',
    ]);
    assert.match(err.message, /^GeoJsonLayer setData: 7 problems in the GeoJSON:\n {2}features\[1\] \(id 7\)/);
  });

  test('projected coordinates have no latitude limit; a wrong top level is named', () => {
    assert.equal(readGeoJson({ type: 'Point', coordinates: [155000, 463000] }, false, 't').length, 1);
    assert.throws(() => readGeoJson([1, 2], true, 't'), /the data must be a GeoJSON object .*not \[1,2\]/);
    assert.throws(() => readGeoJson({ type: 'Topology' }, true, 't'), /"type" must be FeatureCollection, Feature or a geometry type .*not "Topology"/);
  });
});
