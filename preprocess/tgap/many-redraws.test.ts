// Few faces with many vertices: their wavy boundaries are redrawn step after step, and every
// redraw of a face takes a new face id. No face count bounds those ids (a real land-cover
// extract of 136 faces outgrew a table of 2 x faces + 16 and crashed).
import test from 'node:test';
import assert from 'node:assert/strict';
import type { InputFeature } from '../io/read-input.js';
import { defaultStyle } from '../style.js';
import { buildTopology } from '../topology/build-topology.js';
import { generalize } from './generalize.js';

/** k strips 1000 x 1000 side by side; the boundary between strips i-1 and i waves with n points. */
function wavyStrips(k: number, n: number): InputFeature[] {
  const bx = (i: number, y: number): number => (i === 0 || i === k ? i * 1000 : i * 1000 + 30 * Math.sin(y * (0.05 + i * 0.01)));
  const ys = Array.from({ length: n + 1 }, (_, j) => (1000 * j) / n);
  return Array.from({ length: k }, (_, i) => {
    const ring = [...ys.map((y) => [bx(i + 1, y), y]), ...ys.map((y) => [bx(i, y), y]).reverse()];
    return { ref: { index: i, id: `strip${i}` }, properties: {}, polygons: [[Float64Array.from(ring.flat())]] };
  });
}

/**
 * A k x k grid of 1000 x 1000 cells whose sides wave (n points each, amplitude 20, fixed at
 * the corners so that neighbours share them).
 */
function wavyGrid(k: number, n: number): InputFeature[] {
  const wave = (t: number, line: number): number => 20 * Math.sin((Math.PI * t * (1 + (line % 3))) / 1000);
  const side = (p: (u: number) => [number, number]): number[] => Array.from({ length: n }, (_, j) => p((1000 * j) / n)).flat();
  const out: InputFeature[] = [];
  for (let i = 0; i < k; i++) {
    for (let j = 0; j < k; j++) {
      const x0 = i * 1000, y0 = j * 1000;
      // Horizontal line j at x: y0 + wave(x - x0); vertical line i at y: x0 + wave(y - y0).
      const h = (line: number, u: number): [number, number] => [x0 + u, line * 1000 + (line === 0 || line === k ? 0 : wave(u, line))];
      const v = (line: number, u: number): [number, number] => [line * 1000 + (line === 0 || line === k ? 0 : wave(u, line + 1)), y0 + u];
      const ring = [...side((u) => h(j, u)), ...side((u) => v(i + 1, u)), ...side((u) => h(j + 1, 1000 - u)), ...side((u) => v(i, 1000 - u))];
      out.push({ ref: { index: out.length, id: `c${i}-${j}` }, properties: {}, polygons: [[Float64Array.from(ring)]] });
    }
  }
  return out;
}

function run(features: InputFeature[], reemit: { reemitFactor?: number; reemitSlack?: number }): { ids: number; faces: number; steps: number } {
  const topo = buildTopology(features, { precision: 0.001 });
  const g = generalize(topo, () => 0, defaultStyle(['all'], null), { baseScale: 1000, resolutionMm: 0.2, ...reemit });
  assert.equal(g.facesAlive[g.facesAlive.length - 1], 1, 'merged down to one face');
  return { ids: g.faces.length, faces: topo.faceCount - 1, steps: g.facesAlive.length - 1 };
}

test('three faces of 3000 vertices each are generalized to one', () => {
  const r = run(wavyStrips(3, 3000), {});
  assert.equal(r.faces, 3);
  assert.equal(r.steps, 2);
});

test('a face redrawn at every step: far more face ids than twice the faces, no crash', () => {
  // Any cost over the face's own size redraws it: every face an event or a simplification
  // touches takes a new id in every step.
  const r = run(wavyGrid(5, 50), { reemitFactor: 0, reemitSlack: 0 });
  assert.equal(r.faces, 25);
  assert.ok(r.ids > 2 * (r.faces + 1) + 16, `${r.ids} face ids`);
});
