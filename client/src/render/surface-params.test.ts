// The GPU's surface formulas, rewritten around the view centre, against format/slicing-surface.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { flatSliceZ, relativeZ, surfaceParams } from './surface-params.js';
import { surfaceZ, type SurfaceSpec } from '../../../format/slicing-surface.js';

describe('surfaces around the view centre (the GPU formulas)', () => {
  // A view centre on the Dutch national grid, where float32 alone would lose centimetres.
  const cx = 181282.695, cy = 457031.109;
  const specs: SurfaceSpec[] = [
    { kind: 'flat' },
    { kind: 'tilted', cx: 181300.5, cy: 457000.25, dzdx: 0.9, dzdy: -0.4 },
    { kind: 'sine', amplitude: 150, wavelength: 130, angle: 30 },
    { kind: 'lens', cx: 181250, cy: 457100, radius: 140, depth: 370 },
    { kind: 'idw', power: 2, points: [{ x: 181143.2, y: 456911.36, z: 10 }, { x: 181392.7, y: 456951.1, z: 300 }, { x: 181282.7, y: 457181.1, z: 150 }] },
  ];
  for (const spec of specs) {
    test(`${spec.kind}: the same z as surfaces.ts`, () => {
      const s = { base: 220, spec };
      const p = surfaceParams(s, cx, cy);
      let worst = 0;
      for (let k = 0; k < 500; k++) {
        const dx = ((k * 7919) % 401) - 200.3, dy = ((k * 104729) % 397) - 198.7;
        const want = surfaceZ(s, cx + dx, cy + dy, 1e9);
        // surfaceZ clamps to [0, zMax] (the shader too, after relativeZ).
        worst = Math.max(worst, Math.abs(Math.max(0, relativeZ(p, dx, dy)) - want));
      }
      // idw points travel as float32 offsets from the centre: a few micrometres.
      assert.ok(worst < 1e-4, `largest difference ${worst}`);
    });
  }

  test('a flat slice\'s one z is what the surface target holds there (clamped, float32); other surfaces have none', () => {
    for (const [base, want] of [[220.3, Math.fround(220.3)], [-4, 0], [1e9 + 5, Math.fround(1e9)]] as const) {
      const s = { base, spec: { kind: 'flat' } as const };
      assert.equal(flatSliceZ(s, 1e9), want);
      assert.equal(flatSliceZ(s, 1e9), Math.fround(surfaceZ(s, cx, cy, 1e9)));
    }
    for (const spec of specs.slice(1)) assert.equal(flatSliceZ({ base: 220, spec }, 1e9), null);
  });
});
