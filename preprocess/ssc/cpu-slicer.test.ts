// The CPU reference slicer on hand-made triangles: which surface a pixel shows, and how many
// triangles lie over it at or below the slice (the ID pass's fragments, its overdraw).
import test from 'node:test';
import assert from 'node:assert/strict';
import { CpuSlicer } from './cpu-slicer.js';

// 4 x 2 pixels over [0,4] x [0,2]: pixel centres at x = 0.5 .. 3.5, y = 1.5 (row 0), 0.5 (row 1).
const view = { width: 4, height: 2, bbox: [0, 0, 4, 2] as [number, number, number, number] };
/** The square [x0, x1] x [0, 2] as two counterclockwise triangles at z, of face f. */
function square(sl: CpuSlicer, x0: number, x1: number, z: number | [number, number], f: number): void {
  const [za, zb] = typeof z === 'number' ? [z, z] : z;
  sl.triangle(x0, 0, za, x1, 0, zb, x1, 2, zb, f, 0, f);
  sl.triangle(x0, 0, za, x1, 2, zb, x0, 2, za, f, 0, f);
}

test('the nearest surface at or below the slice gives the pixel its face; every one at or below it is a fragment', () => {
  const sl = new CpuSlicer(view, () => 5, true);
  square(sl, 0, 4, 0, 1); // the floor everywhere
  square(sl, 0, 2, 3, 2); // a merge over the left half, below the slice
  square(sl, 1, 4, 7, 3); // above the slice: never shown, no fragment
  square(sl, 3, 4, [4, 6], 4); // tilted in x from 4 to 6: below the slice left of x = 3.5 only
  // The pixel centre at x = 3.5 meets the tilted square at z 5, at the slice: kept, shown.
  assert.deepEqual(Array.from(sl.ids), [2, 2, 1, 4, 2, 2, 1, 4]);
  assert.deepEqual(Array.from(sl.fragments!), [2, 2, 1, 2, 2, 2, 1, 2]);
  // Nothing but the fragment count depends on counting.
  const plain = new CpuSlicer(view, () => 5);
  square(plain, 0, 4, 0, 1);
  square(plain, 0, 2, 3, 2);
  square(plain, 1, 4, 7, 3);
  square(plain, 3, 4, [4, 6], 4);
  assert.deepEqual(plain.ids, sl.ids);
  assert.deepEqual(plain.depth, sl.depth);
});

test('without countFragments there is no count', () => {
  assert.equal(new CpuSlicer(view, () => 0).fragments, null);
});
