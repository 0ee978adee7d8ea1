// npm run bench:passes [-- <dataset filter>] [runs=N]: where a frame's GPU time goes. The WebGL2
// client in headless Chromium at 1280x720, for bgt_otterlo_1800m and nlcd_zion at the base
// scale, two middle scales and the full extent, each view held still (a millimetre pan a frame:
// the slice does not move) and zooming (a ten-thousandth of the scale a frame: the slice moves,
// so the colour pass blends). Per frame: its time (from one frame to the next, each a new view)
// and, in turns of their own, each pass's GPU time, every draw and clear timed alone between two
// reads of a pixel (which wait for the GPU): the surface (a clear where the slice is flat), ID,
// line and colour passes by their shaders' names, the clears of the targets, and the rest. Timed alone, passes cannot overlap, so their sum exceeds the frame time; they
// say which pass to work on, not what a frame costs. Medians over `runs` turns (3) of 10 frames.
// SwiftShader is a software GPU: the numbers compare versions on one machine, nothing more.
import path from 'node:path';
import type { Page } from 'playwright-core';
import { launchChromium } from '../e2e/helpers/browser.js';
import { buildBenchCube } from './bench-cube.js';
import { withClientSite } from './client-site.js';
import { benchArgs, datasets, median } from './datasets.js';
import { printTable } from './table.js';

const WIDTH = 1280, HEIGHT = 720, FRAMES = 10;
const MODES = ['still', 'zooming'] as const;
type Mode = (typeof MODES)[number];

/** What a turn of frames measured: frame times, or per-frame pass times by pass name. */
interface Turn {
  frameMs: number[];
  passMs: Record<string, number>[];
  triangles: number;
  segments: number;
}

/** The page's map and engine, as far as this benchmark uses them. */
interface PageMap {
  getMetadata(): unknown;
  whenIdle(): Promise<unknown>;
  getCenterProjected(): [number, number];
  getScaleDenominator(): number;
  jumpTo(v: { centerProjected?: [number, number]; scaleDenominator?: number }): void;
}
interface PageEngine {
  redraw(): void;
  on(t: 'render', f: (s: { triangles: number; segments: number }) => void): void;
  off(t: 'render', f: (s: { triangles: number; segments: number }) => void): void;
}
interface PassTimer {
  on: boolean;
  frame: Record<string, number>;
}
/** The WebGL2 context as far as the timer uses it (this project's Node types have no DOM). */
interface Gl {
  readonly READ_FRAMEBUFFER: number;
  readonly READ_FRAMEBUFFER_BINDING: number;
  readonly RGBA: number;
  readonly UNSIGNED_BYTE: number;
  readonly FRAGMENT_SHADER: number;
  readonly SHADER_TYPE: number;
  getParameter(p: number): unknown;
  getAttachedShaders(p: object): object[] | null;
  getShaderParameter(s: object, p: number): unknown;
  getShaderSource(s: object): string | null;
}
declare const WebGL2RenderingContext: { prototype: object };
declare const map: PageMap;
declare const engine: PageEngine;
declare const passTimer: PassTimer;

/**
 * Runs in the page before its scripts: wraps the WebGL2 calls that draw or clear so that, while
 * `passTimer.on`, each waits for the GPU before and after (a one-pixel read of the canvas) and
 * adds its time to the pass of the program in use (the first comment of its fragment shader,
 * up to the colon), clears to "clears".
 */
