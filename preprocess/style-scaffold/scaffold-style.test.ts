import { test } from 'node:test';
import assert from 'node:assert/strict';
import type { InputFeature, RawInput } from '../io/read-input.js';
import { PIXEL_SIZE_MM } from '../../format/pixel-size.js';
import { parseStyle } from '../style.js';
import { guessClassProperty, guessIdProperty } from './class-stats.js';
import { formatStyleJson, scaffoldStyle } from './scaffold-style.js';

const rect = (x0: number, y0: number, x1: number, y1: number): Float64Array => Float64Array.of(x0, y0, x1, y0, x1, y1, x0, y1);
const feature = (index: number, properties: Record<string, unknown>, ring: Float64Array): InputFeature => ({ ref: { index, id: null }, properties, polygons: [[ring]] });

// A row of ten 20 m x 20 m houses along a 200 m x 4 m road, and a 200 m x 200 m field.
function village(): RawInput {
  const features: InputFeature[] = [];
  for (let i = 0; i < 10; i++) features.push(feature(features.length, { kind: 'house', fid: `h${i}`, height: 7.5 + i / 10 }, rect(20 * i, 4, 20 * i + 20, 24)));
  for (let i = 0; i < 4; i++) features.push(feature(features.length, { kind: 'road', fid: `r${i}`, height: 0.5 }, rect(50 * i, 0, 50 * i + 50, 4)));
  features.push(feature(features.length, { kind: 'field', fid: 'f', height: 0.25 }, rect(0, 24, 200, 224)));
  return { file: 'village.geojson', crsMember: null, features, repairs: { closedRings: 0, duplicatePoints: 0 } };
}

test('a hand-made village: the class and id properties are guessed, roads suggested linear, areas summed', () => {
  const raw = village();
  assert.equal(guessClassProperty(raw.features).property, 'kind'); // fid is unique, height is a measure
  assert.equal(guessIdProperty(raw.features), 'fid');
  const s = scaffoldStyle(raw);
  const rows = new Map(s.rows.map((r) => [r.key, r]));
  assert.deepEqual([...rows.keys()], ['field', 'house', 'road']);
  assert.equal(rows.get('house')!.faces, 10);
  assert.equal(rows.get('house')!.area, 4000);
  assert.equal(rows.get('road')!.area, 800);
  assert.equal(rows.get('field')!.area, 40000);
  // Road pieces 50 x 4: width 2 * 200 / 108 = 3.7 m, elongation 108^2 / 3200 = 3.6.
  assert.ok(Math.abs(rows.get('road')!.width - 400 / 108) < 1e-9);
  assert.equal(rows.get('road')!.linear, true);
  assert.equal(rows.get('house')!.linear, false);
  assert.equal(rows.get('field')!.linear, false);
  // Mean face: 44800 m2 / 15 faces, 54.65 m across = 20 px of 0.28 mm at 1:9759, rounded to 1:10000.
  const raw1 = Math.sqrt(44800 / 15) / ((20 * PIXEL_SIZE_MM) / 1000);
  assert.ok(raw1 > 7500 && raw1 < 15000);
  assert.equal(s.style.baseScale, 10000);
  assert.equal(s.style.classProperty, 'kind');
  assert.equal(s.classProperty.given, false);
  // The file parses as a style, with the classes in order.
  const parsed = parseStyle(JSON.parse(formatStyleJson(s.style)));
  assert.deepEqual(parsed.classes.map((c) => [c.key, c.linear]), [['field', false], ['house', false], ['road', true]]);
});

test('a given class property with missing values: every feature without one is named in one error', () => {
  const raw = village();
  delete raw.features[3]!.properties.kind;
  raw.features[7]!.properties.kind = null;
  assert.throws(() => scaffoldStyle(raw, { classProperty: 'kind' }), /2 of 15 features have no value for the class property "kind": #3, #7/);
});

test('no property looks like a class: one class', () => {
  const raw = village();
  for (const f of raw.features) f.properties = { fid: f.properties.fid };
  const s = scaffoldStyle(raw);
  assert.equal(s.style.classProperty, null);
  assert.deepEqual(s.rows.map((r) => [r.key, r.faces]), [['all', 15]]);
  assert.equal(parseStyle(s.style).classes.length, 1);
});
