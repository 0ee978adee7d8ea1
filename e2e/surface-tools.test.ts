// The slicing surface tools with real mouse input: a lens of more detail that follows the
// pointer, and control points (inverse-distance weighting) placed by clicking, dragged, and
// changed with the wheel. Each time the GPU's ID buffer must equal the CPU slicer's for the
// surface the tool made, and the surface must sit where the pointer put it.
import assert from 'node:assert/strict';
import { after, afterEach, before, describe, test } from 'node:test';
import type { Browser } from 'playwright-core';
import { scaleAtZ, zAtScale } from '../format/scale.js';
import { formatSurface } from '../format/slicing-surface.js';
import type { SurfaceSpec } from '../format/slicing-surface.js';
import { fitBbox, pixelToGround, viewBbox } from '../client/src/geometry/view.js';
import { openMap, type MapPage } from './helpers/browser.js';
import { compareIds, cpuSlice, type BuiltCube, type CubeContents } from './helpers/cube.js';
import { checkAndClose, setUpTestBed, tearDownTestBed } from './helpers/test-bed.js';
import { readIds, waitIdle } from './helpers/map-page.js';
import type { TestServer } from './helpers/test-server.js';

const W = 640, H = 480;

describe('slicing surface tools (bgt_otterlo_400m)', () => {
  let cube: BuiltCube;
  let contents: CubeContents;
  let server: TestServer;
  let browser: Browser;
  let mp: MapPage | null = null;

  before(async () => {
    ({ cube, contents, server, browser } = await setUpTestBed(['--no-precompress']));
  });

  afterEach(async () => {
    await checkAndClose(mp);
    mp = null;
  });

  after(async () => {
    await tearDownTestBed({ cube, server, browser });
  });

  const close = (a: number, b: number, tol: number, what: string): void => assert.ok(Math.abs(a - b) <= tol, `${what}: ${a} vs ${b}`);

  async function surface(p: MapPage): Promise<{ base: number; spec: SurfaceSpec }> {
    return (await p.page.evaluate(() => ({ base: map.getSliceZ(), spec: map.getSlicingSurface() }))) as unknown as { base: number; spec: SurfaceSpec };
  }

  async function assertMatchesSlicer(p: MapPage, label: string): Promise<void> {
    assert.equal(await waitIdle(p.page), true, `${label}: complete`);
    const s = await surface(p);
    const bbox = viewBbox(fitBbox(contents.meta.extent, W, H));
    const gpu = await readIds(p.page);
    const ref = await cpuSlice(cube.dir, { step: s.base, width: W, height: H, bbox, surface: formatSurface(s.spec) });
    const c = compareIds(gpu.upper, ref, W, H);
    assert.ok(c.share >= 0.995, `${label}: ${(100 * c.share).toFixed(3)}% equal to the CPU slicer; ${c.examples.join('; ')}`);
  }

  test('a lens of more detail follows the pointer', async () => {
    const z = 420;
    mp = await openMap(browser, server.url, { source: 'cube/', z, tool: 'lens', supersampling: 1 });
    const p = mp;
    assert.equal(await waitIdle(p.page), true);
    const view = fitBbox(contents.meta.extent, W, H);
    const flat = await readIds(p.page);
    let previous = flat.upper;
    for (const [x, y] of [[220, 180], [430, 330]] as const) {
      await p.page.mouse.move(x, y, { steps: 4 });
      const s = await surface(p);
      assert.equal(s.spec.kind, 'lens');
      if (s.spec.kind !== 'lens') return;
      const [gx, gy] = pixelToGround(view, x, y);
      close(s.spec.cx, gx, 1e-6, 'lens centre x');
      close(s.spec.cy, gy, 1e-6, 'lens centre y');
      // Radius 120 CSS pixels at the view's scale; depth 200 steps (the tool's defaults).
      close(s.spec.radius, 120 * view.resolution, 1e-9, 'radius');
      assert.equal(s.spec.depth, 200);
      await assertMatchesSlicer(p, `lens at ${x},${y}`);
      const ids = (await readIds(p.page)).upper;
      // More detail under the lens, the same far from it.
      let near = 0, far = 0;
      for (let k = 0; k < W * H; k++) {
        if (ids[k] === previous[k]) continue;
        const d = Math.hypot((k % W) + 0.5 - x, Math.floor(k / W) + 0.5 - y);
        if (d < 125) near++;
        else far++;
      }
      assert.ok(near > 500, `${near} pixels changed under the lens`);
      // Outside the lens the slice is the flat one, but the frame is another (its id pass another
      // shader variant): a pixel centre a few hundredths of a pixel from a shared edge may fall
      // on its other side (bgt_otterlo_400m: one, 0.016 px from an edge between two floor
      // faces; the CPU slicer sides with the flat frame). A lens that reached beyond its radius
      // would change thousands.
      if (previous === flat.upper) assert.ok(far <= 3, `${far} pixels changed outside the lens`);
      previous = ids;
    }
  });

  test('control points are placed by clicks, dragged, and raised or lowered by the wheel', async () => {
    const z = 400;
    mp = await openMap(browser, server.url, { source: 'cube/', z, tool: 'idw', supersampling: 1 });
    const p = mp;
    assert.equal(await waitIdle(p.page), true);
    const view = fitBbox(contents.meta.extent, W, H);
    const meta = contents.meta;
    const newZ = zAtScale(meta, scaleAtZ(meta, z) / 4);
    const clicks: [number, number][] = [[180, 140], [470, 360]];
    for (const [x, y] of clicks) await p.page.mouse.click(x, y);
    let s = await surface(p);
    assert.equal(s.spec.kind, 'idw');
    if (s.spec.kind !== 'idw') return;
    assert.equal(s.spec.points.length, 2);
    clicks.forEach(([x, y], i) => {
      const [gx, gy] = pixelToGround(view, x, y);
      const pt = (s.spec as Extract<SurfaceSpec, { kind: 'idw' }>).points[i]!;
      close(pt.x, gx, 1e-6, `point ${i} x`);
      close(pt.y, gy, 1e-6, `point ${i} y`);
      close(pt.z, newZ, 1e-9, `point ${i} z: a quarter of the view's scale`);
    });
    await assertMatchesSlicer(p, 'two points');
    // Drag the first point by its marker.
    await p.page.mouse.move(180, 140);
    await p.page.mouse.down();
    await p.page.mouse.move(260, 220, { steps: 8 });
    await p.page.mouse.up();
    s = await surface(p);
    if (s.spec.kind !== 'idw') return assert.fail('still idw');
    assert.equal(s.spec.points.length, 2, 'a drag places no new point');
    const [dx, dy] = pixelToGround(view, 260, 220);
    close(s.spec.points[0]!.x, dx, 1e-6, 'dragged x');
    close(s.spec.points[0]!.y, dy, 1e-6, 'dragged y');
    await assertMatchesSlicer(p, 'after the drag');
    // The wheel over the second point: two clicks toward less detail (scale x sqrt(2) each).
    await p.page.mouse.move(470, 360);
    await p.page.mouse.wheel(0, 100);
    await p.page.mouse.wheel(0, 100);
    await p.page.waitForFunction((want) => {
      const sp = map.getSlicingSurface() as unknown as { points: { z: number }[] };
      return Math.abs(sp.points[1]!.z - want) < 1e-6;
    }, zAtScale(meta, scaleAtZ(meta, zAtScale(meta, scaleAtZ(meta, newZ) * Math.SQRT2)) * Math.SQRT2));
    await assertMatchesSlicer(p, 'after the wheel');
  });
});
