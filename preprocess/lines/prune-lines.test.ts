// Pruning over scale: a hand-drawn network of two loops joined by a short bridge, with a
// spur; the density rule on hand-made lines and scales; the 400 m cut of Otterlo.
//
//   (0,100) --a3-- (100,100) -X- (120,100) ----b1---- (220,100)
//      |               |             \                 /
//     a4              a2              b3            b2
//      |               |               \            /
//   (0,0) ---a1--- (100,0)              (170,150)     (b2, b3 go up to it)
//     /
//    S (150 m, to (-90,-120))
import test from 'node:test';
import assert from 'node:assert/strict';
import type { ScaleInfo } from '../../format/scale.js';
import { generalizeFile } from '../pipeline.js';
import { loadStyle } from '../style.js';
import { dataset, styleFile } from '../../testing/paths.js';
import { fixtureStyle, fixtureTgap, ROAD_T } from '../../testing/planar-fixtures.js';
import { collapseLines, type LineJoin, type LineObject } from './collapse-lines.js';
import { lineBudget, mapDensity } from './line-budget.js';
import { lineComponents, mainPiece } from './line-components.js';
import { pruneLines, pruneOrder } from './prune-lines.js';

type Shape = Pick<LineObject, 'step' | 'length' | 'paths' | 'joins'>;

/** Straight lines from one point to the next, born at `steps`; joins where an end meets another line's end. */
function handLines(coords: number[][], steps: number[]): Shape[] {
  const paths = coords.map((c) => Float64Array.from(c));
  const endsOf = (p: Float64Array): string[] => [`${p[0]},${p[1]}`, `${p[p.length - 2]},${p[p.length - 1]}`];
  return paths.map((p, i) => {
    const joins: LineJoin[] = [];
    for (const e of endsOf(p)) {
      paths.forEach((q, k) => {
        if (k === i || !endsOf(q).includes(e)) return;
        const [x, y] = e.split(',').map(Number) as [number, number];
        joins.push({ x, y, line: k, bridge: false });
      });
    }
    let length = 0;
    for (let k = 2; k < p.length; k += 2) length += Math.hypot(p[k]! - p[k - 2]!, p[k + 1]! - p[k - 1]!);
    return { step: steps[i]!, length, paths: [p], joins };
  });
}

const NETWORK = ['a1', 'a2', 'a3', 'a4', 'X', 'b1', 'b2', 'b3', 'S'];
const NETWORK_COORDS = [
  [0, 0, 100, 0], [100, 0, 100, 100], [100, 100, 0, 100], [0, 100, 0, 0], // loop A
  [100, 100, 120, 100], // the bridge X, 20 m: the least important line
  [120, 100, 220, 100], [220, 100, 170, 150], [170, 150, 120, 100], // loop B: 100, 70.7, 70.7 m
  [0, 0, -90, -120], // the spur S, 150 m
];

test('a spur goes before loop edges, a bridge only once one side is gone, whatever their importance', () => {
  const lines = handLines(NETWORK_COORDS, NETWORK.map(() => 1));
  const total = lines.reduce((s, l) => s + l.length, 0);
  // A budget that holds everything until state 10, then a metre less at every state: one line
  // goes at a time, at distinct states.
  const budget = Float64Array.from({ length: 1300 }, (_, s) => Math.max(0, total + 10 - s));
  const { prunedStep, stats } = pruneOrder(lines, { importance: lines.map((l) => l.length), budget });
  const order = [...NETWORK.keys()].sort((a, b) => prunedStep[a]! - prunedStep[b]!).map((i) => NETWORK[i]);
  // S dangles (a free end), so it goes first although it is the longest. Then the least
  // important loop edge (b2, the first of two equal ones); b3 and b1 then dangle. X, the least
  // important of all, stays while it joins the two sides, and goes as soon as it dangles.
  assert.deepEqual(order, ['S', 'b2', 'b3', 'b1', 'X', 'a1', 'a2', 'a3', 'a4']);
  assert.equal(new Set(prunedStep).size, NETWORK.length, 'one line at a time');
  assert.deepEqual(stats, { pruned: 9, prunedAtBirth: 0, toTop: 0, statesOverBudget: 0 });

  for (let s = 0; s < budget.length; s++) {
    const shown = lines.filter((l, i) => l.step <= s && prunedStep[i]! > s);
    const length = shown.reduce((sum, l) => sum + l.length, 0);
    assert.ok(length <= budget[s]!, `state ${s}: ${length} m shown over a budget of ${budget[s]} m`);
    assert.ok(lineComponents(shown.flatMap((l) => l.paths)) <= 1, `state ${s}: the network came apart`);
  }
});

