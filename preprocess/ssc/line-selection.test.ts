// Which lines the build keeps over scale, on bgt_otterlo_1800m with styles/bgt.json, as a
// cartographer would check a topographic map: the main road (klasse "rijbaan regionale weg",
// the heaviest rule) runs through the village down to 1:25,000, where the streets have gone,
// and the watercourses (their own network and share of the line budget) are still drawn at
// 1:5,000 and 1:10,000 beside the roads. Before strokes and shares, the main road was cut into
// short unimportant pieces and eaten from the data's edge in, and water lost its budget to roads.
import assert from 'node:assert/strict';
import test from 'node:test';
import { zAtScale } from '../../format/scale.js';
import { scaleInfoOf } from '../../format/tgap-model.js';
import { dataset, styleFile } from '../../testing/paths.js';
import { generalizeFile } from '../pipeline.js';
import { loadStyle } from '../style.js';
import { generalizedLines } from './cube-lines.js';

test('bgt_otterlo_1800m: the main road stays to 1:25,000 and the watercourses to 1:10,000', async () => {
  const styleName = styleFile('bgt.json');
  const { tgap } = await generalizeFile(dataset('bgt_otterlo_1800m.geojson'), { style: styleName });
  const style = await loadStyle(styleName);
  const { simplified: { lines }, rules } = generalizedLines(tgap, style);
  const info = scaleInfoOf(tgap);
  const ruleOf = (key: string, value: string): number => style.lineRules.findIndex((r) => style.classes[r.classIndex]!.key === key && (r.values ?? []).includes(value));
  const main = ruleOf('wegdeel', 'rijbaan regionale weg'), street = ruleOf('wegdeel', 'rijbaan lokale weg'), water = ruleOf('waterdeel', 'waterloop');
  /** Metres of line of `rule` shown at 1:scale. */
  const km = (rule: number, scale: number): number => {
    const s = Math.floor(zAtScale(info, scale));
    return lines.reduce((sum, l, i) => sum + (rules[i] === rule && l.step <= s && s < l.prunedStep ? l.length : 0), 0) / 1000;
  };
  for (const scale of [5000, 10000, 25000]) assert.ok(km(main, scale) > 2, `1:${scale}: ${km(main, scale).toFixed(2)} km of main road`);
  assert.ok(km(main, 25000) > km(street, 25000), `1:25,000: more main road (${km(main, 25000).toFixed(2)} km) than streets (${km(street, 25000).toFixed(2)} km)`);
  for (const scale of [5000, 10000]) assert.ok(km(water, scale) > 1, `1:${scale}: ${km(water, scale).toFixed(2)} km of watercourse`);
});
