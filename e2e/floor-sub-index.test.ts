// A floor too large for index.json (its tree in sub-index files, as the build writes it for a
// large dataset): a first view at the floor has the map ask for the floor's sub-index files while
// the worker's script is still coming (the head start), then the floor chunks they list; the
// cube's own sub-index files wait for those; where the floor's sub-index files cannot be had, the
// cube's chunks draw the floor. bgt_otterlo_400m in tiny chunks, whose floor tree does not fit a
// 2 kB index file.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { boxMeets } from '../format/index-query.js';
import { fitBbox, viewBbox, type Bbox } from '../client/src/geometry/view.js';
import { eventually } from '../testing/event-loop.js';
import { openMap } from './helpers/browser.js';
import { compareIds, cpuSlice } from './helpers/cube.js';
import { readIds, waitIdle } from './helpers/map-page.js';
import { useTestBed } from './helpers/test-bed.js';
import { assertAskedBeforeScript, WORKER_SCRIPT } from './helpers/worker-script.js';

const W = 640, H = 480;

describe('a floor whose tree is in sub-index files (bgt_otterlo_400m in tiny chunks)', () => {
  const bed = useTestBed(['--chunk-bytes', '4096', '--sub-index-bytes', '2048']);

  test('at the floor the floor\'s sub-index files are asked for while the worker\'s script is still coming, each once; the floor chunks before the cube\'s sub-index files; the map equals the CPU slicer', async () => {
    const { contents, server } = bed;
    // The floor's sub-index files index.json names (those it names in turn the worker asks for).
    const floorRefs = (contents.floorRoot?.children ?? []).flatMap((n) => ('ref' in n ? [n.ref] : []));
    assert.ok(floorRefs.length >= 2, `${floorRefs.length} floor sub-index files in index.json`);
    // The whole extent at the floor: every floor sub-index file and floor chunk is on screen.
    const bbox: Bbox = contents.meta.extent;
    const shown = viewBbox(fitBbox(bbox, W, H));
    const floorOnScreen = contents.floorLeaves.filter((l) => boxMeets(l.bbox, { ground: shown, zMin: 0, zMax: 0 })).map((l) => l.file);
    // The worker's script comes a second late, as its 33 kB gzip would on a slow phone network.
    server.faults.appDelayMs = (p) => (WORKER_SCRIPT.test(p) ? 1000 : 0);
    const logStart = server.log.length;
    bed.page = await openMap(bed.browser, server.url, { source: 'cube/', bbox: bbox.join(','), z: 0, supersampling: 1 });
    assert.equal(await waitIdle(bed.page.page), true);
    // The cube's sub-index files come as the margin, after the view is complete.
    const cubeSubs = contents.subIndexFiles.filter((s) => !contents.floorSubIndexFiles.includes(s));
    const firstAsked = (file: string): number => server.log.slice(logStart).findIndex((e) => e.path === `/cube/${file}`);
    await eventually(() => cubeSubs.some((f) => firstAsked(f) >= 0), 'a sub-index file of the cube asked for, as the margin');
    const log = server.log.slice(logStart);
    for (const ref of floorRefs) {
      const asked = log.filter((e) => e.path === `/cube/${ref}`);
      assert.equal(asked.length, 1, `${ref} fetched once`);
      assertAskedBeforeScript(log, ref, asked[0]);
    }
    // Each floor chunk on screen once, and all of them before any of the cube's sub-index files.
    for (const f of floorOnScreen) assert.equal(log.filter((e) => e.path === `/cube/${f}`).length, 1, `${f} fetched once`);
    const lastFloor = Math.max(...floorOnScreen.map(firstAsked));
    const cubeAsked = cubeSubs.map(firstAsked).filter((i) => i >= 0);
    assert.ok(cubeAsked.length > 0 && cubeAsked.every((i) => i > lastFloor), 'the cube\'s sub-index files asked for, after the floor chunks on screen');
    await assertMatchesSlicer(bbox, 'its floor chunks listed in sub-index files');
  });

  test('a floor sub-index file that cannot be had (a 404): the map draws the floor from the cube\'s chunks, complete and equal to the CPU slicer', async () => {
    const { contents, server } = bed;
    // The extent's south-west quarter, where the view needs floor chunks listed in the floor's sub-index files.
    const [x0, y0, x1, y1] = contents.meta.extent;
    const bbox: Bbox = [x0, y0, (x0 + x1) / 2, (y0 + y1) / 2];
    for (const ref of contents.floorSubIndexFiles) server.faults.notFound.add(ref);
    const logStart = server.log.length;
    try {
      bed.page = await openMap(bed.browser, server.url, { source: 'cube/', bbox: bbox.join(','), z: 0, supersampling: 1 }, { expect: [/Failed to load resource: the server responded with a status of 404/] });
      assert.equal(await waitIdle(bed.page.page), true, 'complete');
      const log = server.log.slice(logStart);
      const refused = contents.floorSubIndexFiles.map((ref) => log.filter((e) => e.path === `/cube/${ref}`).length).filter((n) => n > 0);
      assert.ok(refused.length > 0 && refused.every((n) => n === 1), `the floor sub-index files the view reaches asked for once each (${refused.join(', ')} times)`);
      assert.ok(log.some((e) => /^\/cube\/c-/.test(e.path)), 'the cube\'s chunks fetched');
      await assertMatchesSlicer(bbox, 'the floor drawn from the cube\'s chunks');
    } finally {
      server.faults.notFound.clear();
    }
  });

  /** The map's picture equals the CPU slicer's at the floor. */
  async function assertMatchesSlicer(bbox: Bbox, label: string): Promise<void> {
    const ref = await cpuSlice(bed.cube.dir, { step: 0, width: W, height: H, bbox });
    const c = compareIds((await readIds(bed.page!.page)).upper, ref, W, H);
    assert.ok(c.share >= 0.995, `${label}: ${(100 * c.share).toFixed(3)}% equal to the CPU slicer; ${c.examples.join('; ')}`);
  }
});