test('a free end at the edge of the data is no dead end: the spur that leaves the map stays to the last', () => {
  const lines = handLines(NETWORK_COORDS, NETWORK.map(() => 1));
  const total = lines.reduce((sum, l) => sum + l.length, 0);
  const budget = Float64Array.from({ length: 1300 }, (_, s) => Math.max(0, total + 10 - s));
  const atEdge = NETWORK.map((name) => (name === 'S' ? 1 : 0));
  const { prunedStep } = pruneOrder(lines, { importance: lines.map((l) => l.length), budget, atEdge });
  const order = [...NETWORK.keys()].sort((a, b) => prunedStep[a]! - prunedStep[b]!).map((i) => NETWORK[i]);
  // Nothing dangles at first: loop B's shortest edge goes, B's rest and X dangle in turn. Then
  // loop A opens at a1; a2, a3, a4 dangle in turn, and S, hanging on a4, is the last line.
  assert.deepEqual(order, ['b2', 'b3', 'b1', 'X', 'a1', 'a2', 'a3', 'a4', 'S']);
});

test('between pieces importance decides: a small ring goes before the network\'s spur, a long ring after all of it', () => {
  // Two closed rings apart from the network (no free end): 40 m and 400 m.
  const small = [500, 0, 510, 0, 510, 10, 500, 10, 500, 0];
  const large = [600, 0, 700, 0, 700, 100, 600, 100, 600, 0];
  const names = [...NETWORK, 'small ring', 'large ring'];
  const lines = handLines([...NETWORK_COORDS, small, large], names.map(() => 1));
  const total = lines.reduce((sum, l) => sum + l.length, 0);
  const budget = Float64Array.from({ length: 1800 }, (_, s) => Math.max(0, total + 10 - s));
  const { prunedStep } = pruneOrder(lines, { importance: lines.map((l) => l.length), budget });
  const order = [...names.keys()].sort((a, b) => prunedStep[a]! - prunedStep[b]!).map((i) => names[i]);
  // The network offers S first (its only dangling end, 150 m): the small ring (40 m) is less
  // important and goes before it; the large ring outweighs every line the network offers.
  assert.deepEqual(order, ['small ring', 'S', 'b2', 'b3', 'b1', 'X', 'a1', 'a2', 'a3', 'a4', 'large ring']);
});

test('a line that joins parts not yet born holds, even when the budget wants everything gone', () => {
  // Only X is born at step 1; both loops and the spur are areas until step 5, and X may not cut
  // them apart.
  const lines = handLines(NETWORK_COORDS, NETWORK.map((n) => (n === 'X' ? 1 : 5)));
  const budget = new Float64Array(8); // nothing allowed at any state
  const { prunedStep, stats } = pruneOrder(lines, { importance: lines.map((l) => l.length), budget });
  assert.deepEqual([...prunedStep], NETWORK.map(() => 5), 'X stays until the rest is born, then everything goes');
  assert.equal(stats.statesOverBudget, 4, 'states 1 to 4 keep X over budget');
  assert.equal(stats.prunedAtBirth, 8, 'all but X went the state they were born in');
});

test('density: the base scale\'s line length per map area held over scale, the least important first', () => {
  // 1 km x 1 km, base 1:1,000; faces alive per step give the scales 1:1,000, 1:1,250, 1:2,000,
  // 1:2,500, 1:5,000, 1:10,000 (S = 1000 sqrt(100 / faces)).
  const info: ScaleInfo = { baseScale: 1000, baseFaces: 100, scaleTable: [[0, 100], [1, 64], [2, 25], [3, 16], [4, 4], [5, 1]], zMax: 5 };
  // Four separate lines: 400 and 300 m born at step 1, 200 m at step 2, 90 m at step 3 with
  // five times the weight of the others.
  const lines = handLines([[0, 0, 400, 0], [0, 10, 300, 10], [0, 20, 200, 20], [0, 30, 90, 30]], [1, 1, 2, 3]);
  const weight = [1, 1, 1, 5];
  // 1,000 m at 1:1,000 is 1,000 mm of map over 1,000 x 1,000 mm of map.
  const density = mapDensity(1000, 1e6, 1000);
  assert.equal(density, 1000 / 1e6);
  const budget = lineBudget(info, 5, 1e6, density);
  [1000, 800, 500, 400, 200, 100].forEach((b, s) => assert.ok(Math.abs(budget[s]! - b) < 1e-9, `state ${s}: budget ${budget[s]}, expected ${b}`));
  const { prunedStep, stats } = pruneOrder(lines, { importance: lines.map((l, i) => l.length * weight[i]!), budget });
  // State 1: 700 m of 800. State 2: 900 of 500, the 200 then the 300 go. State 3: 490 of 400,
  // the 400 (importance 400) goes before the 90 (importance 450). States 4, 5: 90 m fits.
  assert.deepEqual([...prunedStep], [3, 2, 2, 6]);
  assert.equal(stats.toTop, 1);
  assert.equal(stats.prunedAtBirth, 1, 'the 200 m line went at the step it was born');
});

