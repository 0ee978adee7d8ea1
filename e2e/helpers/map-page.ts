// Driving the test page's map (index.html: window.map, a VarioMap, and window.engine, its
// engine through the internal engineOf()) from the tests.
import type { Page } from 'playwright-core';
import type { IdBuffer as PageIds } from '../../client/src/render/id-buffer.js';

export interface PageCubeMeta {
  zMax: number;
  extent: [number, number, number, number];
  baseScale: number;
  baseFaces: number;
  scaleTable: [number, number][];
  pixelSizeMm: number;
  style: { background: string; classes: { key: string; label: string; color: string; pattern?: { kind: string; color: string; maxScale?: number; minScale?: number } }[] };
}

/** The part of VarioMap the tests use, as seen from the page (structural, no DOM types). */
export interface MapApi {
  whenIdle(): Promise<{ complete: boolean }>;
  loaded(): boolean;
  fitBoundsProjected(b: [number, number, number, number], o?: { sliceZ?: number | null; duration?: number; padding?: number }): Promise<boolean>;
  jumpTo(v: { centerProjected?: [number, number]; scaleDenominator?: number; sliceZ?: number | null }): unknown;
  getCenterProjected(): [number, number];
  getSliceZ(): number;
  getScaleDenominator(): number;
  getSlicingSurface(): { kind: string } & Record<string, unknown>;
  setSlicingSurface(s: string | object): unknown;
  setBlending(b: object): unknown;
  setBoundaries(b: object): unknown;
  setLinesVisible(visible: boolean): unknown;
  setFeatureState(f: { face: number }, s: object): unknown;
  removeFeatureState(f: { face: number }, key?: string): unknown;
  queryFeatures(p: [number, number]): Promise<unknown[]>;
  getMetadata(): PageCubeMeta | null;
  on(type: string, fn: (ev: unknown) => void): unknown;
  once(type: string): Promise<unknown>;
  getCanvas(): { getContext(t: string): unknown };
}

/** The map's engine, as the test page gives it (engineOf(map)): what no public method shows. */
export interface EngineApi {
  getView(): { centerX: number; centerY: number; resolution: number; width: number; height: number };
  setSupersampling(n: number): unknown;
  setGpuMemoryBudget(n: number): unknown;
  readIds(): { width: number; height: number; upper: Uint32Array; lower: Uint32Array; classes: Uint32Array; z: Float32Array; slice: Float32Array } | null;
  chunkStatuses(): Map<string, string>;
  neededChunks(): { visible: string[]; margin: string[] };
  stats(): { frame: number; triangles: number; segments: number; chunks: number; queryMs: number; gpuBytes: number; targetBytes: number };
}


/** Waits until the map is idle (everything fetched and drawn); returns whether it is complete. */
export async function waitIdle(page: Page): Promise<boolean> {
  await page.waitForFunction(() => typeof map !== "undefined" && map.getMetadata() !== null);
  // A map that never settles is a failure to report, not a test that hangs.
  const limitMs = 120_000;
  let timer: NodeJS.Timeout | undefined;
  const timeout = new Promise<never>((_, reject) => {
    timer = setTimeout(() => reject(new Error(`the map did not become idle within ${limitMs / 1000} s`)), limitMs);
  });
  try {
    return await Promise.race([page.evaluate(async () => (await map.whenIdle()).complete), timeout]);
  } finally {
    clearTimeout(timer);
  }
}

/** Waits until every one of `files` is on the GPU (a margin, say, which comes after 'idle'). */
export async function untilOnGpu(page: Page, files: readonly string[]): Promise<void> {
  await page.waitForFunction((fs) => fs.every((f) => engine.chunkStatuses().get(f) === 'gpu'), files);
}

export type { PageIds };

/** The map's ID buffer (upper and lower face, surface z and slice z per pixel). */
export async function readIds(page: Page): Promise<PageIds> {
  const r = await page.evaluate(() => {
    const ids = engine.readIds();
    if (!ids) return null;
    const b64 = (a: ArrayBufferView): string => {
      const u8 = new Uint8Array(a.buffer, a.byteOffset, a.byteLength);
      let s = '';
      for (let i = 0; i < u8.length; i += 0x8000) s += String.fromCharCode(...u8.subarray(i, i + 0x8000));
      return btoa(s);
    };
    return { width: ids.width, height: ids.height, upper: b64(ids.upper), lower: b64(ids.lower), classes: b64(ids.classes), z: b64(ids.z), slice: b64(ids.slice) };
  });
  if (!r) throw new Error('the map has no ID buffer (no WebGL2, or not drawn yet)');
  const u32 = (s: string): Uint32Array => {
    const b = Buffer.from(s, 'base64');
    return new Uint32Array(b.buffer, b.byteOffset, b.byteLength / 4).slice();
  };
  const f32 = (s: string): Float32Array => {
    const b = Buffer.from(s, 'base64');
    return new Float32Array(b.buffer, b.byteOffset, b.byteLength / 4).slice();
  };
  return { width: r.width, height: r.height, upper: u32(r.upper), lower: u32(r.lower), classes: u32(r.classes), z: f32(r.z), slice: f32(r.slice) };
}

