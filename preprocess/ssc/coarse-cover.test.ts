// nlcd_zion's smooth cube, sliced whole at the coarse scales as the map gets it (the surfaces
// the build makes, in a chunk on the coarsest grid the build may choose): every pixel inside the
// data shows a face alive at that z. Slivers that a face kept showing for a winner soon to give
// them back (removals left out) must end up in some face's surfaces, and a ramp's chord
// midpoints must not leave lines that other surfaces meet: a chunk puts them on its grid. Where
// either failed, the map showed a face that had ended, and then nothing (its chunk no longer
// fetched): 94 and 71 pixels of 48 whole-extent views of 1280x720. bgt_otterlo_400m is checked
// the same way in e2e/pipeline-cube.
import test from 'node:test';
import assert from 'node:assert/strict';
import { decodeChunk } from '../../format/chunk.js';
import { faceAliveAt } from '../../format/tgap-model.js';
import { generalizedDataset } from '../../testing/generalized-dataset.js';
import { tempDir } from '../../testing/temp-dir.js';
import { fitView } from '../map/rasterize.js';
import { assembleChunk } from './assemble-chunk.js';
import { coarsestCubeGrid } from './build-cube.js';
import { CpuSlicer, sliceChunk } from './cpu-slicer.js';
import { buildSurfaces } from './surfaces.js';

const W = 640, H = 360;

test('nlcd_zion: at 24 z over the coarser half of the cube, every pixel of the whole extent inside the data shows a face alive there', async (t) => {
  const { tgap } = await generalizedDataset(tempDir(t), 'nlcd_zion.geojson.gz', 'nlcd.json');
  const grid = coarsestCubeGrid(tgap);
  const { surfaces: s, tgap: cube, stats } = buildSurfaces(tgap, { smooth: true, snapStep: 2 ** grid });
  const steps = cube.meta.steps;
  const all = Uint32Array.from({ length: s.count }, (_, i) => i);
  const chunk = await decodeChunk(assembleChunk(s, all, s.xs, s.ys, (f) => cube.faces[f]!.classIndex, grid).bytes);
  assert.equal(chunk.gridExponent, grid);
  const view = fitView(cube.meta.extent, W, H);
  const zs = Array.from({ length: 24 }, (_, k) => steps / 2 + ((k + 1) * steps) / 2 / 25);
  // Every triangle at or below the slice, as the slicer keeps the nearest: one whose face has
  // ended shows only where nothing newer covers it (the map's chunks leave it out from there).
  const slice = (z: number): Uint32Array => {
    const sl = new CpuSlicer(view, () => z);
    sliceChunk(sl, chunk);
    return sl.ids;
  };
  const alive = (f: number, z: number): boolean => f > 0 && faceAliveAt(cube.faces[f]!, z, steps);
  const base = slice(0);
  const wrong: string[] = [];
  let pixels = 0;
  for (const z of zs) {
    const ids = slice(z);
    for (let p = 0; p < ids.length; p++) {
      if (base[p] === 0) continue; // outside the data
      pixels++;
      if (!alive(ids[p]!, z)) wrong.push(`z ${z.toFixed(1)}: pixel ${p % W},${Math.floor(p / W)} shows face ${ids[p]}`);
    }
  }
  assert.ok(pixels > 0.3 * W * H * zs.length, `${pixels} pixels inside the data`);
  assert.deepEqual(wrong.slice(0, 10), [], `${wrong.length} pixels show no face alive`);
  // The path that hands such slivers on runs here.
  assert.ok(stats.sliversHandedOn > 0, `${stats.sliversHandedOn} slivers handed on`);
});
