// The style schema: the bundled styles pass, classes come out in order with their defaults,
// and a style with several problems has each one named by its path.
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { describe, test } from 'node:test';
import * as v from 'valibot';
import { styleFile } from '../testing/paths.js';
import { describeIssues } from './schema-issues.js';
import { MAX_LINE_RULES } from './line-style.js';
import { drawnStyle, styleClasses, StyleSchema } from './style.js';

describe('style', () => {
  test('the bundled styles are valid', () => {
    for (const name of ['bgt.json', 'nlcd.json', 'as18.json']) {
      const json: unknown = JSON.parse(readFileSync(styleFile(name), 'utf8'));
      const r = v.safeParse(StyleSchema, json);
      assert.ok(r.success, `${name}: ${r.success ? '' : describeIssues(r.issues).join('; ')}`);
    }
  });

  test('classes in order, with defaults, from an object or a keyed array', () => {
    const fromObject = v.parse(StyleSchema, { classes: { road: { color: '#FFFFFF', linear: true, weight: 1.5 }, '7': { color: '#00ff00', label: 'grass' } } });
    // A JSON object puts integer-like keys first: that is why arrays are allowed too.
    assert.deepEqual(styleClasses(fromObject).map((c) => c.key), ['7', 'road']);
    const fromArray = v.parse(StyleSchema, { classes: [{ key: 'road', color: '#FFFFFF', linear: true, weight: 1.5 }, { key: 7, color: '#00ff00', label: 'grass' }] });
    assert.deepEqual(styleClasses(fromArray), [
      { key: 'road', label: 'road', color: '#ffffff', weight: 1.5, linear: true },
      { key: '7', label: 'grass', color: '#00ff00', weight: 1, linear: false },
    ]);
    assert.equal(fromArray.name, 'unnamed');
    assert.equal(fromArray.resolutionMm, 0.28);
    assert.equal(fromArray.defaultCompatibility, 0.5);
    assert.equal(fromArray.background, '#ffffff');
  });

  test('every problem of a style is named by its path', () => {
    const r = v.safeParse(StyleSchema, {
      baseScale: 0.5,
      defaultCompatibility: 2,
      classes: { road: { color: 'grey', weight: 0 }, water: { color: '#0000ff', pattern: { kind: 'waves', color: '#0000ff' } } },
      compatibility: { road: { water: 'yes' } },
    });
    assert.ok(!r.success);
    assert.deepEqual(describeIssues(r.issues).sort(), [
      'baseScale: must be a number >= 1 (or 0: chosen from the data)',
      'classes.road.color: must be a colour "#rrggbb"',
      'classes.road.weight: must be a positive number',
      'classes.water.pattern.kind: must be hatch, dots or cross',
      'compatibility.road.water: must be a number',
      'defaultCompatibility: must be in [0, 1]',
    ]);
  });

  test('a style with more line rules than the map draws is refused, naming how many it has', () => {
    const road = (n: number) => ({ color: '#808080', linear: true, line: { width: 1, by: 'kind', rules: Array.from({ length: n }, (_, i) => ({ values: [i], width: 2 })) } });
    // 1 + 126 rules: the most there may be.
    const most = v.safeParse(StyleSchema, { classes: { road: road(126) } });
    assert.ok(most.success && drawnStyle(most.output).lines.length === MAX_LINE_RULES);
    const over = v.safeParse(StyleSchema, { classes: [{ key: 'road', ...road(126) }, { key: 'rail', ...road(0) }] });
    assert.ok(!over.success);
    assert.deepEqual(describeIssues(over.issues), [`classes: has 128 line rules (each class's line and each of its rules), more than the map draws (${MAX_LINE_RULES})`]);
  });

  test('no classes at all is refused', () => {
    for (const classes of [undefined, {}, [], 'road']) {
      const r = v.safeParse(StyleSchema, { classes });
      assert.ok(!r.success && describeIssues(r.issues).some((m) => m.startsWith('classes')), JSON.stringify(classes));
    }
  });
});