export interface Rgba {
  width: number;
  height: number;
  data: Uint8Array;
}

/** What the user sees: a screenshot of the page as RGBA pixels. */
export async function screenshot(page: Page): Promise<Rgba> {
  const { PNG } = await import('pngjs');
  const png = PNG.sync.read(await page.screenshot({ type: 'png' }));
  return { width: png.width, height: png.height, data: new Uint8Array(png.data.buffer, png.data.byteOffset, png.data.byteLength) };
}

/**
 * Loses the map's WebGL context (WEBGL_lose_context), calls `whileLost`, restores the context
 * and waits until the map is idle again.
 */
export async function loseAndRestoreContext(page: Page, whileLost: () => Promise<void> = async () => {}): Promise<void> {
  await page.evaluate(async () => {
    const ext = (map.getCanvas().getContext('webgl2') as { getExtension(n: string): { loseContext(): void; restoreContext(): void } }).getExtension('WEBGL_lose_context');
    const lost = map.once('contextlost');
    ext.loseContext();
    await lost;
    (globalThis as unknown as { restore: () => void }).restore = () => ext.restoreContext();
  });
  await whileLost();
  await page.evaluate(async () => {
    const restored = map.once('contextrestored');
    (globalThis as unknown as { restore: () => void }).restore();
    await restored;
  });
  if (!(await waitIdle(page))) throw new Error('the map is not complete after its context was restored');
}

export function pixel(img: Rgba, i: number, j: number): [number, number, number] {
  const o = 4 * (j * img.width + i);
  return [img.data[o]!, img.data[o + 1]!, img.data[o + 2]!];
}

export function hexColour(hex: string): [number, number, number] {
  const n = parseInt(hex.slice(1), 16);
  return [(n >> 16) & 255, (n >> 8) & 255, n & 255];
}

/**
 * An init script (openMap's initScript) that logs, as WebGL is asked, every program linked and
 * every texture and renderbuffer allocated: read back by glAllocations.
 */
export const GL_ALLOCATION_LOG = `window.glLog = { links: 0, storage: [] };
  const P = WebGL2RenderingContext.prototype, link = P.linkProgram, tex = P.texStorage2D, rb = P.renderbufferStorage;
  P.linkProgram = function (p) { window.glLog.links++; return link.call(this, p); };
  P.texStorage2D = function (t, levels, format, w, h) { window.glLog.storage.push([format, w, h]); return tex.call(this, t, levels, format, w, h); };
  P.renderbufferStorage = function (t, format, w, h) { window.glLog.storage.push([format, w, h]); return rb.call(this, t, format, w, h); };`;

/** Bytes a pixel of each internal format the map allocates at the canvas's size takes. */
const FORMAT_BYTES = new Map([
  [0x823c, 8], // RG32UI
  [0x822e, 4], // R32F
  [0x881a, 8], // RGBA16F
  [0x8058, 4], // RGBA8
  [0x8cac, 4], // DEPTH_COMPONENT32F
]);

/**
 * What GL_ALLOCATION_LOG saw: programs linked, the formats of the textures and renderbuffers of
 * the canvas's size (the frame's targets) in order, and their bytes.
 */
export async function glAllocations(page: Page): Promise<{ links: number; targets: number[]; targetBytes: number }> {
  const { links, sized } = await page.evaluate(() => {
    const w = globalThis as unknown as { glLog: { links: number; storage: [number, number, number][] }; document: { querySelector(s: string): { width: number; height: number } } };
    const c = w.document.querySelector('canvas');
    return { links: w.glLog.links, sized: w.glLog.storage.filter(([, tw, th]) => tw === c.width && th === c.height) };
  });
  let targetBytes = 0;
  for (const [f, w, h] of sized) {
    const b = FORMAT_BYTES.get(f);
    if (b === undefined) throw new Error(`a target of format 0x${f.toString(16)}, which glAllocations does not know`);
    targetBytes += b * w * h;
  }
  return { links, targets: sized.map(([f]) => f), targetBytes };
}