function installPassTimer(): void {
  const proto = WebGL2RenderingContext.prototype as Record<string, unknown>;
  const g = globalThis as unknown as { passTimer: PassTimer };
  g.passTimer = { on: false, frame: {} };
  const names = new WeakMap<object, string>();
  let current = 'none';
  type Fn = (this: Gl, ...a: unknown[]) => unknown;
  const original = (name: string): Fn => proto[name] as Fn;
  const useProgram = original('useProgram'), bindFramebuffer = original('bindFramebuffer'), readPixels = original('readPixels');
  const passName = (gl: Gl, p: object): string => {
    let n = names.get(p);
    if (n === undefined) {
      const fs = (gl.getAttachedShaders(p) ?? []).find((s) => gl.getShaderParameter(s, gl.SHADER_TYPE) === gl.FRAGMENT_SHADER);
      const comment = (fs ? gl.getShaderSource(fs) ?? '' : '').split('\n').find((l) => l.startsWith('//')) ?? '// ?';
      n = comment.slice(3).split(':')[0] ?? '?';
      names.set(p, n);
    }
    return n;
  };
  proto['useProgram'] = function (this: Gl, p: object | null) {
    current = p ? passName(this, p) : 'none';
    return useProgram.call(this, p);
  };
  const pixel = new Uint8Array(4);
  const wait = (gl: Gl): void => {
    const read = gl.getParameter(gl.READ_FRAMEBUFFER_BINDING);
    bindFramebuffer.call(gl, gl.READ_FRAMEBUFFER, null);
    readPixels.call(gl, 0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
    bindFramebuffer.call(gl, gl.READ_FRAMEBUFFER, read);
  };
  for (const name of ['drawArrays', 'drawElements', 'clear', 'clearBufferfv', 'clearBufferuiv']) {
    const f = original(name);
    proto[name] = function (this: Gl, ...a: unknown[]) {
      if (!g.passTimer.on) return f.apply(this, a);
      wait(this);
      const t0 = performance.now();
      const r = f.apply(this, a);
      wait(this);
      const pass = name.startsWith('draw') ? current : 'clears';
      g.passTimer.frame[pass] = (g.passTimer.frame[pass] ?? 0) + performance.now() - t0;
      return r;
    };
  }
  // WEBGL_multi_draw's calls are on the extension object: wrapped where it is handed out.
  const getExtension = original('getExtension');
  proto['getExtension'] = function (this: Gl, name: string) {
    const ext = getExtension.call(this, name) as Record<string, unknown> | null;
    if (name === 'WEBGL_multi_draw' && ext && !ext['timed']) {
      const multi = ext['multiDrawElementsWEBGL'] as (...a: unknown[]) => unknown;
      ext['multiDrawElementsWEBGL'] = (...a: unknown[]) => {
        if (!g.passTimer.on) return multi.apply(ext, a);
        wait(this);
        const t0 = performance.now();
        const r = multi.apply(ext, a);
        wait(this);
        g.passTimer.frame[current] = (g.passTimer.frame[current] ?? 0) + performance.now() - t0;
        return r;
      };
      ext['timed'] = true;
    }
    return ext;
  };
}

/** FRAMES frames in `mode`, each a new view, after two to warm up; timed per pass when `timed`. */
function turn(page: Page, mode: Mode, timed: boolean): Promise<Turn> {
  return page.evaluate(
    ([n, mode, timed]) =>
      new Promise<Turn>((resolve) => {
        const [cx, cy] = map.getCenterProjected();
        const scale = map.getScaleDenominator();
        const times: number[] = [], passes: Record<string, number>[] = [];
        let triangles = 0, segments = 0;
        const f = (s: { triangles: number; segments: number }): void => {
          times.push(performance.now());
          if (times.length > 2) {
            triangles += s.triangles;
            segments += s.segments;
            if (timed) passes.push(passTimer.frame);
          }
          passTimer.frame = {};
          passTimer.on = timed && times.length >= 2;
          if (times.length >= n + 3) {
            passTimer.on = false;
            engine.off('render', f);
            const kept = times.slice(2);
            resolve({ frameMs: kept.slice(1).map((t, i) => t - kept[i]!), passMs: passes, triangles: triangles / n, segments: segments / n });
            return;
          }
          const k = times.length % 2;
          if (mode === 'zooming') map.jumpTo({ scaleDenominator: scale * (1 + k * 1e-4) });
          else map.jumpTo({ centerProjected: [cx + k * 1e-3, cy] });
        };
        engine.on('render', f);
        engine.redraw();
      }),
    [FRAMES, mode, timed] as const,
  );
}

async function main(): Promise<void> {
  const { runs, filter } = benchArgs(3);
  const sets = datasets(filter, ['bgt_otterlo_1800m', 'nlcd_zion']);
  const browser = await launchChromium();
  const passNames = ['Surface pass', 'ID pass', 'Line pass', 'Colour pass', 'clears'];
  const rows: string[][] = [['dataset', 'scale', 'mode', 'frame ms', ...passNames.map((p) => `${p.replace(' pass', '')} ms`), 'other ms', 'triangles', 'segments']];
  try {
    for (const d of sets) {
      await withClientSite('ssc-bench-passes-', async ({ dir, url }) => {
        const cube = buildBenchCube(d, path.join(dir, 'cube'));
        const meta = cube.index.meta;
        const [x0, y0, x1, y1] = meta.extent;
        const centre: [number, number] = [(x0 + x1) / 2, (y0 + y1) / 2];
        const full = (Math.max((x1 - x0) / WIDTH, (y1 - y0) / HEIGHT) * 1000) / meta.pixelSizeMm;
        // Base, a third and two thirds of the way to the full extent (geometric), and the full extent.
        const scales = [0, 1 / 3, 2 / 3, 1].map((t) => meta.baseScale * (full / meta.baseScale) ** t);
        for (const scale of scales) {
          const context = await browser.newContext({ viewport: { width: WIDTH, height: HEIGHT } });
          const page = await context.newPage();
          await page.addInitScript(installPassTimer);
          await page.goto(`${url}index.html?source=cube/&center=${centre.join(',')}&scale=${scale}&supersampling=1`);
          await page.waitForFunction(() => typeof map !== 'undefined' && map.getMetadata() !== null);
          await page.evaluate(() => map.whenIdle());
          const frames = new Map<Mode, number[]>(MODES.map((m) => [m, []]));
          const passes = new Map<Mode, Record<string, number>[]>(MODES.map((m) => [m, []]));
          const counts = new Map<Mode, Turn>();
          for (let r = 0; r < runs; r++) {
            for (const mode of MODES) {
              const plain = await turn(page, mode, false);
              frames.get(mode)!.push(median(plain.frameMs));
              counts.set(mode, plain);
              passes.get(mode)!.push(...(await turn(page, mode, true)).passMs);
            }
          }
          await context.close();
          for (const mode of MODES) {
            const per = passes.get(mode)!;
            const known = passNames.map((p) => median(per.map((f) => f[p] ?? 0)));
            const other = median(per.map((f) => Object.entries(f).filter(([k]) => !passNames.includes(k)).reduce((s, [, v]) => s + v, 0)));
            const c = counts.get(mode)!;
            rows.push([d.name, `1:${Math.round(scale)}`, mode, median(frames.get(mode)!).toFixed(0), ...known.map((v) => v.toFixed(1)), other.toFixed(1), Math.round(c.triangles).toString(), Math.round(c.segments).toString()]);
          }
          process.stderr.write(`${d.name} 1:${Math.round(scale)} done\n`);
        }
      });
    }
  } finally {
    await browser.close();
  }
  process.stdout.write(`\nGPU time per pass (each timed alone; ms per frame, medians over ${runs} turns of ${FRAMES} frames), 1280x720, SwiftShader\n`);
  printTable(rows);
}

main().catch((e: unknown) => {
  process.stderr.write(`${e instanceof Error ? e.stack ?? e.message : String(e)}\n`);
  process.exit(1);
});
