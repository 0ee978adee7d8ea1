// What the user sees and picks, in real Chromium on real cubes of bgt_otterlo_400m: class
// colours and patterns, near-intersection blending, face boundaries, supersampling, picking
// (by a real click too), device pixel ratio and resize, a lost and restored WebGL context, and
// the message where WebGL2 is missing.
import assert from 'node:assert/strict';
import { readFile } from 'node:fs/promises';
import { after, afterEach, before, describe, test } from 'node:test';
import type { Browser } from 'playwright-core';
import { scaleAtZ, zAtScale } from '../format/scale.js';
import { fitBbox, pixelToGround, viewBbox, type Bbox } from '../client/src/geometry/view.js';
import { openMap, type MapPage, type OpenOptions } from './helpers/browser.js';
import { compareIds, cpuSlice, otterlo400, type BuiltCube, type CubeContents } from './helpers/cube.js';
import { checkAndClose, setUpTestBed, tearDownTestBed } from './helpers/test-bed.js';
import { hexColour, loseAndRestoreContext, pixel, readIds, screenshot, waitIdle, type PageIds, type Rgba } from './helpers/map-page.js';
import type { TestServer } from './helpers/test-server.js';

const W = 640, H = 480;

// Blending and supersampling depend on how the cube's surfaces lie in z: they run on the smooth
// cube (the default; tilted surfaces, z per vertex) and on the classic one (ssc build --classic,
// every surface horizontal). The other checks do not, and run on the smooth cube only.
for (const classic of [false, true]) describe(`rendering and picking (bgt_otterlo_400m, ${classic ? 'classic' : 'smooth'} cube)`, () => {
  let cube: BuiltCube;
  let contents: CubeContents;
  let server: TestServer;
  let browser: Browser;
  let mp: MapPage | null = null;
  let classColours: [number, number, number][];
  let background: [number, number, number];

  before(async () => {
    ({ cube, contents, server, browser } = await setUpTestBed(classic ? ['--classic'] : []));
    classColours = contents.meta.style.classes.map((c) => hexColour(c.color));
    background = hexColour(contents.meta.style.background);
  });

  afterEach(async () => {
    await checkAndClose(mp);
    mp = null;
  });

  after(async () => {
    await tearDownTestBed({ cube, server, browser });
  });

  const smoothOnly = (name: string, fn: () => Promise<void>): void => {
    if (!classic) test(name, fn);
  };
  const ext = (): Bbox => contents.meta.extent;
  const info = () => contents.meta;

  /** The colours a class may show at slice z: its fill, and its pattern's colour within the pattern's scale range. */
  function coloursAt(cls: number, z: number): [number, number, number][] {
    const p = contents.meta.style.classes[cls]!.pattern;
    const inRange = p && (p.minScale === undefined || z >= zAtScale(info(), p.minScale)) && (p.maxScale === undefined || z <= zAtScale(info(), p.maxScale));
    return inRange ? [classColours[cls]!, hexColour(p.color)] : [classColours[cls]!];
  }

  // The faces' colours, without the cube's lines over them (e2e/lines.test.ts draws those).
  async function open(params: Record<string, string | number>, opts: OpenOptions = {}): Promise<MapPage> {
    mp = await openMap(browser, server.url, { source: 'cube/', supersampling: 1, lines: 0, ...params }, opts);
    return mp;
  }

  async function set(p: MapPage, fn: string): Promise<PageIds> {
    await p.page.evaluate(fn);
    assert.equal(await waitIdle(p.page), true);
    return readIds(p.page);
  }

  /** Pixels whose colours differ between two screenshots. */
  function changed(a: Rgba, b: Rgba): Set<number> {
    const out = new Set<number>();
    for (let p = 0; p < a.width * a.height; p++) {
      if (a.data[4 * p] !== b.data[4 * p] || a.data[4 * p + 1] !== b.data[4 * p + 1] || a.data[4 * p + 2] !== b.data[4 * p + 2]) out.add(p);
    }
    return out;
  }

  smoothOnly('every pixel shows the class colour of its face, or the background outside the cube', async () => {
    // At this level of detail (about 1:4000) the style's patterns (up to 1:2500) are off.
    const p = await open({ z: 410 });
    assert.equal(await waitIdle(p.page), true);
    const ids = await readIds(p.page);
    const img = await screenshot(p.page);
    let checked = 0;
    const classesSeen = new Set<number>();
    for (let k = 0; k < W * H; k++) {
      const i = k % W, j = Math.floor(k / W);
      const want = ids.upper[k] === 0 ? background : classColours[idsClass(ids, k)]!;
      if (ids.upper[k] !== 0) classesSeen.add(idsClass(ids, k));
      assert.deepEqual(pixel(img, i, j), want, `pixel (${i},${j})`);
      checked++;
    }
    assert.equal(checked, W * H);
    assert.ok(classesSeen.size >= 4, `${classesSeen.size} classes on screen`);
  });

  smoothOnly('class patterns show only within their scale range', async () => {
    const vegetated = contents.meta.style.classes.findIndex((c) => c.key === 'begroeidterreindeel');
    const pat = contents.meta.style.classes[vegetated]!.pattern!;
    assert.ok(pat && pat.maxScale, 'the style gives vegetated terrain a pattern up to a scale');
    const patternColour = hexColour(pat.color);
    const count = async (scale: number): Promise<{ pattern: number; of: number }> => {
      const ids = await set(mpOrThrow(), `map.jumpTo({ scaleDenominator: ${scale}, sliceZ: null })`);
      const img = await screenshot(mpOrThrow().page);
      let pattern = 0, of = 0;
      for (let k = 0; k < W * H; k++) {
        if (ids.upper[k] === 0 || idsClass(ids, k) !== vegetated) continue;
        of++;
        const c = pixel(img, k % W, Math.floor(k / W));
        if (c[0] === patternColour[0] && c[1] === patternColour[1] && c[2] === patternColour[2]) pattern++;
      }
      return { pattern, of };
    };
    await open({ center: `${(ext()[0] + ext()[2]) / 2},${(ext()[1] + ext()[3]) / 2}`, scale: 1500 });
    assert.equal(await waitIdle(mpOrThrow().page), true);
    const inside = await count(pat.maxScale * 0.8);
    assert.ok(inside.of > 1000 && inside.pattern > inside.of * 0.02, `at 1:${pat.maxScale * 0.8} ${inside.pattern} of ${inside.of} vegetated pixels show the pattern`);
    const beyond = await count(pat.maxScale * 1.25);
    assert.ok(beyond.of > 1000 && beyond.pattern === 0, `at 1:${pat.maxScale * 1.25} ${beyond.pattern} of ${beyond.of} show it`);
  });

  function mpOrThrow(): MapPage {
    if (!mp) throw new Error('no page');
    return mp;
  }

  test('near-intersection blending changes colours only where a boundary in scale is near', async () => {
    const z = 240, c = 6;
    const p = await open({ z, blending: 'off' });
    assert.equal(await waitIdle(p.page), true);
    const plain = await screenshot(p.page);
    const ids = await set(p, `map.setBlending({ mode: 'always', distance: ${c} })`);
    const blended = await screenshot(p.page);
    const diff = changed(plain, blended);
    // Where the slice at z and the slice c lower show different faces, a surface lies within
    // c under the slice: only there may the colour change.
    const view = fitBbox(ext(), W, H);
    const atZ = await cpuSlice(cube.dir, { step: z, width: W, height: H, bbox: viewBbox(view) });
    const below = await cpuSlice(cube.dir, { step: z - c, width: W, height: H, bbox: viewBbox(view) });
    let near = 0;
    for (let k = 0; k < W * H; k++) if (atZ[k] !== below[k]) near++;
    // Within a pixel: on a steep ramp (a front paced in zoom time crosses many steps per pixel
    // near its start) a sub-pixel difference between GPU and CPU is a fraction of a step.
    const nearBy = (k: number): boolean => {
      const i = k % W, j = Math.floor(k / W);
      for (let dj = -1; dj <= 1; dj++) for (let di = -1; di <= 1; di++) {
        const ii = i + di, jj = j + dj;
        if (ii >= 0 && jj >= 0 && ii < W && jj < H && atZ[jj * W + ii] !== below[jj * W + ii]) return true;
      }
      return false;
    };
    let outside = 0;
    const where: string[] = [];
    for (const k of diff) {
      if (!nearBy(k) && !onFaceBoundary(atZ, k)) {
        outside++;
        if (where.length < 5) where.push(`${k % W},${Math.floor(k / W)} (face ${atZ[k]})`);
      }
    }
    assert.ok(diff.size > 200, `${diff.size} pixels blended`);
    assert.ok(near < W * H * 0.5, 'most of the map is far from a boundary in scale');
    assert.equal(outside, 0, `${outside} of ${diff.size} changed pixels have no boundary within ${c} steps below: ${where.join(', ')}`);
    // And the colour is the mix the definition gives: mix(colour(lower), colour(upper), d / c),
    // d the distance from the slice down to the surface at the pixel (on a tilted surface, where
    // the slice meets the plane through its vertices: the z read back, which slice-accuracy
    // checks against the CPU slicer, as the face below). A class's colour is its fill or, within its pattern's
    // scale range (vegetated terrain's dots are on at this z), the pattern's colour where the
    // pattern covers the pixel: either is accepted, for each face.
    let checked = 0, worst = 0;
    for (const k of diff) {
      const d = ids.slice[k]! - ids.z[k]!;
      const lower = (ids.classes[k]! >>> 16) & 0xffff;
      if (lower >= classColours.length || d >= c) continue;
      const got = pixel(blended, k % W, Math.floor(k / W));
      let error = Infinity;
      for (const up of coloursAt(idsClass(ids, k), ids.slice[k]!)) {
        for (const lo of coloursAt(lower, ids.slice[k]!)) {
          const want = up.map((u, q) => Math.round(lo[q]! + (u - lo[q]!) * (d / c)));
          error = Math.min(error, Math.max(...want.map((w, q) => Math.abs(got[q]! - w))));
        }
      }
      assert.ok(error <= 1, `pixel (${k % W},${Math.floor(k / W)}): ${got} is ${error} levels off the mix at d ${d}`);
      worst = Math.max(worst, error);
      checked++;
    }
    assert.ok(checked >= 50, `${checked} blended pixels checked (worst ${worst} levels off)`);
    // 'moving' blends only while the slice moves: at rest it is the plain map.
    await set(p, `map.setBlending({ mode: 'moving' })`);
    assert.equal(changed(plain, await screenshot(p.page)).size, 0);
  });

  smoothOnly('face boundaries are drawn exactly where the face id changes, in CSS pixel widths', async () => {
    const p = await open({ z: 200 });
    assert.equal(await waitIdle(p.page), true);
    const plain = await screenshot(p.page);
    const ids = await set(p, `map.setBoundaries({ enabled: true, width: 1 })`);
    const one = changed(plain, await screenshot(p.page));
    // Width 1: the pixel left of and below each change of id (rows from the top: below is j + 1... in
    // screen terms the pixel whose right or upper neighbour differs).
    const expected = new Set<number>();
    for (let j = 0; j < H; j++) {
      for (let i = 0; i < W; i++) {
        const k = j * W + i;
        if ((i + 1 < W && ids.upper[k + 1] !== ids.upper[k]) || (j > 0 && ids.upper[k - W] !== ids.upper[k])) expected.add(k);
      }
    }
    assert.ok(expected.size > 1000);
    assert.deepEqual(sortedDiff(one, expected), [[], []]);
    await set(p, `map.setBoundaries({ width: 3 })`);
    const three = changed(plain, await screenshot(p.page));
    assert.ok(three.size > 2.2 * one.size && three.size < 3.5 * one.size, `${three.size} pixels at width 3, ${one.size} at width 1`);
    await set(p, `map.setBoundaries({ enabled: false })`);
    assert.equal(changed(plain, await screenshot(p.page)).size, 0);
  });

  test('supersampling smooths edges and leaves the inside of faces alone', async () => {
    const p = await open({ z: 100 });
    assert.equal(await waitIdle(p.page), true);
    const plain = await screenshot(p.page);
    const ids = await set(p, `engine.setSupersampling(16)`);
    const smooth = await screenshot(p.page);
    const diff = changed(plain, smooth);
    assert.ok(diff.size > 500, `${diff.size} pixels smoothed`);
    // Changes belong next to an id change (or the image border, beyond which the jittered
    // samples see what lies outside). A few elsewhere are sub-pixel details the centre misses
    // (a wall thinner than a pixel, a sliver): at most one in a thousand changed pixels.
    // Measured: 3 of about 15,000 on either cube (a smooth cube that left losers' slivers
    // narrower than a pixel inside winners had 27; the CPU slicer showed them too).
    const off = [...diff].filter((k) => {
      const i = k % W, j = Math.floor(k / W);
      return i > 0 && j > 0 && i < W - 1 && j < H - 1 && !onFaceBoundary(ids.upper, k);
    });
    assert.ok(off.length <= Math.max(10, diff.size / 1000), `${off.length} of ${diff.size} changed pixels away from edges: ${off.slice(0, 10).map((k) => `(${k % W},${Math.floor(k / W)})`).join(' ')}`);
  });

  // The passes link each combination of their features when a frame first needs it, so a
  // shader error in one shows only then: every combination is drawn here once.
  smoothOnly('every combination of shader features compiles, links and draws: lines, blending, boundaries, feature state, a curved slice, supersampling', async () => {
    const z = 100;
    const p = await open({ z, lines: 1 });
    assert.equal(await waitIdle(p.page), true);
    const ids = await readIds(p.page);
    const face = ids.upper[(H / 2) * W + W / 2]!;
    assert.ok(face > 0, 'a face in the middle of the map');
    const combos: { ss: number; lines: boolean; blending: boolean; boundaries: boolean; state: boolean; curved: boolean }[] = [];
    for (let bits = 0; bits < 32; bits++) {
      combos.push({ ss: 1, lines: (bits & 1) > 0, blending: (bits & 2) > 0, boundaries: (bits & 4) > 0, state: (bits & 8) > 0, curved: (bits & 16) > 0 });
    }
    // Supersampled, the frames accumulate off the canvas and the present pass paints them, with or without lines.
    for (const lines of [false, true]) combos.push({ ss: 4, lines, blending: false, boundaries: false, state: false, curved: false });
    for (const c of combos) {
      const label = JSON.stringify(c);
      const before = await p.page.evaluate(() => engine.stats().frame);
      await p.page.evaluate(([c, face, z]) => {
        engine.setSupersampling(c.ss);
        map.setLinesVisible(c.lines);
        map.setBlending({ mode: c.blending ? 'always' : 'off' });
        map.setBoundaries({ enabled: c.boundaries });
        if (c.state) map.setFeatureState({ face }, { highlight: true });
        else map.removeFeatureState({ face });
        map.setSlicingSurface(c.curved ? `sine:amplitude=${z / 2},wavelength=200,angle=30` : 'flat');
      }, [c, face, z] as const);
      assert.equal(await waitIdle(p.page), true, label);
      const stats = await p.page.evaluate(() => engine.stats());
      assert.ok(stats.frame > before && stats.triangles > 0, `${label}: drawn`);
      // Lines on: the line pass drew some, so the colour or present pass painted them.
      assert.equal(stats.segments > 0, c.lines, `${label}: ${stats.segments} line segments`);
      assert.deepEqual(p.problems, [], label);
    }
  });

  smoothOnly('picking returns the face under the pointer, with its class, attributes and steps', async () => {
    const z = 90;
    const p = await open({ z });
    assert.equal(await waitIdle(p.page), true);
    const view = fitBbox(ext(), W, H);
    const ref = await cpuSlice(cube.dir, { step: z, width: W, height: H, bbox: viewBbox(view) });
    const input = JSON.parse(await readFile(otterlo400, 'utf8')) as { features: { properties: Record<string, unknown> }[] };
    // Points well inside faces (a 7x7 block of one face in the reference), spread over the map.
    const points: [number, number][] = [];
    for (let j = 20; j < H - 20 && points.length < 12; j += 37) {
      for (let i = 90; i < W - 90 && points.length < 12; i += 53) {
        if (interior(ref, j * W + i, 3) && !points.some(([x]) => x === i)) points.push([i, j]);
      }
    }
    assert.ok(points.length >= 8);
    const faces = new Set<number>();
    for (const [i, j] of points) {
      const all = (await p.page.evaluate((pt) => map.queryFeatures(pt), [i + 0.5, j + 0.5] as [number, number])) as {
        kind: string; face: number; classKey: string; feature: number; properties: Record<string, unknown>; stepLow: number; stepHigh: number;
      }[];
      // A line of the cube may lie over the face (then first); one face under it.
      const fs = all.filter((f) => f.kind === 'face');
      assert.equal(fs.length, 1);
      assert.ok(all.length === 1 || all[0]!.kind === 'line', 'the line first, then the face');
      const f = fs[0]!;
      assert.equal(f.face, ref[j * W + i], `face at (${i},${j})`);
      faces.add(f.face);
      assert.ok(f.stepLow <= z && z < f.stepHigh, `face ${f.face} alive at ${z}: ${f.stepLow}..${f.stepHigh}`);
      assert.deepEqual(f.properties, input.features[f.feature]!.properties);
      assert.equal(f.classKey, input.features[f.feature]!.properties.layer, 'the class is the feature\'s layer');
    }
    assert.ok(faces.size >= 4, `${faces.size} different faces picked`);
    // Outside the cube there is nothing to pick.
    const outside = await p.page.evaluate(() => map.queryFeatures([5, 240]));
    assert.deepEqual(outside, []);
    // A real click shows the picked face in the demo's info box.
    const [ci, cj] = points[0]!;
    await p.page.mouse.click(ci + 0.5, cj + 0.5);
    await p.page.waitForFunction("document.getElementById('info').textContent !== ''");
    const text = (await p.page.textContent('#info')) ?? '';
    assert.match(text, new RegExp(`face ${ref[cj * W + ci]}\\b`));
  });

  smoothOnly('a device pixel ratio of 2 draws every device pixel, and picking maps CSS pixels', async () => {
    const z = 120;
    const p = await open({ z }, { width: 320, height: 240, deviceScaleFactor: 2 });
    assert.equal(await waitIdle(p.page), true);
    const ids = await readIds(p.page);
    assert.deepEqual([ids.width, ids.height], [W, H], 'a 320x240 CSS pixel map at ratio 2');
    const bbox = viewBbox(fitBbox(ext(), W, H));
    const ref = await cpuSlice(cube.dir, { step: z, width: W, height: H, bbox });
    const c = compareIds(ids.upper, ref, W, H);
    assert.ok(c.share >= 0.995, `${(100 * c.share).toFixed(3)}% equal`);
    for (let k = W * 100 + 100; k < W * 400; k += 9973) {
      if (!interior(ref, k, 2)) continue;
      const fs = (await p.page.evaluate((pt) => map.queryFeatures(pt), [(k % W) / 2 + 0.25, Math.floor(k / W) / 2 + 0.25] as [number, number])) as { kind: string; face: number }[];
      assert.equal(fs.find((f) => f.kind === 'face')?.face, ref[k]);
    }
  });

  smoothOnly('a resized container gets a map of its new size', async () => {
    const z = 60;
    const p = await open({ z });
    assert.equal(await waitIdle(p.page), true);
    await p.page.setViewportSize({ width: 500, height: 300 });
    await p.page.waitForFunction(() => engine.getView().width === 500 && engine.getView().height === 300);
    const bbox: Bbox = [ext()[0] + 50, ext()[1] + 80, ext()[0] + 300, ext()[1] + 230];
    const ids = await set(p, `map.fitBoundsProjected([${bbox.join(',')}], { sliceZ: ${z}, duration: 0 })`);
    assert.deepEqual([ids.width, ids.height], [500, 300]);
    const ref = await cpuSlice(cube.dir, { step: z, width: 500, height: 300, bbox });
    assert.ok(compareIds(ids.upper, ref, 500, 300).share >= 0.995);
  });

  smoothOnly('a lost WebGL context is restored without reloading, with the same picture', async () => {
    const p = await open({ z: 180, supersampling: 8 });
    assert.equal(await waitIdle(p.page), true);
    const before = await screenshot(p.page);
    const idsBefore = await readIds(p.page);
    await loseAndRestoreContext(p.page, async () => {
      assert.equal(await p.page.evaluate(() => engine.readIds()), null, 'nothing to read while lost');
    });
    const idsAfter = await readIds(p.page);
    assert.deepEqual(idsAfter.upper, idsBefore.upper);
    assert.equal(changed(before, await screenshot(p.page)).size, 0, 'the same picture');
    assert.ok(new Set(idsAfter.upper).size > 20);
  });

  smoothOnly('without float render targets the surface is computed on the CPU, with the same slices', async () => {
    // Some WebGL2 devices cannot render to float textures (no EXT_color_buffer_float).
    const noFloat = `(() => { const get = WebGL2RenderingContext.prototype.getExtension; WebGL2RenderingContext.prototype.getExtension = function (n) { return n === 'EXT_color_buffer_float' ? null : get.call(this, n); }; })()`;
    const z = 220, spec = 'sine:amplitude=150,wavelength=130,angle=30';
    const p = await open({ z, surface: spec, supersampling: 4 }, { initScript: noFloat });
    assert.equal(await waitIdle(p.page), true);
    const ids = await readIds(p.page);
    const bbox = viewBbox(fitBbox(ext(), W, H));
    const ref = await cpuSlice(cube.dir, { step: z, width: W, height: H, bbox, surface: spec });
    const c = compareIds(ids.upper, ref, W, H);
    assert.ok(c.share >= 0.995, `${(100 * c.share).toFixed(3)}% equal`);
    // The slice z read back is the CPU's: the sine's range around z.
    let lo = Infinity, hi = -Infinity;
    for (const v of ids.slice) {
      lo = Math.min(lo, v);
      hi = Math.max(hi, v);
    }
    assert.ok(lo >= z - 150 - 1e-3 && hi <= z + 150 + 1e-3 && hi - lo > 250, `slice z from ${lo} to ${hi}`);
  });

  smoothOnly('without WebGL2 the container says so', async () => {
    const p = await open({}, { initScript: `(() => { const get = HTMLCanvasElement.prototype.getContext; HTMLCanvasElement.prototype.getContext = function (t, ...a) { return t === 'webgl2' ? null : get.call(this, t, ...a); }; })()` });
    await p.page.waitForSelector('.ssc-no-webgl2');
    const text = await p.page.textContent('.ssc-no-webgl2');
    assert.match(text ?? '', /WebGL2/);
    assert.equal(await p.page.evaluate(() => engine.readIds()), null);
  });

  // z and scale agree with the shared definitions (a sanity check of the test's own numbers).
  smoothOnly('the scale of the default view and its z are consistent', async () => {
    const p = await open({});
    assert.equal(await waitIdle(p.page), true);
    const [scale, z] = await p.page.evaluate(() => [map.getScaleDenominator(), map.getSliceZ()]);
    assert.ok(Math.abs(z - zAtScale(info(), scale)) < 1e-9);
    assert.ok(Math.abs(scaleAtZ(info(), z) - scale) / scale < 1e-9 || z === 0 || z === info().zMax);
    const v = await p.page.evaluate(() => engine.getView());
    const [gx, gy] = pixelToGround(v, W / 2, H / 2);
    assert.ok(Math.abs(gx - (ext()[0] + ext()[2]) / 2) < 1e-6 && Math.abs(gy - (ext()[1] + ext()[3]) / 2) < 1e-6);
  });
});

