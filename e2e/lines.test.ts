// The cube's lines in the browser (issue 12): the GPU's line pass against the CPU reference
// (preprocess/map/draw-lines.ts, what `ssc slice` draws), on a flat slice and under a lens,
// and a real click on a line giving the line's class and its input feature's attributes.
import assert from 'node:assert/strict';
import { readFile } from 'node:fs/promises';
import { describe, test } from 'node:test';
import type { Page } from 'playwright-core';
import { lineOfChunk } from '../format/line-chunk.js';
import type { LineRecord } from '../format/line-record.js';
import { lineRuleFinder, type LineRule } from '../format/line-style.js';
import { PIXEL_SIZE_MM } from '../format/pixel-size.js';
import { parseSurface, surfaceZ } from '../format/slicing-surface.js';
import { drawLines, linePaintColour, type LinePaint } from '../preprocess/map/draw-lines.js';
import { fitView } from '../preprocess/map/rasterize.js';
import { CubeReader } from '../preprocess/ssc/read-cube.js';
import { openMap } from './helpers/browser.js';
import { otterlo400 } from './helpers/cube.js';
import { GL_ALLOCATION_LOG, glAllocations, hexColour, pixel, screenshot, waitIdle, type Rgba } from './helpers/map-page.js';
import { useTestBed } from './helpers/test-bed.js';

const W = 640, H = 480;
type Bbox = [number, number, number, number];

/** The map's style as getStyle gives it, as far as this test reads it. */
interface LineLike { width?: number; color?: string; casing?: { width: number; color: string } | null; rules?: LineLike[] }
interface StyleLike { name: string; classes: { key: string; linear: boolean; line?: LineLike }[] }

interface LinesWindow {
  map: { setLinesVisible(v: boolean): unknown; whenIdle(): Promise<unknown>; on(t: string, f: (ev: unknown) => void): unknown; getStyle(): StyleLike; setStyle(s: object): unknown };
  clicked?: { features: { kind: string; classKey: string; feature: number; properties: unknown; face?: number }[] };
}

