// Which lines the build keeps over scale, on bgt_otterlo_1800m with styles/bgt.json, as a
// cartographer would check a topographic map: the main road (klasse "rijbaan regionale weg",
// the heaviest rule) runs through the village down to 1:25,000, where the streets have gone,
// and the watercourses (their own network and share of the line budget) are still drawn at
// 1:5,000 and 1:10,000 beside the roads. Before strokes and shares, the main road was cut into
// short unimportant pieces and eaten from the data's edge in, and water lost its budget to roads.
// And the road network itself: at the base scale, 1:5k, 1:10k and 1:25k its main piece is one
// connected component (the lines shown, with the roads not yet collapsed, which are still areas).
import assert from 'node:assert/strict';
import test from 'node:test';
import { lineComponents, mainPiece } from '../lines/line-components.js';
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

test('bgt_otterlo_1800m: the main road network is one piece at the base scale, 1:5,000, 1:10,000 and 1:25,000', async (t) => {
  const styleName = styleFile('bgt.json');
  const { tgap } = await generalizeFile(dataset('bgt_otterlo_1800m.geojson'), { style: styleName });
  const style = await loadStyle(styleName);
  const { simplified: { lines }, pruned } = generalizedLines(tgap, style);
  const info = scaleInfoOf(tgap);
  const road = style.classes.findIndex((c) => c.key === 'wegdeel');
  const roads = lines.filter((l) => l.classIndex === road);
  // The longest piece of all road lines ever made, joined where they share a point: those
  // pruned the state they are born in too, which until then stand in for their areas.
  const main = mainPiece(pruned.lines.filter((l) => l.classIndex === road));
  assert.ok(main.length > 100, `${main.length} road lines in the main network`);
  let shownAt = 0;
  for (const scale of [info.baseScale, 5000, 10000, 25000]) {
    const s = Math.floor(zAtScale(info, scale));
    const shown = roads.filter((l) => l.step <= s && s < l.prunedStep);
    const pieces = shown.length > 0 ? lineComponents(shown.map((l) => l.paths.flatMap((p) => [...p]))) : 0;
    const km = shown.reduce((sum, l) => sum + l.length, 0) / 1000;
    t.diagnostic(`1:${scale}: ${shown.length} road lines, ${km.toFixed(2)} km, ${pieces} pieces`);
    if (!main.some((l) => l.step <= s && s < l.prunedStep)) continue;
    shownAt++;
    // Lines shown and lines not yet born (still areas, which carry the network) make one piece.
    const network = main.filter((l) => l.prunedStep > s);
    assert.equal(lineComponents(network.map((l) => l.paths.flatMap((p) => [...p]))), 1, `1:${scale}: the main road network is in pieces`);
  }
  assert.ok(shownAt >= 3, `the main road network shown at ${shownAt} of the four scales`);
});
