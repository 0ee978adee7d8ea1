// Run-time style, feature state and the legend, in real Chromium on a real cube of
// bgt_otterlo_400m, through the test page (index.html): setClassStyle recolours exactly the
// pixels of that class (the ID buffer says which) without a request; a whole style is drawn as
// given, and a bad one is refused with each problem named and nothing changed; a real click
// highlights exactly the clicked face's pixels, with the popup's facts and the face's outline;
// the legend lists the cube's classes with their colours and follows changes.
import assert from 'node:assert/strict';
import path from 'node:path';
import { describe, test } from 'node:test';
import { scaleAtZ } from '../format/scale.js';
import type { MapPage } from './helpers/browser.js';
import { openMap } from './helpers/browser.js';
import { repoRoot } from './helpers/cube.js';
import { hexColour, loseAndRestoreContext, pixel, readIds, screenshot, waitIdle, type PageIds, type Rgba } from './helpers/map-page.js';
import { useTestBed } from './helpers/test-bed.js';

const W = 640, H = 480;
/** No pattern shows at this level of detail (about 1:4000; the style's go up to 1:2500). */
const Z = 410;

interface StyleClassJson {
  key: string;
  label: string;
  color: string;
  pattern?: { kind: string; color: string };
}
interface StyleJson {
  name: string;
  background: string;
  classes: StyleClassJson[];
}
interface PickedFeature {
  kind: string;
  face: number;
  classKey: string;
  classLabel: string;
  properties: Record<string, unknown> | null;
  scaleRange: [number, number];
  sliceZ: number;
  outline?: [number, number][][];
}
/** A click or pointermove: everything under the pointer, topmost first (a line of the cube, then the face). */
interface PointerEv {
  features: PickedFeature[];
}
/** The part of VarioMap these tests use beyond the test page's MapApi. */
interface StyleMap {
  getStyle(): StyleJson | null;
  setStyle(s: unknown): unknown;
  setClassStyle(key: string, change: object): unknown;
  setFeatureState(f: { face: number }, s: object): unknown;
  getFeatureState(f: { face: number }): Record<string, unknown>;
  removeFeatureState(f: { face: number }, key?: string): unknown;
  getStatePaint(state: string): { color: string; opacity: number; outlineColor: string; outlineWidth: number };
  queryFeatures(p: [number, number], o?: { outline?: boolean }): Promise<PickedFeature[]>;
  on(type: string, fn: (ev: PointerEv) => void): unknown;
  off(type: string, fn: (ev: PointerEv) => void): unknown;
  getScaleDenominator(): number;
  getBoundsProjected(): [number, number, number, number];
}
interface StyleWindow {
  map: StyleMap;
  clicked?: PickedFeature | null;
  hovered?: number;
  onMove?: (ev: PointerEv) => void;
}

/** The class of the upper face at pixel k (from the ID buffer). */
const classAt = (ids: PageIds, k: number): number => ids.classes[k]! & 0xffff;

/** The error message `fn` (page code calling the map) throws, or null. */
function thrown(p: MapPage, call: string): Promise<string | null> {
  return p.page.evaluate(`(() => { try { ${call}; return null; } catch (e) { return e.message; } })()`);
}

function mix(a: [number, number, number], b: [number, number, number], t: number): [number, number, number] {
  return [0, 1, 2].map((i) => Math.round(a[i]! + (b[i]! - a[i]!) * t)) as [number, number, number];
}

/** Every pixel shows its class's colour in `colours` (by class index), or `background` off the cube. */
function assertDrawnIn(shot: Rgba, ids: PageIds, background: number[], colours: readonly string[]): void {
  for (let k = 0; k < W * H; k++) {
    const want = ids.upper[k] === 0 ? background : hexColour(colours[classAt(ids, k)]!);
    assert.deepEqual(pixel(shot, k % W, Math.floor(k / W)), want, `pixel ${k}`);
  }
}

const near = (a: number[], b: number[], tol: number): boolean => a.every((v, i) => Math.abs(v - b[i]!) <= tol);