describe('lines of the cube (bgt_otterlo_400m)', () => {
  const bed = useTestBed();

  async function lines(): Promise<{ all: LineRecord[]; cube: CubeReader }> {
    const cube = await CubeReader.open(bed.cube.dir);
    const all: LineRecord[] = [];
    for (const leaf of cube.index.lines ?? []) {
      const c = await cube.lineChunk(leaf);
      for (let i = 0; i < c.lineCount; i++) all.push(lineOfChunk(c, i));
    }
    return { all, cube };
  }

  /** The z (a whole step) at which the most lines are on the map. */
  function busiestZ(all: LineRecord[], zMax: number): number {
    let best = 0, most = -1;
    for (let z = 0; z <= zMax; z += Math.max(1, Math.floor(zMax / 200))) {
      const n = all.filter((l) => l.zStart <= z && z < l.zEnd).length;
      if (n > most) [best, most] = [z, n];
    }
    return best;
  }

  /** Boxes of the map's controls and the test page's text box (CSS px), which hide the map. */
  function covered(page: Page): Promise<Bbox[]> {
    return page.evaluate(() => {
      // The page's DOM, as seen from Node's types (no DOM library here).
      const doc = (globalThis as unknown as { document: { querySelectorAll(s: string): Iterable<{ getBoundingClientRect(): { left: number; top: number; right: number; bottom: number } }> } }).document;
      return Array.from(doc.querySelectorAll('.vario-map-control-container > * > *, #info')).map((el) => {
        const r = el.getBoundingClientRect();
        return [r.left, r.top, r.right, r.bottom] as Bbox;
      });
    });
  }

  const diff = (a: number[], b: number[]): number => Math.max(...a.map((v, k) => Math.abs(v - b[k]!)));
  const under = (hidden: Bbox[], i: number, j: number): boolean => hidden.some((b) => i + 1 >= b[0] - 1 && i <= b[2] + 1 && j + 1 >= b[1] - 1 && j <= b[3] + 1);

  /** Whether mask has a pixel within r pixels (a (2r+1)² square) of (i, j). */
  const nearby = (mask: (i: number, j: number) => boolean, i: number, j: number, r = 1): boolean => {
    for (let dj = -r; dj <= r; dj++) for (let di = -r; di <= r; di++) {
      const x = i + di, y = j + dj;
      if (x >= 0 && y >= 0 && x < W && y < H && mask(x, y)) return true;
    }
    return false;
  };

  async function setLinesVisible(page: Page, visible: boolean): Promise<void> {
    await page.evaluate((v) => (globalThis as unknown as LinesWindow).map.setLinesVisible(v), visible);
    await waitIdle(page);
  }

  /**
   * Lines in black over a white map (the style changed at run time): how dark a pixel is says
   * how much a line covers it. Lines narrower than a pixel, casing and all, are left out: the
   * CPU's test of pixel centres samples them too sparsely to compare with. With `thinMm`, every
   * line is drawn that wide instead, with no casing.
   */
  async function blackOnWhite(page: Page, thinMm?: number): Promise<void> {
    await page.evaluate(([minMm, thin]) => {
      const m = (globalThis as unknown as LinesWindow).map;
      const s = m.getStyle();
      const black = (l: LineLike, d: LineLike): LineLike => {
        if (thin !== null) return { ...l, width: thin, color: '#000000', casing: null };
        const width = l.width ?? d.width ?? 0;
        const casing = l.casing === undefined ? d.casing : l.casing;
        const band = width + (casing ? 2 * casing.width : 0);
        return { ...l, width: band >= minMm ? width : 0, color: '#000000', ...(l.casing ? { casing: { ...l.casing, color: '#000000' } } : {}) };
      };
      m.setStyle({
        name: s.name,
        background: '#ffffff',
        classes: s.classes.map((c) => {
          const out: Record<string, unknown> = { key: c.key, color: '#ffffff', linear: c.linear };
          const line = c.line;
          if (line) out['line'] = { ...black(line, line), ...(line.rules ? { rules: line.rules.map((r) => black(r, line)) } : {}) };
          return out;
        }),
      });
    }, [PIXEL_SIZE_MM, thinMm ?? null] as const);
    await waitIdle(page);
  }

  /** The style's rules as blackOnWhite leaves them: those narrower than a pixel drawn 0 wide. */
  const widePixels = (rules: readonly LineRule[]): LineRule[] => rules.map((r) => (r.width + (r.casing ? 2 * r.casing.width : 0) >= PIXEL_SIZE_MM ? r : { ...r, width: 0 }));

  /**
   * The GPU's lines against the CPU's paint, each within a pixel of the other. The CPU paints a
   * pixel whose centre lies within half the width of a line (casing or fill); the GPU's
   * box-filtered coverage is at least a half exactly there, so in black on white a GPU line
   * pixel is one darker than mid grey. Where segments overlap the GPU paints a pixel once, by
   * the segment covering it most, so no GPU line pixel lies more than a pixel from the CPU's.
   * A line narrower than a pixel covers at most a little over half of a pixel its centre
   * passes, so there the half is a coin toss between the two sides' rounding (of z, and so of
   * width and glides): for the CPU's pixels a GPU pixel counts from 45% coverage.
   */
  function compare(label: string, img: Rgba, paint: LinePaint, thin: LinePaint, hidden: Bbox[]): void {
    const cpu = (i: number, j: number): boolean => paint[j * W + i]! !== 0;
    const nearThin = (i: number, j: number): boolean => thin[j * W + i]! !== 0 && paint[j * W + i]! === 0;
    const gpu = (i: number, j: number): boolean => Math.max(...pixel(img, i, j)) < 128;
    const gpuNearHalf = (i: number, j: number): boolean => Math.max(...pixel(img, i, j)) < 141;
    let gpuPixels = 0, cpuPixels = 0;
    const stray: string[] = [], missing: string[] = [];
    for (let j = 0; j < H; j++) for (let i = 0; i < W; i++) {
      if (under(hidden, i, j)) continue;
      if (gpu(i, j)) {
        gpuPixels++;
        // Where a line narrower than a pixel lies (as it grows or shrinks), pixel centres say
        // too little: its casing and fill, each covering less than half, together pass a half.
        if (nearThin(i, j)) continue;
        if (!nearby(cpu, i, j)) stray.push(`(${i}, ${j})`);
      }
      if (cpu(i, j)) {
        cpuPixels++;
        if (!nearby(gpuNearHalf, i, j)) missing.push(`(${i}, ${j})`);
      }
    }
    assert.ok(cpuPixels > 1000 && gpuPixels > 1000, `${label}: lines on screen (CPU ${cpuPixels} px, GPU ${gpuPixels} px)`);
    assert.deepEqual(stray.slice(0, 20), [], `${label}: ${stray.length} of ${gpuPixels} GPU line pixels with no CPU line within a pixel`);
    assert.deepEqual(missing, [], `${label}: CPU line pixels with no GPU line within a pixel`);
  }

  test('the line pass draws, a pixel either way, what the CPU reference draws, flat and under a lens; in the style\'s colours; hidden on request', async () => {
    const { all, cube } = await lines();
    const meta = cube.index.meta;
    assert.ok(all.length > 50, `${all.length} lines in the cube`);
    const z = busiestZ(all, meta.zMax);
    const bbox = meta.extent;
    const view = fitView(meta.extent, W, H, bbox);
    const [x0, y0, x1, y1] = view.bbox;
    const lens = `lens:cx=${(x0 + x1) / 2},cy=${(y0 + y1) / 2},radius=${(x1 - x0) / 4},depth=${-z / 2}`;
    for (const surface of ['flat', lens]) {
      const spec = parseSurface(surface);
      const label = `${surface.split(':')[0]!} at z ${z}`;
      bed.page = await openMap(bed.browser, bed.server.url, { source: 'cube/', bbox: bbox.join(','), z, supersampling: 1, surface });
      const page = bed.page.page;
      assert.equal(await waitIdle(page), true);
      const hidden = await covered(page);
      const px = (x1 - x0) / W, py = (y1 - y0) / H;
      const zAt = (p: number): number => surfaceZ({ base: z, spec }, x0 + ((p % W) + 0.5) * px, y1 - (Math.floor(p / W) + 0.5) * py, meta.zMax);
      const paint = drawLines(view, all, meta.style.lines, { zAt, info: meta });
      // In the style's colours: where the CPU paints a line unlike the map under it, the GPU's
      // pixel is nearer the line's colour than the map without lines is (anti-aliased edges
      // and crossings of lines of different rules blend, so not always equal).
      const on = await screenshot(page);
      await setLinesVisible(page, false);
      const off = await screenshot(page);
      let shown = 0, toward = 0;
      for (let p = 0; p < W * H; p++) {
        const c = linePaintColour(meta.style.lines, paint[p]!);
        const i = p % W, j = Math.floor(p / W);
        if (c === undefined || under(hidden, i, j)) continue;
        const want = hexColour(c), map = pixel(off, i, j);
        if (diff(want, map) <= 40) continue;
        shown++;
        if (diff(pixel(on, i, j), want) < diff(map, want)) toward++;
      }
      assert.ok(shown > 500 && toward >= 0.95 * shown, `${label}: ${toward} of ${shown} line pixels toward the line's colour`);
      // Where they are, in black on white.
      await setLinesVisible(page, true);
      await blackOnWhite(page);
      const wide = widePixels(meta.style.lines);
      compare(label, await screenshot(page), drawLines(view, all, wide, { zAt, info: meta }), drawLines(view, all, wide, { zAt, info: meta }, { minHalfPx: 1.5 }), hidden);
      // Hidden, they leave nothing.
      await setLinesVisible(page, false);
      const blank = await screenshot(page);
      let dark = 0;
      for (let j = 0; j < H; j++) for (let i = 0; i < W; i++) if (!under(hidden, i, j) && Math.max(...pixel(blank, i, j)) < 250) dark++;
      assert.equal(dark, 0, `${label}: with the lines hidden the white map has no line left`);
      await bed.page.close();
      bed.page = null;
    }
  });

  test('with its lines hidden the map keeps no target for them; shown, it makes one; the stats count the targets WebGL was asked for', async () => {
    const { all, cube } = await lines();
    const meta = cube.index.meta;
    const z = busiestZ(all, meta.zMax);
    bed.page = await openMap(bed.browser, bed.server.url, { source: 'cube/', bbox: meta.extent.join(','), z, supersampling: 1, lines: 0 }, { initScript: GL_ALLOCATION_LOG });
    const page = bed.page.page;
    assert.equal(await waitIdle(page), true);
    const RGBA8 = 0x8058;
    const hidden = await glAllocations(page);
    assert.equal(hidden.targets.length, 5, 'ids, aux, depth, surface and colour: none for lines or overlays while the lines are hidden');
    assert.equal((await page.evaluate(() => engine.stats())).targetBytes, hidden.targetBytes);
    await setLinesVisible(page, true);
    const shown = await glAllocations(page);
    assert.deepEqual(shown.targets, [...hidden.targets, RGBA8], 'the lines\' coverage');
    const stats = await page.evaluate(() => engine.stats());
    assert.ok(stats.segments > 0, 'lines drawn');
    assert.equal(stats.targetBytes, shown.targetBytes);
    assert.equal(shown.targetBytes - hidden.targetBytes, 4 * W * H);
  });

  test('a line is as dark at its vertices and joins as along its segments: overlapping segments paint a pixel once', async () => {
    const { all, cube } = await lines();
    const meta = cube.index.meta;
    const z = busiestZ(all, meta.zMax);
    const bbox = meta.extent;
    bed.page = await openMap(bed.browser, bed.server.url, { source: 'cube/', bbox: bbox.join(','), z, supersampling: 1 });
    const page = bed.page.page;
    assert.equal(await waitIdle(page), true);
    const hidden = await covered(page);
    // Half a pixel wide: one segment covers at most 0.75 of a pixel (the box filter over a
    // band of 0.5 px centred on the pixel), so no pixel is darker than a quarter of white.
    // Blended once per segment, a pixel where two segments meet would reach 1 - 0.25² = 0.94.
    const widthPx = 0.5;
    await blackOnWhite(page, widthPx * PIXEL_SIZE_MM);
    const img = await screenshot(page);
    const darkest = Math.round(255 * (1 - (widthPx / 2 + 0.5)));
    let drawn = 0;
    const beads: string[] = [];
    for (let j = 0; j < H; j++) for (let i = 0; i < W; i++) {
      if (under(hidden, i, j)) continue;
      const v = Math.min(...pixel(img, i, j).slice(0, 3));
      if (v < 200) drawn++;
      if (v < darkest - 2) beads.push(`(${i}, ${j}): ${v}`);
    }
    assert.ok(drawn > 1000, `${drawn} pixels of thin lines drawn`);
    assert.deepEqual(beads.slice(0, 20), [], `${beads.length} pixels darker than one segment makes them (${darkest})`);
  });

  test('with supersampling the lines are painted sharp over the accumulated map: the same pixels as without it', async () => {
    const { all, cube } = await lines();
    const meta = cube.index.meta;
    const z = busiestZ(all, meta.zMax);
    const bbox = meta.extent;
    const shots: Rgba[] = [];
    let hidden: Bbox[] = [];
    for (const supersampling of [1, 8]) {
      bed.page = await openMap(bed.browser, bed.server.url, { source: 'cube/', bbox: bbox.join(','), z, supersampling });
      const page = bed.page.page;
      assert.equal(await waitIdle(page), true);
      // A white map: accumulated, it stays white; lines blurred by the jitter would show grey.
      await blackOnWhite(page);
      hidden = await covered(page);
      shots.push(await screenshot(page));
      await bed.page.close();
      bed.page = null;
    }
    const [one, many] = shots as [Rgba, Rgba];
    let dark = 0;
    const unlike: string[] = [];
    for (let j = 0; j < H; j++) for (let i = 0; i < W; i++) {
      if (under(hidden, i, j)) continue;
      if (Math.max(...pixel(one, i, j)) < 128) dark++;
      if (diff(pixel(one, i, j), pixel(many, i, j)) > 2) unlike.push(`(${i}, ${j}): ${pixel(one, i, j).join(' ')} and ${pixel(many, i, j).join(' ')}`);
    }
    assert.ok(dark > 1000, `${dark} line pixels`);
    assert.deepEqual(unlike.slice(0, 20), [], `${unlike.length} pixels unlike with 8 frames of supersampling`);
  });

  test('a click on a line gives the line first, with its class and its feature\'s attributes, then the face under it', async () => {
    const { all, cube } = await lines();
    const meta = cube.index.meta;
    const z = busiestZ(all, meta.zMax);
    const bbox = meta.extent;
    const view = fitView(meta.extent, W, H, bbox);
    const paint = drawLines(view, all, meta.style.lines, { zAt: () => z, info: meta });
    bed.page = await openMap(bed.browser, bed.server.url, { source: 'cube/', bbox: bbox.join(','), z, supersampling: 1 });
    const page = bed.page.page;
    assert.equal(await waitIdle(page), true);
    const hidden = await covered(page);
    // A pixel deep inside a road's fill (its 5 x 5 neighbourhood painted alike), not under a control.
    const roads = meta.style.lines.map((r, i) => (meta.style.classes[r.classIndex]!.key === 'wegdeel' ? 2 + 2 * i : -1));
    let at = -1;
    for (let p = 0; p < W * H && at < 0; p++) {
      const i = p % W, j = Math.floor(p / W);
      if (!roads.includes(paint[p]!) || i < 2 || j < 2 || i >= W - 2 || j >= H - 2) continue;
      if (hidden.some((b) => i >= b[0] - 3 && i <= b[2] + 3 && j >= b[1] - 3 && j <= b[3] + 3)) continue;
      let same = true;
      for (let dj = -2; dj <= 2; dj++) for (let di = -2; di <= 2; di++) if (paint[p + dj * W + di] !== paint[p]) same = false;
      if (same) at = p;
    }
    assert.ok(at >= 0, 'a road line wide enough to click');
    await page.evaluate(() => {
      const w = globalThis as unknown as LinesWindow;
      w.map.on('click', (ev) => (w.clicked = ev as LinesWindow['clicked']));
    });
    await page.mouse.click((at % W) + 0.5, Math.floor(at / W) + 0.5);
    await page.waitForFunction(() => (globalThis as unknown as LinesWindow).clicked !== undefined);
    const clicked = await page.evaluate(() => (globalThis as unknown as LinesWindow).clicked!.features);
    const [line, face] = clicked;
    assert.equal(line?.kind, 'line', JSON.stringify(clicked));
    assert.equal(line.classKey, 'wegdeel');
    // Its attributes are its input feature's, read from the GeoJSON itself; its rule is the one they select.
    const input = JSON.parse(await readFile(otterlo400, 'utf8')) as { features: { properties: Record<string, unknown> }[] };
    const props = input.features[line.feature]!.properties;
    assert.deepEqual(line.properties, props);
    const rule = lineRuleFinder(meta.style.lines)(meta.style.classes.findIndex((c) => c.key === 'wegdeel'), props);
    assert.equal(2 + 2 * rule, paint[at], `the rule of klasse ${JSON.stringify(props['klasse'])} is the one drawn there`);
    assert.equal(face?.kind, 'face');
    assert.ok((face.face ?? 0) > 0);
  });
});
