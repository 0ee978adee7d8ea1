// The style as the generalization uses it: class numbering, the compatibility matrix, and one
// error that names every problem of a style file.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { InputError } from './io/errors.js';
import { parseStyle, styleToJson } from './style.js';

describe('style', () => {
  test('classes are numbered in order and compatibilities fill a matrix', () => {
    const s = parseStyle({
      defaultCompatibility: 0.2,
      classes: { road: { color: '#ffffff', linear: true }, field: { color: '#00FF00' }, house: { color: '#aa0000', weight: 4 } },
      compatibility: { road: { field: 0.9 }, house: { road: 0.4 } },
    });
    assert.deepEqual(s.classes.map((c) => c.key), ['road', 'field', 'house']);
    assert.deepEqual(s.compat.map((row) => [...row]), [
      [1, 0.9, 0.2],
      [0.2, 1, 0.2],
      [0.4, 0.2, 1],
    ]);
    assert.equal(s.classes[1]!.color, '#00ff00');
  });

  test('the stored style reads back the same', () => {
    const s = parseStyle({
      name: 'x', baseScale: 5000,
      classes: [
        { key: 2, color: '#010203', pattern: { kind: 'dots', color: '#000000', minScale: 100 } },
        { key: 1, color: '#040506', linear: true, line: { width: 0.3, casing: { width: 0.1, color: '#000000' }, by: 'k', rules: [{ values: ['a'], width: 0.5, casing: null }] } },
        { key: 3, color: '#070809', linear: true, network: '1' },
      ],
      compatibility: { 2: { 1: 0.7 } },
    });
    const again = parseStyle(styleToJson(s));
    assert.deepEqual(again, s);
    assert.equal(again.classes[2]!.network, '1');
    assert.deepEqual(again.lineRules.map((r) => [r.classIndex, r.width, r.casing?.width ?? null]), [[1, 0.3, 0.1], [1, 0.5, null]], 'the line rules with it');
  });

  test('every problem of a style file is named in one error', () => {
    const bad = {
      classes: [
        { key: 'road', color: '#ffffff' }, { key: 'road', color: '#000000' }, { key: 'water', color: '#0000ff' },
        { key: 'bridge', color: '#999999', linear: true, network: 'water' }, { key: 'ferry', color: '#999999', linear: true, network: 'boat' },
        { key: 'pier', color: '#999999', network: 'bridge' },
      ],
      compatibility: { lake: { road: 0.5 }, road: { sea: 0.5 } },
    };
    assert.throws(() => parseStyle(bad, 'my-style.json'), (e: unknown) => {
      assert.ok(e instanceof InputError);
      assert.match(e.message, /^my-style.json: style: 6 problems:/);
      assert.match(e.message, /classes.bridge.network: names class "water", which is not linear/);
      assert.match(e.message, /classes.ferry.network: names unknown class "boat"/);
      assert.match(e.message, /classes.pier.network: only a linear class \(linear: true\) joins a line network/);
      assert.match(e.message, /classes: "road" is defined twice/);
      assert.match(e.message, /compatibility: names unknown class "lake"/);
      assert.match(e.message, /compatibility.road: names unknown class "sea"/);
      return true;
    });
    assert.throws(() => parseStyle({ background: 'white', classes: { a: { color: '#fff' } } }, 's.json'),
      /s.json: style: 2 problems:\n {2}background: must be a colour "#rrggbb"\n {2}classes.a.color: must be a colour "#rrggbb"/);
  });
});
