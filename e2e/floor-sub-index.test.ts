// A floor too large for index.json (its tree in sub-index files, as the build writes it for a
// large dataset): a first view at the floor has the map ask for the floor's sub-index files while
// the worker's script is still coming (the head start), then the floor chunks they list; the
// cube's own sub-index files wait for those. bgt_otterlo_400m in tiny chunks, whose floor tree
// does not fit a 2 kB index file.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { boxMeets } from '../format/index-query.js';
import { fitBbox, viewBbox, type Bbox } from '../client/src/geometry/view.js';
import { openMap } from './helpers/browser.js';
import { compareIds, cpuSlice } from './helpers/cube.js';
import { readIds, waitIdle } from './helpers/map-page.js';
import { useTestBed } from './helpers/test-bed.js';

const W = 640, H = 480;

describe('a floor whose tree is in sub-index files (bgt_otterlo_400m in tiny chunks)', () => {
  const bed = useTestBed(['--chunk-bytes', '4096', '--sub-index-bytes', '2048']);
  /** The worker's script, as the test page's build names it. */
  const worker = /^\/assets\/chunk-worker-[\w-]+\.js$/;

  test('at the floor the floor\'s sub-index files are asked for while the worker\'s script is still coming, each once; the floor chunks before the cube\'s sub-index files; the map equals the CPU slicer', async () => {
    const { contents, server } = bed;
    const floorRefs = contents.floorSubIndexFiles;
    assert.ok(floorRefs.length >= 2, `${floorRefs.length} floor sub-index files`);
    // The whole extent at the floor: every floor sub-index file and floor chunk is on screen.
    const bbox: Bbox = contents.meta.extent;
    const shown = viewBbox(fitBbox(bbox, W, H));
    const floorOnScreen = contents.floorLeaves.filter((l) => boxMeets(l.bbox, { ground: shown, zMin: 0, zMax: 0 })).map((l) => l.file);
    // The worker's script comes a second late, as its 33 kB gzip would on a slow phone network.
    server.faults.appDelayMs = (path) => (worker.test(path) ? 1000 : 0);
    const logStart = server.log.length;
    bed.page = await openMap(bed.browser, server.url, { source: 'cube/', bbox: bbox.join(','), z: 0, supersampling: 1 });
    assert.equal(await waitIdle(bed.page.page), true);
    const log = server.log.slice(logStart);
    const script = log.find((e) => worker.test(e.path));
    assert.ok(script && script.outcome === 200, 'the worker\'s script was served');
    for (const ref of floorRefs) {
      const asked = log.filter((e) => e.path === `/cube/${ref}`);
      assert.equal(asked.length, 1, `${ref} fetched once`);
      assert.ok(asked[0]!.start < script.end - 500, `${ref} asked for ${asked[0]!.start - script.start} ms after the worker's script was, which came after ${script.end - script.start} ms`);
    }
    // Each floor chunk on screen once, and all of them before any of the cube's sub-index files.
    const firstAsked = (file: string): number => log.findIndex((e) => e.path === `/cube/${file}`);
    for (const f of floorOnScreen) assert.equal(log.filter((e) => e.path === `/cube/${f}`).length, 1, `${f} fetched once`);
    const cubeSubs = contents.subIndexFiles.filter((s) => !floorRefs.includes(s)).map(firstAsked).filter((i) => i >= 0);
    const lastFloor = Math.max(...floorOnScreen.map(firstAsked));
    assert.ok(cubeSubs.every((i) => i > lastFloor), 'the cube\'s sub-index files asked for after the floor chunks on screen');
    const ref = await cpuSlice(bed.cube.dir, { step: 0, width: W, height: H, bbox });
    const c = compareIds((await readIds(bed.page.page)).upper, ref, W, H);
    assert.ok(c.share >= 0.995, `${(100 * c.share).toFixed(3)}% equal to the CPU slicer; ${c.examples.join('; ')}`);
  });
});
