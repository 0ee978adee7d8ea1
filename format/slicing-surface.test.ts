// Slicing surfaces: z at hand-computed points for each kind, the clamp to the cube, the z
// range over a box, and the text form read back exactly.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { formatSurface, parseSurface, surfaceRange, surfaceZ, type Surface, type SurfaceSpec } from './slicing-surface.js';

describe('slicing surfaces', () => {
  test('z at points worked out by hand', () => {
    assert.equal(surfaceZ({ base: 50, spec: { kind: 'flat' } }, 3, 4, 100), 50);
    assert.equal(surfaceZ({ base: 50, spec: { kind: 'tilted', cx: 10, cy: 0, dzdx: 2, dzdy: -1 } }, 13, 5, 100), 50 + 6 - 5);
    // sine at angle 0: a quarter wavelength along x is the crest.
    assert.ok(Math.abs(surfaceZ({ base: 50, spec: { kind: 'sine', amplitude: 10, wavelength: 40, angle: 0 } }, 10, 99, 100) - 60) < 1e-9);
    // lens: full depth at the centre, (1 - 1/4)^2 of it half-way out, nothing at the rim.
    const lens = { base: 50, spec: { kind: 'lens', cx: 0, cy: 0, radius: 10, depth: 40 } } as const;
    assert.equal(surfaceZ(lens, 0, 0, 100), 10);
    assert.equal(surfaceZ(lens, 5, 0, 100), 50 - 40 * 0.75 * 0.75);
    assert.equal(surfaceZ(lens, 0, 10, 100), 50);
    // idw with power 2: at (1, 0) between points at (0, 0) z 0 and (3, 0) z 30, weights 1 and 1/4.
    const idw: Surface = { base: 50, spec: { kind: 'idw', power: 2, points: [{ x: 0, y: 0, z: 0 }, { x: 3, y: 0, z: 30 }] } };
    assert.ok(Math.abs(surfaceZ(idw, 1, 0, 100) - (0.25 * 30) / 1.25) < 1e-9);
    assert.equal(surfaceZ(idw, 3, 0, 100), 30, 'a control point keeps its own z');
  });

  test('z is clamped to the cube', () => {
    const steep = { base: 50, spec: { kind: 'tilted', cx: 0, cy: 0, dzdx: 100, dzdy: 0 } } as const;
    assert.equal(surfaceZ(steep, 1, 0, 120), 120);
    assert.equal(surfaceZ(steep, -1, 0, 120), 0);
  });

  test('the z range over a box holds every z inside it', () => {
    const s = { base: 50, spec: { kind: 'tilted', cx: 0, cy: 0, dzdx: 1, dzdy: 2 } } as const;
    const [lo, hi] = surfaceRange(s, [0, 0, 10, 10], 1000);
    for (let x = 0; x <= 10; x += 2.5) for (let y = 0; y <= 10; y += 2.5) {
      const z = surfaceZ(s, x, y, 1000);
      assert.ok(lo <= z && z <= hi, `${z} outside [${lo}, ${hi}]`);
    }
    assert.equal(lo, 50);
    assert.equal(hi, 80);
  });

  test('a surface written as text reads back the same', () => {
    const specs: SurfaceSpec[] = [
      { kind: 'flat' },
      { kind: 'tilted', cx: 181300.5, cy: 457000.25, dzdx: 0.9, dzdy: -0.4 },
      { kind: 'sine', amplitude: 150, wavelength: 130, angle: 30 },
      { kind: 'lens', cx: 181250, cy: 457100, radius: 140, depth: 370 },
      { kind: 'idw', power: 2, points: [{ x: 181143.2, y: 456911.36, z: 10 }, { x: 0.1 + 0.2, y: 1e-7, z: 300 }] },
    ];
    for (const spec of specs) assert.deepEqual(parseSurface(formatSurface(spec)), spec);
    assert.equal(formatSurface({ kind: 'lens', cx: 1, cy: 2, radius: 3, depth: 4 }), 'lens:cx=1,cy=2,radius=3,depth=4');
  });

  test('bad text is refused with what is wrong', () => {
    assert.throws(() => parseSurface('lens:cx=1,cy=2,radius=3'), /depth/);
    assert.throws(() => parseSurface('lens:cx=1,cy=2,radius=3,depth=4,width=2'), /unknown key "width"/);
    assert.throws(() => parseSurface('cone'), /cone/);
  });
});