describe('run-time style and feature state (bgt_otterlo_400m)', () => {
  const bed = useTestBed(['--no-precompress']);

  // The faces' colours and paints, without the cube's lines over them (e2e/lines.test.ts has those).
  async function open(params: Record<string, string | number> = {}): Promise<MapPage> {
    bed.page = await openMap(bed.browser, bed.server.url, { source: 'cube/', supersampling: 1, z: Z, lines: 0, ...params });
    assert.equal(await waitIdle(bed.page.page), true);
    return bed.page;
  }

  async function redrawn(p: MapPage): Promise<Rgba> {
    assert.equal(await waitIdle(p.page), true);
    return screenshot(p.page);
  }

  test('setClassStyle recolours that class and nothing else, with no request', async () => {
    const p = await open();
    const ids = await readIds(p.page);
    const before = await screenshot(p.page);
    const classes = bed.contents.meta.style.classes;
    // The class with the most pixels on screen.
    const counts = new Map<number, number>();
    for (let k = 0; k < W * H; k++) if (ids.upper[k] !== 0) counts.set(classAt(ids, k), (counts.get(classAt(ids, k)) ?? 0) + 1);
    const [target, pixels] = [...counts].sort((a, b) => b[1] - a[1])[0]!;
    assert.ok(counts.size >= 4 && pixels > 1000, `${counts.size} classes on screen, ${pixels} pixels of the largest`);
    const key = classes[target]!.key;
    const requests = bed.server.log.length;
    await p.page.evaluate((k) => (globalThis as unknown as StyleWindow).map.setClassStyle(k, { color: '#ff00ff' }), key);
    const after = await redrawn(p);
    let recoloured = 0;
    for (let k = 0; k < W * H; k++) {
      const i = k % W, j = Math.floor(k / W);
      const mine = ids.upper[k] !== 0 && classAt(ids, k) === target;
      assert.deepEqual(pixel(after, i, j), mine ? [255, 0, 255] : pixel(before, i, j), `pixel (${i},${j}) of class ${classAt(ids, k)}`);
      if (mine) recoloured++;
    }
    assert.equal(recoloured, pixels);
    assert.equal(bed.server.log.length, requests, `no request: ${bed.server.log.slice(requests).map((r) => r.path).join(', ')}`);
    const style = await p.page.evaluate(() => (globalThis as unknown as StyleWindow).map.getStyle());
    assert.equal(style?.classes[target]?.color, '#ff00ff');
    assert.deepEqual(style?.classes.filter((_, i) => i !== target).map((c) => c.color), classes.filter((_, i) => i !== target).map((c) => c.color));
    // An unknown class is named, with the classes there are.
    assert.match((await thrown(p, "map.setClassStyle('sand', { color: '#ffff00' })")) ?? '', /setClassStyle: no class "sand" \(the classes: "pand", /);
  });

  test('a whole style is drawn as given; a bad one is refused, naming each problem, and nothing changes', async () => {
    const p = await open();
    const ids = await readIds(p.page);
    const before = await screenshot(p.page);
    const original = await p.page.evaluate(() => (globalThis as unknown as StyleWindow).map.getStyle());
    assert.ok(original);
    const bad = { ...original, classes: original.classes.map((c, i) => (i === 0 ? { ...c, color: 'brown' } : i === 1 ? { ...c, pattern: { kind: 'waves', color: '#000000' } } : c)) };
    const message = await thrown(p, `map.setStyle(${JSON.stringify(bad)})`);
    assert.match(message ?? '', /^setStyle: 2 problems: classes\.0\.color: must be a colour "#rrggbb"; classes\.1\.pattern\.kind: must be hatch, dots or cross$/);
    const missing = { ...original, classes: original.classes.slice(1) };
    assert.match((await thrown(p, `map.setStyle(${JSON.stringify(missing)})`)) ?? '', new RegExp(`the cube's "${original.classes[0]!.key}" is missing`));
    assert.deepEqual(await p.page.evaluate(() => (globalThis as unknown as StyleWindow).map.getStyle()), original, 'the style as it was');
    const unchanged = await redrawn(p);
    assert.equal(Buffer.compare(Buffer.from(unchanged.data), Buffer.from(before.data)), 0, 'the picture as it was');

    // A style of the cube's classes in reverse order (an object, as a style file has them), every
    // colour new, a new background: each pixel shows its class's new colour.
    const colours = original.classes.map((_, i) => `#${(0x102030 + i * 0x0f0d0b).toString(16).padStart(6, '0')}`);
    const style = { background: '#202020', classes: Object.fromEntries(original.classes.map((c, i) => [c.key, { color: colours[i], label: c.label }]).reverse()) };
    await p.page.evaluate((s) => (globalThis as unknown as StyleWindow).map.setStyle(s), style);
    const after = await redrawn(p);
    assertDrawnIn(after, ids, [0x20, 0x20, 0x20], colours);
  });

  test('a style given at load time is drawn from the first frame; one that does not fit is refused with an error event', async () => {
    let p = await open();
    const ids = await readIds(p.page);
    const before = await screenshot(p.page);
    const original = await p.page.evaluate(() => (globalThis as unknown as StyleWindow).map.getStyle());
    assert.ok(original);
    await p.close();
    const colours = original.classes.map((_, i) => `#${(0x302010 + i * 0x0b0d0f).toString(16).padStart(6, '0')}`);
    const style = { background: '#404040', classes: Object.fromEntries(original.classes.map((c, i) => [c.key, { color: colours[i], label: c.label }])) };
    p = await open({ style: JSON.stringify(style) });
    const first = await screenshot(p.page);
    assertDrawnIn(first, ids, [0x40, 0x40, 0x40], colours);
    assert.deepEqual((await p.page.evaluate(() => (globalThis as unknown as StyleWindow).map.getStyle()))?.classes.map((c) => c.color), colours);
    await p.close();
    // A colour that is not one: the cube's own style is drawn, and the page hears why.
    const bad = { ...style, classes: { ...style.classes, [original.classes[0]!.key]: { color: 'brown' } } };
    p = await open({ style: JSON.stringify(bad) });
    assert.equal((await p.page.textContent('#info')) ?? '', `style error: setStyle: classes.${original.classes[0]!.key}.color: must be a colour "#rrggbb"`);
    // The test page shows that message over the map.
    await p.page.addStyleTag({ content: '#info { display: none !important; }' });
    assert.equal(Buffer.compare(Buffer.from((await redrawn(p)).data), Buffer.from(before.data)), 0, 'the cube\'s own style');
  });

  test('a real click highlights exactly the clicked face, with what a popup needs and its outline', async () => {
    const p = await open();
    // The test page's own box for the clicked face would cover part of the map.
    await p.page.addStyleTag({ content: '#info { display: none !important; }' });
    const ids = await readIds(p.page);
    const before = await screenshot(p.page);
    // A face with many pixels, clicked well inside it.
    const sizes = new Map<number, number>();
    for (const f of ids.upper) if (f !== 0) sizes.set(f, (sizes.get(f) ?? 0) + 1);
    const inside = (k: number, r: number): boolean => {
      const i = k % W, j = Math.floor(k / W);
      for (let dj = -r; dj <= r; dj++) for (let di = -r; di <= r; di++) if (ids.upper[(j + dj) * W + i + di] !== ids.upper[k]) return false;
      return true;
    };
    const faces = [...sizes].filter(([, n]) => n > 2000 && n < W * H / 4).map(([f]) => f);
    /** A point well inside a large face other than `not`. */
    const pointIn = (not: number): number => {
      for (let k = 10 * W; k < (H - 10) * W; k++) if (ids.upper[k] !== not && faces.includes(ids.upper[k]!) && k % W > 10 && k % W < W - 10 && inside(k, 6)) return k;
      return -1;
    };
    const k0 = pointIn(0);
    assert.ok(k0 >= 0, 'a large face to click');
    const face = ids.upper[k0]!;
    await p.page.evaluate(() => {
      const w = globalThis as unknown as StyleWindow;
      w.map.on('click', (ev) => {
        const face = ev.features.find((f) => f.kind === 'face') ?? null;
        w.clicked = face;
        if (face) w.map.setFeatureState({ face: face.face }, { highlight: true });
      });
    });
    await p.page.mouse.click((k0 % W) + 0.5, Math.floor(k0 / W) + 0.5);
    await p.page.waitForFunction(() => (globalThis as unknown as StyleWindow).clicked !== undefined);
    const after = await redrawn(p);

    // Every pixel of the face changed, and no other: the fill inside, the outline along its edge.
    const painted = async (state: string, f: number, k: number, was: Rgba, now: Rgba): Promise<void> => {
      const paint = await p.page.evaluate((s) => (globalThis as unknown as StyleWindow).map.getStatePaint(s), state);
      const fill = mix(pixel(was, k % W, Math.floor(k / W)), hexColour(paint.color), paint.opacity);
      const r = paint.outlineWidth; // device px at a ratio of 1
      let inner = 0, edge = 0;
      for (let k = 0; k < W * H; k++) {
        const i = k % W, j = Math.floor(k / W);
        if (ids.upper[k] !== f) {
          assert.deepEqual(pixel(now, i, j), pixel(was, i, j), `pixel (${i},${j}) of face ${ids.upper[k]} unchanged`);
          continue;
        }
        let onEdge = false;
        for (let dj = -r; dj <= r && !onEdge; dj++) {
          for (let di = -r; di <= r; di++) {
            const x = i + di, y = j + dj;
            if (x >= 0 && y >= 0 && x < W && y < H && ids.upper[y * W + x] !== f) onEdge = true;
          }
        }
        if (onEdge) {
          edge++;
          assert.deepEqual(pixel(now, i, j), hexColour(paint.outlineColor), `${state} outline at (${i},${j})`);
        } else {
          inner++;
          assert.ok(near(pixel(now, i, j), fill, 1), `${state} fill at (${i},${j}): ${pixel(now, i, j)} for ${fill}`);
        }
      }
      assert.ok(inner > 1000 && edge > 100, `${state}: ${inner} filled and ${edge} outline pixels`);
    };
    // The face's interior is one colour here (no pattern at this scale): its fill is one mix.
    await painted('highlight', face, k0, before, after);
    assert.deepEqual(await p.page.evaluate((f) => (globalThis as unknown as StyleWindow).map.getFeatureState({ face: f }), face), { highlight: true });

    // The click's feature: the face, its class as the style names it, its input attributes, and
    // a scale range holding the scale of the slice there.
    const clicked = await p.page.evaluate(() => (globalThis as unknown as StyleWindow).clicked);
    assert.ok(clicked);
    const cls = bed.contents.meta.style.classes[classAt(ids, k0)]!;
    assert.equal(clicked.face, face);
    assert.deepEqual([clicked.classKey, clicked.classLabel], [cls.key, cls.label]);
    assert.ok(clicked.properties && Object.keys(clicked.properties).length > 0, 'the input feature\'s attributes');
    const scale = scaleAtZ(bed.contents.meta, clicked.sliceZ);
    assert.ok(clicked.scaleRange[0] <= scale && scale <= clicked.scaleRange[1], `1:${scale} in ${clicked.scaleRange}`);

    // Its outline on screen encloses exactly the face's pixels: the rings' signed area (outer
    // rings counter-clockwise, holes clockwise) is the face's pixel count times a pixel's area.
    const picked = (await p.page.evaluate((pt) => (globalThis as unknown as StyleWindow).map.queryFeatures(pt, { outline: true }), [(k0 % W) + 0.5, Math.floor(k0 / W) + 0.5] as [number, number])).find((f) => f.kind === 'face');
    const bounds = await p.page.evaluate(() => (globalThis as unknown as StyleWindow).map.getBoundsProjected());
    const pixelArea = ((bounds[2] - bounds[0]) / W) * ((bounds[3] - bounds[1]) / H);
    let area = 0;
    for (const ring of picked?.outline ?? []) for (let n = 0; n + 1 < ring.length; n++) area += (ring[n]![0] * ring[n + 1]![1] - ring[n + 1]![0] * ring[n]![1]) / 2;
    assert.ok(Math.abs(area / pixelArea - sizes.get(face)!) < 1e-3 * sizes.get(face)!, `outline area ${area / pixelArea} pixels for ${sizes.get(face)}`);

    // Hover, by a real pointer move onto another face: that face's edge in the hover paint,
    // and the highlighted face as it was.
    const k1 = pointIn(face);
    assert.ok(k1 >= 0, 'another large face to hover');
    await p.page.evaluate(() => {
      const w = globalThis as unknown as StyleWindow;
      w.onMove = (ev): void => {
        if (w.hovered !== undefined) w.map.removeFeatureState({ face: w.hovered }, 'hover');
        w.hovered = ev.features.find((f) => f.kind === 'face')?.face;
        if (w.hovered !== undefined) w.map.setFeatureState({ face: w.hovered }, { hover: true });
      };
      w.map.on('pointermove', w.onMove);
    });
    await p.page.mouse.move((k1 % W) + 0.5, Math.floor(k1 / W) + 0.5);
    await p.page.waitForFunction((f) => (globalThis as unknown as StyleWindow).hovered === f, ids.upper[k1]!);
    await painted('hover', ids.upper[k1]!, k1, after, await redrawn(p));
    await p.page.evaluate(() => {
      const w = globalThis as unknown as StyleWindow;
      if (w.onMove) w.map.off('pointermove', w.onMove);
      if (w.hovered !== undefined) w.map.removeFeatureState({ face: w.hovered }, 'hover');
    });

    // Taken away, the picture is as before.
    await p.page.evaluate((f) => (globalThis as unknown as StyleWindow).map.removeFeatureState({ face: f }, 'highlight'), face);
    const cleared = await redrawn(p);
    assert.equal(Buffer.compare(Buffer.from(cleared.data), Buffer.from(before.data)), 0, 'the picture as before');
    assert.match((await thrown(p, 'map.setFeatureState({ face: -3 }, { highlight: true })')) ?? '', /setFeatureState: \{ face \} must be a face id \(an integer from 1 to \d+\), not -3/);
  });

  test('a lost and restored WebGL context keeps the run-time style and the highlight', async () => {
    const p = await open();
    const plain = await screenshot(p.page);
    const ids = await readIds(p.page);
    const k = (H / 2) * W + W / 2;
    assert.ok(ids.upper[k] !== 0, 'a face at the centre');
    const key = bed.contents.meta.style.classes[classAt(ids, k)]!.key;
    await p.page.evaluate(([c, f]) => {
      const m = (globalThis as unknown as StyleWindow).map;
      m.setStyle({ ...m.getStyle(), background: '#000000' });
      m.setClassStyle(c, { color: '#00ffff' });
      m.setFeatureState({ face: f }, { highlight: true });
    }, [key, ids.upper[k]!] as [string, number]);
    const styled = await redrawn(p);
    assert.notDeepEqual(pixel(styled, W / 2, H / 2), pixel(plain, W / 2, H / 2), 'restyled and highlighted');
    await loseAndRestoreContext(p.page);
    const restored = await screenshot(p.page);
    assert.equal(Buffer.compare(Buffer.from(restored.data), Buffer.from(styled.data)), 0, 'the same picture after the context came back');
  });

  test('the legend lists every class with its colour and label, follows setClassStyle, and folds away', async () => {
    const p = await open({ legend: 1 });
    // The test page leaves the library's stylesheet out (no control covers its canvas); a page
    // with a legend has it.
    await p.page.addStyleTag({ path: path.join(repoRoot, 'client/src/ui/vario-map.css') });
    const classes = bed.contents.meta.style.classes;
    const legend = p.page.getByRole('region', { name: 'Legend' });
    const entries = (): Promise<{ key: string; label: string; fill: string; pattern: string | null }[]> =>
      p.page.$$eval('.vario-map-legend-item', (items) =>
        items.map((li) => ({
          key: li.getAttribute('data-class') ?? '',
          label: li.textContent ?? '',
          fill: li.querySelector('rect')?.getAttribute('fill') ?? '',
          pattern: li.querySelector('.vario-map-legend-pattern')?.getAttribute('data-kind') ?? null,
        })),
      );
    assert.equal(await legend.getByRole('listitem').count(), classes.length);
    assert.deepEqual(await entries(), classes.map((c) => ({ key: c.key, label: c.label, fill: c.color, pattern: c.pattern?.kind ?? null })));

    await p.page.evaluate(() => (globalThis as unknown as StyleWindow).map.setClassStyle('waterdeel', { color: '#0000ff', label: 'open water', pattern: null }));
    const water = (await entries()).find((e) => e.key === 'waterdeel');
    assert.deepEqual(water, { key: 'waterdeel', label: 'open water', fill: '#0000ff', pattern: null });

    const toggle = legend.getByRole('button', { name: 'Legend' });
    assert.equal(await toggle.getAttribute('aria-expanded'), 'true');
    await toggle.click();
    assert.equal(await toggle.getAttribute('aria-expanded'), 'false');
    assert.equal(await legend.getByRole('listitem').count(), 0, 'folded away');
    await toggle.click();
    assert.equal(await legend.getByRole('listitem').count(), classes.length);
  });
});