/** The class of the upper face at pixel k (from the ID buffer). */
function idsClass(ids: PageIds, k: number): number {
  return ids.classes[k]! & 0xffff;
}

function onFaceBoundary(ids: ArrayLike<number>, k: number): boolean {
  const i = k % W, j = Math.floor(k / W);
  for (let dj = -1; dj <= 1; dj++) {
    for (let di = -1; di <= 1; di++) {
      const x = i + di, y = j + dj;
      if (x >= 0 && y >= 0 && x < W && y < H && ids[y * W + x] !== ids[k]) return true;
    }
  }
  return false;
}

/** The pixel and its (2r+1)^2 neighbourhood show one face. */
function interior(ids: ArrayLike<number>, k: number, r: number): boolean {
  const i = k % W, j = Math.floor(k / W);
  if (ids[k] === 0) return false;
  for (let dj = -r; dj <= r; dj++) {
    for (let di = -r; di <= r; di++) {
      const x = i + di, y = j + dj;
      if (x < 0 || y < 0 || x >= W || y >= H || ids[y * W + x] !== ids[k]) return false;
    }
  }
  return true;
}

function sortedDiff(a: Set<number>, b: Set<number>): [number[], number[]] {
  return [[...a].filter((x) => !b.has(x)).sort((x, y) => x - y).slice(0, 10), [...b].filter((x) => !a.has(x)).sort((x, y) => x - y).slice(0, 10)];
}
