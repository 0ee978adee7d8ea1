// Driving the demo page's VarioMap (window.map, the public API) from the tests: opening it,
// reading its camera, and recording what it did (moves, frames, chunk requests) in the page.
import type { Browser, Page } from 'playwright-core';
import { openMap, type MapPage, type OpenOptions } from './browser.js';

/** The part of VarioMap the tests use, as seen from the page (structural, no DOM types). */
export interface VarioApi {
  getCenter(): { lng: number; lat: number };
  getCenterProjected(): [number, number];
  getZoom(): number;
  getScaleDenominator(): number;
  getSliceZ(): number;
  getBoundsProjected(): [number, number, number, number];
  getBounds(): { getWest(): number; getSouth(): number; getEast(): number; getNorth(): number };
  setZoom(zoom: number): unknown;
  fitBounds(b: [number, number, number, number], o?: { duration?: number; padding?: number }): Promise<boolean>;
  getMetadata(): { zMax: number; baseScale: number; pixelSizeMm: number; extent: [number, number, number, number] } | null;
  getSettings(): { zoomStep: number; zoomDurationMs: number; panDurationMs: number; minZoomFrames: number; comparisonMode: boolean };
  setSettings(s: object): unknown;
  getSlicingSurface(): { kind: string } & Record<string, unknown>;
  isMoving(): boolean;
  jumpTo(o: { center?: [number, number]; centerProjected?: [number, number]; scaleDenominator?: number; zoom?: number }): unknown;
  easeTo(o: { centerProjected?: [number, number]; scaleDenominator?: number; duration?: number }): Promise<boolean>;
  flyTo(o: { centerProjected?: [number, number]; scaleDenominator?: number; duration?: number; speed?: number }): Promise<boolean>;
  project(lngLat: [number, number]): [number, number];
  unproject(p: [number, number]): { lng: number; lat: number };
  projectProjected(xy: [number, number]): [number, number];
  unprojectProjected(p: [number, number]): [number, number];
  whenIdle(): Promise<{ complete: boolean }>;
  remove(): void;
  getCanvasContainer(): { getAttribute(n: string): string | null; tabIndex: number };
  getContainer(): object;
  on(type: string, fn: (ev: unknown) => void): unknown;
  off(type: string, fn: (ev: unknown) => void): unknown;
}

export interface VarioWindow {
  map: VarioApi;
  /** What record() collects. */
  rec: Rec[];
}

export interface Rec {
  /** performance.now() */
  t: number;
  type: string;
  x: number;
  y: number;
  scale: number;
  z: number;
  bounds: [number, number, number, number];
  file?: string;
}

export interface Camera {
  x: number;
  y: number;
  scale: number;
}

/** Opens the demo (demo.html, built on the public API) on the test cube and waits until it is idle. */
export async function openDemo(browser: Browser, baseUrl: string, params: Record<string, string | number> = {}, opts: OpenOptions = {}): Promise<MapPage> {
  const mp = await openMap(browser, baseUrl, { source: 'cube/', supersampling: 1, sw: 0, ...params }, { page: 'demo.html', ...opts });
  await idle(mp.page);
  return mp;
}

/** Waits until the map has its metadata and is idle; fails after two minutes instead of hanging. */
export async function idle(page: Page): Promise<void> {
  await page.waitForFunction(() => {
    const w = globalThis as unknown as Partial<VarioWindow>;
    return w.map !== undefined && w.map.getMetadata() !== null;
  });
  await page.waitForFunction(() => !(globalThis as unknown as VarioWindow).map.isMoving(), null, { timeout: 120_000 });
  await page.evaluate(() => (globalThis as unknown as VarioWindow).map.whenIdle());
}

export function camera(page: Page): Promise<Camera> {
  return page.evaluate(() => {
    const m = (globalThis as unknown as VarioWindow).map;
    const [x, y] = m.getCenterProjected();
    return { x, y, scale: m.getScaleDenominator() };
  });
}

/** Starts recording the map's moves, frames and chunk requests into window.rec. */
export async function record(page: Page): Promise<void> {
  await page.evaluate(() => {
    const w = globalThis as unknown as VarioWindow & { recording?: boolean };
    w.rec = [];
    if (w.recording) return;
    w.recording = true;
    for (const type of ['move', 'render', 'movestart', 'moveend', 'dataloading']) {
      w.map.on(type, (ev) => {
        const [x, y] = w.map.getCenterProjected();
        const r: Rec = { t: performance.now(), type, x, y, scale: w.map.getScaleDenominator(), z: w.map.getSliceZ(), bounds: w.map.getBoundsProjected() };
        if (type === 'dataloading') r.file = (ev as { file: string }).file;
        w.rec.push(r);
      });
    }
  });
}

export function recorded(page: Page): Promise<Rec[]> {
  return page.evaluate(() => (globalThis as unknown as VarioWindow).rec);
}

/** Waits until the map has stopped moving and `done` (a page-side test of the camera) holds. */
export async function settle(page: Page, done: string): Promise<void> {
  await page.waitForFunction(`!window.map.isMoving() && (${done})`, null, { timeout: 120_000 });
}

/** The ground point (the cube's projected CRS) under a CSS pixel of the map. */
export function groundAt(page: Page, p: [number, number]): Promise<[number, number]> {
  return page.evaluate((q) => (globalThis as unknown as VarioWindow).map.unprojectProjected(q), p);
}

/** How many CSS pixels apart two ground points are at a scale. */
export function apart(a: [number, number], b: [number, number], scale: number, pixelSizeMm: number): number {
  return Math.hypot(a[0] - b[0], a[1] - b[1]) / resolution(scale, pixelSizeMm);
}

/** Ground units per CSS pixel at a scale. */
export function resolution(scale: number, pixelSizeMm: number): number {
  return (scale * pixelSizeMm) / 1000;
}

/** The little of the page's document the tests touch (the Node build has no DOM types). */
export interface PageDocument {
  activeElement: { classList: { contains(c: string): boolean } } | null;
  querySelectorAll(selector: string): Iterable<{ getAttribute(name: string): string | null }>;
  addEventListener(type: string, fn: () => void, options?: object): void;
}

export interface PageWindow {
  document: PageDocument;
}