test('pruning takes from the networks over their share of the budget, however important their lines', () => {
  // Network A: two 100 m lines of importance 1000 and 1001; network B: two 20 m lines of
  // importance 10 and 11; each network has half the budget. At state 1 the budget is 150 m:
  // A holds 200 m of its 75, B 40 m of its 75, so A's less important line goes, and B keeps its
  // lines although they are less important than A's.
  const lines = handLines([[0, 0, 100, 0], [0, 10, 100, 10], [0, 20, 20, 20], [0, 30, 20, 30]], [0, 0, 0, 0]);
  const importance = [1000, 1001, 10, 11];
  const budget = Float64Array.of(240, 150);
  const shared = pruneOrder(lines, { importance, budget, network: [0, 0, 1, 1], share: [0.5, 0.5] });
  assert.deepEqual([...shared.prunedStep], [1, 2, 2, 2]);
  // One budget for all: the least important go first, B's two lines, then A's first.
  assert.deepEqual([...pruneOrder(lines, { importance, budget }).prunedStep], [1, 2, 1, 1]);
});

test('pruneLines on a generalized T of roads: prune steps inside the tGAP, bad lines named', () => {
  const style = fixtureStyle([{ key: 'road', linear: true }, { key: 'field', weight: 4 }]);
  const tgap = fixtureTgap(ROAD_T, ['road', 'field'], style);
  const { lines } = collapseLines(tgap, style);
  const out = pruneLines(lines, tgap, style);
  assert.equal(out.lines.length, 3);
  const top = tgap.meta.steps + 1;
  for (const l of out.lines) assert.ok(l.prunedStep >= l.step && l.prunedStep <= top, `line of face ${l.face}: [${l.step}, ${l.prunedStep}) outside [1, ${top}]`);
  const [x0, y0, x1, y1] = tgap.meta.extent;
  assert.equal(out.density, mapDensity(lines.reduce((s, l) => s + l.length, 0), (x1 - x0) * (y1 - y0), tgap.meta.baseScale));
  const withBad = (change: Partial<LineObject>): LineObject[] => [lines[0]!, { ...lines[1]!, ...change }];
  assert.throws(() => pruneLines(withBad({ step: top }), tgap, style), new RegExp(`line 1 \\(face ${lines[1]!.face}, feature #${lines[1]!.feature}\\): step ${top} is not a step of the tGAP`));
  assert.throws(() => pruneLines(withBad({ length: NaN }), tgap, style), /line 1 .*: length NaN is not a number >= 0/);
  assert.throws(() => pruneLines(withBad({ classIndex: 7 }), tgap, style), /line 1 .*: class 7 is not in the style \(2 classes\)/);
});

test('bgt_otterlo_400m: the main road network is one piece at every step roads are shown; lines within budget and the cube', async () => {
  const styleName = styleFile('bgt.json');
  const { tgap } = await generalizeFile(dataset('bgt_otterlo_400m.geojson'), { style: styleName });
  const style = await loadStyle(styleName);
  const { lines } = collapseLines(tgap, style);
  const out = pruneLines(lines, tgap, style);
  const top = tgap.meta.steps + 1;
  assert.ok(out.stats.pruned > lines.length / 2, `${out.stats.pruned} of ${lines.length} lines pruned`);
  for (const l of out.lines) assert.ok(l.step <= l.prunedStep && l.prunedStep <= top, `face ${l.face}: [${l.step}, ${l.prunedStep})`);

  // The main road network: the longest piece of all road lines, joined where they share a point.
  const road = style.classes.findIndex((c) => c.key === 'wegdeel');
  const main = mainPiece(out.lines.filter((l) => l.classIndex === road));
  assert.ok(main.length > 30, `${main.length} lines in the main road network`);

  let shownStates = 0;
  for (let s = 0; s <= tgap.meta.steps; s++) {
    // Lines shown, and lines not yet born: their areas still carry the network.
    const shown = main.filter((l) => l.step <= s && l.prunedStep > s);
    if (shown.length === 0) continue;
    shownStates++;
    const network = main.filter((l) => l.prunedStep > s);
    assert.equal(lineComponents(network.map((l) => l.paths.flatMap((p) => [...p]))), 1, `state ${s}: the main road network is in pieces`);
    const length = out.lines.filter((l) => l.step <= s && l.prunedStep > s).reduce((sum, l) => sum + l.length, 0);
    assert.ok(length <= out.budget[s]! + 1e-6, `state ${s}: ${length} m of lines over a budget of ${out.budget[s]} m`);
  }
  assert.ok(shownStates > 100, `roads shown at ${shownStates} states`);

  assert.deepEqual(pruneLines(lines, tgap, style), out, 'the same lines give the same prune steps');
});
