// The line style of a class: what a rule leaves out it takes from the line's defaults (colour
// from the class, weight from the class), rules are numbered in class order then rule order,
// a feature gets the rule listing its attribute's value, else the default, and a style with
// wrong line fields is refused with every problem named by its path.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import * as v from 'valibot';
import { lineRuleDrawnAt, lineRuleFinder, lineRules } from './line-style.js';
import { describeIssues } from './schema-issues.js';
import { drawnStyle, StyleSchema } from './style.js';

const style = {
  classes: {
    field: { color: '#00ff00' },
    road: {
      color: '#FAFAFA', weight: 1.5, linear: true,
      line: {
        width: 0.35, casing: { width: 0.1, color: '#8C8C8C' }, maxScale: 50000, by: 'klasse',
        rules: [
          { values: ['fietspad'], width: 0.25, color: '#D06A5A', casing: null, weight: 1 },
          { values: ['hoofdweg', 7], width: 0.7, color: '#f8c86a', minScale: 5000 },
        ],
      },
    },
    ditch: { color: '#9ec9e8', linear: true },
    river: { color: '#4A8FCF', weight: 2.5, linear: true, line: { width: 0.3 } },
  },
};

describe('line style', () => {
  test('rules in class order, each rule inheriting what it leaves out', () => {
    const rules = drawnStyle(v.parse(StyleSchema, style)).lines;
    assert.deepEqual(rules, [
      { classIndex: 1, by: null, values: null, width: 0.35, color: '#fafafa', casing: { width: 0.1, color: '#8c8c8c' }, weight: 1.5, maxScale: 50000 },
      { classIndex: 1, by: 'klasse', values: ['fietspad'], width: 0.25, color: '#d06a5a', casing: null, weight: 1, maxScale: 50000 },
      { classIndex: 1, by: 'klasse', values: ['hoofdweg', '7'], width: 0.7, color: '#f8c86a', casing: { width: 0.1, color: '#8c8c8c' }, weight: 1.5, minScale: 5000, maxScale: 50000 },
      { classIndex: 3, by: null, values: null, width: 0.3, color: '#4a8fcf', casing: null, weight: 2.5 },
    ]);
  });

  test('a feature gets the rule listing its value (as a string), else the class default; a class without line none', () => {
    const rules = lineRules(drawnStyle(v.parse(StyleSchema, style)).classes);
    const find = lineRuleFinder(rules);
    assert.equal(find(1, { klasse: 'fietspad' }), 1);
    assert.equal(find(1, { klasse: 'hoofdweg' }), 2);
    assert.equal(find(1, { klasse: 7 }), 2, 'a number matches its string');
    assert.equal(find(1, { klasse: 'voetpad' }), 0, 'a value no rule lists');
    assert.equal(find(1, {}), 0, 'no such attribute');
    assert.equal(find(1, null), 0, 'no feature');
    assert.equal(find(3, { klasse: 'fietspad' }), 3, 'a class without by');
    assert.equal(find(2, { klasse: 'fietspad' }), -1, 'a linear class without line');
    assert.equal(find(0, {}), -1, 'a class that is not linear');
  });

  test('a scale range holds its bounds', () => {
    const r = { minScale: 5000, maxScale: 50000 };
    assert.deepEqual([4999, 5000, 20000, 50000, 50001].map((s) => lineRuleDrawnAt(r, s)), [false, true, true, true, false]);
    assert.ok(lineRuleDrawnAt({}, 1e9));
  });

  test('every problem of the line fields is named by its path', () => {
    const r = v.safeParse(StyleSchema, {
      classes: {
        field: { color: '#00ff00', line: { width: 0.3 } },
        road: {
          color: '#ffffff', linear: true,
          line: {
            width: -1, colour: '#000000', casing: { width: 0, color: 'grey' }, minScale: 9000, maxScale: 8000, by: 'klasse',
            rules: [{ values: ['a', 'b'], maxScale: 100 }, { values: [], width: 0.2 }, { values: ['b'], weight: 0 }],
          },
        },
        water: { color: '#0000ff', linear: true, line: { width: 0.3, rules: [{ values: ['x'] }] } },
      },
    });
    assert.ok(!r.success);
    assert.deepEqual(describeIssues(r.issues).sort(), [
      'classes.field: line: only a linear class (linear: true) has lines',
      'classes.road.line.casing.color: must be a colour "#rrggbb"',
      'classes.road.line.casing.width: must be a number of mm > 0',
      'classes.road.line.colour: a line is an object of width, color, casing, minScale, maxScale, weight, by and rules',
      'classes.road.line.rules.1.values: is empty',
      'classes.road.line.rules.2.weight: must be a positive number',
      'classes.road.line.width: must be a number of mm >= 0',
      'classes.water.line: by and rules go together: the attribute and the rules for its values',
    ]);
    // Checks across fields run once the fields themselves are right.
    const r2 = v.safeParse(StyleSchema, {
      classes: {
        road: {
          color: '#ffffff', linear: true,
          line: { width: 0.3, minScale: 9000, maxScale: 8000, by: 'klasse', rules: [{ values: ['a', 'b'], maxScale: 10000 }, { values: ['b'], minScale: 1 }, { values: ['c'], minScale: 20000 }] },
        },
      },
    });
    assert.ok(!r2.success);
    assert.deepEqual(describeIssues(r2.issues), [
      'classes.road.line: minScale must not be above maxScale',
      'classes.road.line: rules[1]: value "b" is in rules[0] already',
      'classes.road.line: rules[2]: minScale must not be above maxScale',
    ]);
  });
});
