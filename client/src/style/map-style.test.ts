// Run-time styles: a whole style is checked against the schema and the cube's classes and comes
// out in the cube's order; one class's change leaves the others and the old style alone; every
// mistake is named.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { parseMapStyle, StyleError, withClassStyle } from './map-style.js';

const cube = [{ key: 'road' }, { key: 'water' }, { key: '7' }];

describe('map style', () => {
  test('a style in another order, from an object, comes out in the cube class order', () => {
    const s = parseMapStyle({ background: '#EEEEEE', classes: { '7': { color: '#00FF00', label: 'grass' }, water: { color: '#0000ff', pattern: { kind: 'hatch', color: '#000080', maxScale: 5000 } }, road: { color: '#808080' } } }, cube);
    assert.deepEqual(s.classes.map((c) => [c.key, c.label, c.color]), [['road', 'road', '#808080'], ['water', 'water', '#0000ff'], ['7', 'grass', '#00ff00']]);
    assert.equal(s.background, '#eeeeee');
    assert.deepEqual(s.classes[1]!.pattern, { kind: 'hatch', color: '#000080', maxScale: 5000 });
  });

  test('a missing or foreign class, and bad values, are named', () => {
    assert.throws(() => parseMapStyle({ classes: { road: { color: '#808080' }, water: { color: '#0000ff' }, sand: { color: '#ffff00' } } }, cube), (e: Error) => {
      assert.ok(e instanceof StyleError);
      assert.match(e.message, /"7" is missing/);
      assert.match(e.message, /the cube has no "sand"/);
      return true;
    });
    assert.throws(() => parseMapStyle({ classes: { road: { color: 'grey' }, water: { color: '#0000ff', pattern: { kind: 'waves', color: '#000000' } } } }, cube), /2 problems: classes\.road\.color: must be a colour "#rrggbb"; classes\.water\.pattern\.kind: must be hatch, dots or cross/);
    assert.throws(() => parseMapStyle('red', cube), /setStyle: /);
  });

  test('one class changes; the style it came from does not', () => {
    const before = parseMapStyle({ classes: [{ key: 'road', color: '#808080', pattern: { kind: 'dots', color: '#000000' } }, { key: 'water', color: '#0000ff' }, { key: 7, color: '#00ff00' }] }, cube);
    const after = withClassStyle(before, 'road', { color: '#FF0000', label: 'Road' });
    assert.deepEqual(after.classes[0], { key: 'road', label: 'Road', color: '#ff0000', weight: 1, linear: false, pattern: { kind: 'dots', color: '#000000' } });
    assert.deepEqual(after.classes.slice(1), before.classes.slice(1));
    assert.equal(before.classes[0]!.color, '#808080');
    const plain = withClassStyle(after, 'road', { pattern: null });
    assert.equal(plain.classes[0]!.pattern, undefined);
    const hatched = withClassStyle(plain, 'water', { pattern: { kind: 'hatch', color: '#FFFFFF' } });
    assert.deepEqual(hatched.classes[1]!.pattern, { kind: 'hatch', color: '#ffffff' });
  });

  test('an unknown class, an unknown key or a bad colour is an error naming it', () => {
    const s = parseMapStyle({ classes: { road: { color: '#808080' }, water: { color: '#0000ff' }, '7': { color: '#00ff00' } } }, cube);
    assert.throws(() => withClassStyle(s, 'sand', { color: '#ffff00' }), /setClassStyle: no class "sand" \(the classes: "road", "water", "7"\)/);
    assert.throws(() => withClassStyle(s, 'road', { colour: '#ffff00' }), /setClassStyle\("road"\): .*colour/);
    assert.throws(() => withClassStyle(s, 'road', { color: 'yellow' }), /setClassStyle\("road"\): color: must be a colour "#rrggbb"/);
    assert.throws(() => withClassStyle(s, 'road', { weight: 3 }), /weight/);
  });
});
