// A face drawn again under a new id (a re-emit) shows nowhere after: over its whole former
// area, just after the re-emit, the smooth cube shows faces alive then. Slivers the face kept
// showing for a winner that was soon to give them back (removals left out) must go with it,
// or to the face that holds them once the winner no longer does.
import test from 'node:test';
import assert from 'node:assert/strict';
import { faceAliveAt, phaseZ, REEMIT_PHASE } from '../../format/tgap-model.js';
import { generalizedDataset } from '../../testing/generalized-dataset.js';
import { tempDir } from '../../testing/temp-dir.js';
import { CpuSlicer } from './cpu-slicer.js';
import { buildSurfaces } from './surfaces.js';

test('bgt_otterlo_400m: just after each re-emit, the face re-emitted shows nowhere in its former area, and every pixel there shows a face alive', async (t) => {
  const { tgap } = await generalizedDataset(tempDir(t), 'bgt_otterlo_400m.geojson', 'bgt.json');
  const { surfaces: s, tgap: cube, origins, stats } = buildSurfaces(tgap, { smooth: true });
  const steps = cube.meta.steps;
  const alive = (f: number, z: number): boolean => f > 0 && faceAliveAt(cube.faces[f]!, z, steps);
  const reemits = origins.filter((o) => o.kind === 'reemit');
  assert.ok(reemits.length > 20, `${reemits.length} re-emits`);
  let checked = 0;
  for (const o of reemits) {
    // The face's former area: the box of every triangle it was ever drawn with.
    let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
    for (let i = 0; i < s.count; i++) {
      if (s.upper[i] !== o.face) continue;
      for (let j = 0; j < 3; j++) {
        const v = s.v[3 * i + j]!;
        x0 = Math.min(x0, s.xs[v]!); x1 = Math.max(x1, s.xs[v]!);
        y0 = Math.min(y0, s.ys[v]!); y1 = Math.max(y1, s.ys[v]!);
      }
    }
    const z = phaseZ(o.step, REEMIT_PHASE) + 0.01;
    const view = { width: 120, height: 120, bbox: [x0, y0, x1, y1] as [number, number, number, number] };
    const at = new CpuSlicer(view, () => z), base = new CpuSlicer(view, () => 0);
    for (let i = 0; i < s.count; i++) {
      const [a, b, c] = [s.v[3 * i]!, s.v[3 * i + 1]!, s.v[3 * i + 2]!];
      const args = [s.xs[a]!, s.ys[a]!, s.z[3 * i]!, s.xs[b]!, s.ys[b]!, s.z[3 * i + 1]!, s.xs[c]!, s.ys[c]!, s.z[3 * i + 2]!] as const;
      at.triangle(...args, s.upper[i]!, s.lower[i]!);
      if (s.zMin[i] === 0) base.triangle(...args, s.upper[i]!, s.lower[i]!);
    }
    for (let p = 0; p < at.ids.length; p++) {
      if (base.ids[p] === 0) continue; // outside the data
      const f = at.ids[p]!;
      assert.ok(alive(f, z), `step ${o.step}, re-emit of ${o.face} as ${o.into}: (${at.cx(p % 120).toFixed(2)}, ${at.cy(Math.floor(p / 120)).toFixed(2)}) shows face ${f}, not alive at z ${z}`);
    }
    checked++;
  }
  assert.equal(checked, reemits.length);
  // The path that hands such slivers on runs here.
  assert.ok(stats.sliversHandedOn > 0, `${stats.sliversHandedOn} slivers handed on`);
});
