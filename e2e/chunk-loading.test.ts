// Chunk loading in the worker against a server that misbehaves on purpose: every chunk fetched
// once while it stays needed, the nearest first; requests for a view left behind aborted; a
// small GPU memory budget evicts and later fetches again; before the first complete map an
// incomplete one is drawn at most every 250 ms; 30% failing requests still give a
// complete map; a 404 and corrupt chunks are reported as errors; sub-index files load on
// demand; gzip bodies without Content-Encoding are read; at the floor the floor chunks come
// first, the cube's after them as the margin. The cube is a real one of
// bgt_otterlo_400m in small chunks (about 60) with sub-index files.
import assert from 'node:assert/strict';
import { readFile } from 'node:fs/promises';
import { request } from 'node:http';
import path from 'node:path';
import { after, afterEach, before, describe, test } from 'node:test';
import type { Browser } from 'playwright-core';
import { decodeChunk } from '../format/chunk.js';
import type { ChunkLeaf, ExternalNode, InnerNode } from '../format/cube-index.js';
import { boxMeets } from '../format/index-query.js';
import { fitBbox, growBbox, viewBbox, type Bbox } from '../client/src/geometry/view.js';
import { keepUpwardTriangles } from '../client/src/source/upward-triangles.js';
import { lineSegmentPayload } from '../client/src/source/line-chunk-fetch.js';
import { payloadBytes } from '../client/src/source/worker-protocol.js';
import { decodeLineChunk } from '../format/line-chunk.js';
import { openMap, type MapPage } from './helpers/browser.js';
import { compareIds, cpuSlice, type BuiltCube, type CubeContents } from './helpers/cube.js';
import { checkAndClose, setUpTestBed, tearDownTestBed } from './helpers/test-bed.js';
import { eventually } from '../testing/event-loop.js';
import { readIds, untilOnGpu, waitIdle, type PageIds } from './helpers/map-page.js';
import { noFaults, type LoggedRequest, type TestServer } from './helpers/test-server.js';
import { assertAskedBeforeScript as assertAskedBefore, WORKER_SCRIPT } from './helpers/worker-script.js';

const W = 640, H = 480;
const MARGIN = 0.25; // the map's default prefetch margin

describe('chunk loading (bgt_otterlo_400m in about 60 chunks)', () => {
  let cube: BuiltCube;
  let contents: CubeContents;
  let server: TestServer;
  let browser: Browser;
  let mp: MapPage | null = null;
  let logStart = 0;
  /** What each chunk takes on the GPU (the memory budget's unit): its decoded vertices and its upward triangles. */
  const gpuBytes = new Map<string, number>();

  before(async () => {
    ({ cube, contents, server, browser } = await setUpTestBed(['--chunk-bytes', '16384', '--sub-index-bytes', '3000']));
    assert.ok(contents.leaves.length >= 30, `${contents.leaves.length} chunks`);
    assert.ok(contents.subIndexFiles.length >= 2, `${contents.subIndexFiles.length} sub-index files`);
    for (const l of contents.leaves) {
      const c = await decodeChunk(await readFile(path.join(cube.dir, l.file)), l.file);
      gpuBytes.set(l.file, c.vertexByteLength + c.indices.BYTES_PER_ELEMENT * 3 * keepUpwardTriangles(c.positions, c.indices));
    }
    // Line chunks share the budget: their segments as the map holds them.
    for (const l of contents.lines) {
      const payload = { ...lineSegmentPayload(await decodeLineChunk(await readFile(path.join(cube.dir, l.file)), l.file), contents.meta), file: l.file, bbox: l.bbox, verified: true };
      gpuBytes.set(l.file, payloadBytes(payload));
    }
  });

  afterEach(async () => {
    await checkAndClose(mp);
    mp = null;
    Object.assign(server.faults, noFaults());
  });

  after(async () => {
    await tearDownTestBed({ cube, server, browser });
  });

  const ext = (): Bbox => contents.meta.extent;
  /** A box of `w` by `h` metres with its lower left corner at (fx, fy) of the extent. */
  const box = (fx: number, fy: number, w: number, h: number): Bbox => {
    const [x0, y0, x1, y1] = ext();
    const x = x0 + fx * (x1 - x0), y = y0 + fy * (y1 - y0);
    return [x, y, x + w, y + h];
  };
  /** Views of 70 x 52 m over the extent, row by row from the south west. */
  const candidates = (): Bbox[] => {
    const out: Bbox[] = [];
    for (let fy = 0.02; fy < 0.85; fy += 0.06) for (let fx = 0.02; fx < 0.8; fx += 0.06) out.push(box(fx, fy, 70, 52));
    return out;
  };
  /**
   * The first pair of candidate views with the property a test needs (the chunking is the
   * build's to choose, so the tests look for suitable places rather than assume them).
   */
  const pickPair = (ok: (a: Bbox, b: Bbox) => boolean, second: (a: Bbox) => Bbox[] = () => candidates()): [Bbox, Bbox] => {
    for (const a of candidates()) for (const b of second(a)) if (ok(a, b)) return [a, b];
    throw new Error('no pair of views with the property this test needs (is the cube in small chunks?)');
  };
  const files = (ls: ChunkLeaf[]): Set<string> => new Set(ls.map((l) => l.file));
  /** Chunks on screen in view b that view a did not need at all. */
  const fresh = (a: Bbox, b: Bbox, z: number): ChunkLeaf[] => needed(b, z).visible.filter((l) => !files(needed(a, z).all).has(l.file));
  /** The chunks a view of `bbox` at z needs on screen and with the prefetch margin. */
  const needed = (bbox: Bbox, z: number): { visible: ChunkLeaf[]; all: ChunkLeaf[] } => {
    const v = viewBbox(fitBbox(bbox, W, H));
    const m = growBbox(v, MARGIN);
    return {
      visible: contents.leaves.filter((l) => boxMeets(l.bbox, { ground: v, zMin: z, zMax: z })),
      all: contents.leaves.filter((l) => boxMeets(l.bbox, { ground: m, zMin: z, zMax: z })),
    };
  };
  /** The sub-index files a query reaches (their node's box meets it). */
  const reachedRefs = (ground: Bbox, z: number): string[] => {
    const out: string[] = [];
    const walk = (n: InnerNode | ExternalNode | ChunkLeaf): void => {
      if (!boxMeets(n.bbox, { ground, zMin: z, zMax: z })) return;
      if ('ref' in n) {
        out.push(n.ref);
        walk(contents.subs.get(n.ref)!);
      } else if ('children' in n) n.children.forEach(walk);
    };
    walk(contents.root);
    return out;
  };
  const chunkRequests = (): LoggedRequest[] => server.log.slice(logStart).filter((e) => /^\/cube\/[cb]-/.test(e.path));
  const fileOf = (e: LoggedRequest): string => e.path.slice('/cube/'.length);
  /**
   * The requests for `file`: refused with 429 (Retry-After: 2), then asked for again two seconds
   * later or more. Both times are the server's; the answer's way to the browser only makes the gap longer.
   */
  const askedAgainAfter429 = (file: string, what: string): LoggedRequest[] => {
    const asked = chunkRequests().filter((r) => fileOf(r) === file);
    assert.deepEqual(asked.map((r) => r.outcome), [429, 200], what);
    const waited = asked[1]!.start - asked[0]!.end;
    assert.ok(waited >= 2000, `${file}: asked again ${waited} ms after the 429`);
    return asked;
  };
  const countBy = (rs: LoggedRequest[]): Map<string, number> => {
    const m = new Map<string, number>();
    for (const r of rs) m.set(fileOf(r), (m.get(fileOf(r)) ?? 0) + 1);
    return m;
  };

  async function open(bbox: Bbox, z: number, extra: Record<string, string | number> = {}, expect: RegExp[] = [], initScript?: string): Promise<MapPage> {
    logStart = server.log.length;
    mp = await openMap(browser, server.url, { source: 'cube/', bbox: bbox.join(','), z, supersampling: 1, ...extra }, initScript ? { expect, initScript } : { expect });
    return mp;
  }

  /** Records the map's error events from now on; the function returned reads them back. */
  async function recordErrors(p: MapPage): Promise<() => Promise<{ kind: string; status?: number; file?: string; message: string }[]>> {
    await p.page.evaluate(() => {
      const errors: unknown[] = [];
      (globalThis as unknown as { errors: unknown[] }).errors = errors;
      map.on('error', (e) => errors.push(e));
    });
    return () => p.page.evaluate(() => (globalThis as unknown as { errors: { kind: string; status?: number; file?: string; message: string }[] }).errors);
  }

  async function goTo(p: MapPage, bbox: Bbox, z: number): Promise<void> {
    await p.page.evaluate(([b, zz]) => map.fitBoundsProjected(b, { sliceZ: zz, duration: 0 }), [bbox, z] as const);
  }

  /** The map's picture (`gpu`, read already; else read now) equals the CPU slicer's of `bbox` at z. */
  async function assertMatchesSlicer(p: MapPage, bbox: Bbox, z: number, label: string, gpu?: PageIds): Promise<void> {
    gpu ??= await readIds(p.page);
    const ref = await cpuSlice(cube.dir, { step: z, width: W, height: H, bbox });
    const c = compareIds(gpu.upper, ref, W, H);
    // Face boundaries only here; slice-accuracy.test.ts covers the sub-pixel cases.
    assert.ok(c.share >= 0.995, `${label}: ${(100 * c.share).toFixed(3)}% equal to the CPU slicer; ${c.examples.join('; ')}`);
  }

  test('each chunk is fetched once while it stays needed, and the map is complete', async () => {
    // Five pans of 12 m east, somewhere the views reach only some of the sub-index files.
    const pans = (a: Bbox): Bbox[] => [0, 1, 2, 3, 4].map((k) => [a[0] + 12 * k, a[1], a[2] + 12 * k, a[3]] as Bbox);
    const reachedBy = (vs: Bbox[], zz: number): Set<string> => new Set(vs.flatMap((v) => reachedRefs(growBbox(viewBbox(fitBbox(v, W, H)), MARGIN), zz)));
    const fits = (a: Bbox, zz: number): boolean => reachedBy(pans(a), zz).size < contents.subIndexFiles.length && needed(a, zz).visible.length >= 3;
    // At some z: the chunks a view of the whole extent needs come first in the plan, so the
    // first sub-index files may reach over the whole ground up to that view's z.
    const z = [30, 120, 240, 360, 420].find((zz) => candidates().some((a) => fits(a, zz)));
    assert.ok(z !== undefined, 'a z where some views reach only some of the sub-index files');
    const [first] = pickPair((a) => fits(a, z), (a) => [a]);
    const views = pans(first);
    const p = await open(views[0]!, z);
    assert.equal(await waitIdle(p.page), true);
    for (const v of views.slice(1)) {
      await goTo(p, v, z);
      assert.equal(await waitIdle(p.page), true);
    }
    const counts = countBy(chunkRequests());
    const twice = [...counts].filter(([, n]) => n > 1);
    assert.deepEqual(twice, [], 'no chunk requested twice');
    const union = new Set(views.flatMap((v) => needed(v, z).all.map((l) => l.file)));
    const visible = new Set(views.flatMap((v) => needed(v, z).visible.map((l) => l.file)));
    // Besides, the first view just above the floor's top draws the floor on screen under itself
    // while its own chunks come (its interim floor).
    const interim = files(floorOnScreen(views[0]!));
    for (const f of counts.keys()) assert.ok(union.has(f) || interim.has(f), `${f} was fetched but no view needed it`);
    for (const f of visible) assert.ok(counts.has(f), `${f} was on screen but never fetched`);
    assert.ok(visible.size >= 3 && visible.size < contents.leaves.length / 2, `${visible.size} chunks on screen: a zoomed-in view`);
    const statuses = await p.page.evaluate(() => [...engine.chunkStatuses()]);
    const last = needed(views[views.length - 1]!, z).visible;
    for (const l of last) assert.equal(new Map(statuses).get(l.file), 'gpu', `${l.file} is on the GPU`);
    // Sub-index files: exactly those the views reach, each once.
    const subs = countBy(server.log.slice(logStart).filter((e) => /^\/cube\/i-/.test(e.path)));
    const reached = reachedBy(views, z);
    assert.ok(reached.size >= 1 && reached.size < contents.subIndexFiles.length, `the views reach ${reached.size} of ${contents.subIndexFiles.length} sub-index files`);
    assert.deepEqual(new Set(subs.keys()), reached);
    for (const [f, n] of subs) assert.equal(n, 1, `${f} fetched ${n} times`);
    await assertMatchesSlicer(p, views[views.length - 1]!, z, 'after the pans');
  });

  /** The floor chunks a view of `bbox` at the base scale shows. */
  const floorOnScreen = (bbox: Bbox): ChunkLeaf[] => contents.floorLeaves.filter((l) => boxMeets(l.bbox, { ground: viewBbox(fitBbox(bbox, W, H)), zMin: 0, zMax: 0 }));

  test("just above the floor's top a first view draws the floor on screen under itself while its own chunks come: that picture is the floor's, the complete one its own", async () => {
    // The cube's chunks are held back until the floor's picture has been read.
    let release = (): void => {};
    const held = new Promise<void>((resolve) => (release = resolve));
    server.faults.heldUntil = (f) => (/^c-/.test(f) ? held : undefined);
    try {
      const z = 2;
      assert.ok(z > contents.floorTop);
      const [view] = pickPair((a) => floorOnScreen(a).length >= 2, (a) => [a]);
      const p = await open(view, z);
      const floor = [...files(floorOnScreen(view))];
      // A picture drawn with the floor on the GPU: an incomplete one is drawn at most 250 ms
      // (PARTIAL_FRAME_MS) after its chunks went up, or it was drawn already.
      await p.page.evaluate(async (fs) => {
        while (!fs.every((f) => engine.chunkStatuses().get(f) === 'gpu')) await map.once('render');
        await Promise.race([map.once('render'), new Promise((resolve) => setTimeout(resolve, 400))]);
      }, floor);
      // The picture and the chunks' statuses as they are now, before the cube's chunks may come.
      const interimIds = await readIds(p.page);
      const statuses = new Map(await p.page.evaluate(() => [...engine.chunkStatuses()]));
      release();
      const own = needed(view, z).visible;
      assert.ok(own.some((l) => statuses.get(l.file) !== 'gpu'), 'the premise: read while some of the view\'s own chunks were still coming');
      await assertMatchesSlicer(p, view, 0, 'the interim picture: the floor', interimIds);
      assert.equal(await waitIdle(p.page), true);
      await assertMatchesSlicer(p, view, z, 'complete');
      const order = chunkRequests().map(fileOf);
      const firstCube = order.findIndex((f) => f.startsWith('c-'));
      assert.deepEqual(new Set(order.slice(0, firstCube)), new Set(floor), 'the floor on screen, before any of the cube\'s chunks');
      assert.equal(order.filter((f) => f.startsWith('b-')).length, floor.length, 'each floor chunk once, and no other');
    } finally {
      release();
    }
  });

  test('at the floor the first complete map needs the floor chunks alone, and equals the CPU slicer', async () => {
    // The cube's own chunks are all missing: what the map shows comes from the floor chunks.
    server.faults.notFound = files(contents.leaves);
    const [view] = pickPair((a) => floorOnScreen(a).length >= 2, (a) => [a]);
    const p = await open(view, 0);
    assert.equal(await waitIdle(p.page), true, 'complete without any of the cube\'s chunks');
    await assertMatchesSlicer(p, view, 0, 'at the floor');
    const onScreen = floorOnScreen(view);
    const counts = countBy(chunkRequests());
    for (const l of onScreen) assert.equal(counts.get(l.file), 1, `${l.file} (floor, on screen) fetched once`);
    const floorFiles = files(contents.floorLeaves);
    for (const f of counts.keys()) assert.ok(floorFiles.has(f) || server.faults.notFound.has(f), `${f} is a chunk of the cube`);
    assert.ok(contents.floorTop > 0 && contents.floorLeaves.length > 1, `${contents.floorLeaves.length} floor chunks below z ${contents.floorTop}`);
  });

  /** The first request for `what` went out while the worker's script was still coming (this test's log). */
  const assertAskedBeforeScript = (what: string, asked: LoggedRequest | undefined): void => assertAskedBefore(server.log.slice(logStart), what, asked);

  test('at the floor the first view\'s floor chunks are asked for while the worker\'s script is still coming, each once, and the map equals the CPU slicer', async () => {
    // The worker's script comes a second late, as its 33 kB gzip would on a slow phone network:
    // the map reads index.json and fetches the first view's floor chunks for the worker meanwhile.
    server.faults.appDelayMs = (path) => (WORKER_SCRIPT.test(path) ? 1000 : 0);
    const [view] = pickPair((a) => floorOnScreen(a).length >= 2, (a) => [a]);
    const p = await open(view, 0);
    assert.equal(await waitIdle(p.page), true);
    const requests = chunkRequests();
    for (const l of floorOnScreen(view)) {
      const asked = requests.filter((r) => fileOf(r) === l.file);
      assert.equal(asked.length, 1, `${l.file} fetched once`);
      assertAskedBeforeScript(l.file, asked[0]);
    }
    await assertMatchesSlicer(p, view, 0, 'at the floor, its chunks fetched by the map');
  });

  test('above the floor the sub-index files the first view reaches are asked for while the worker\'s script is still coming, each once', async () => {
    server.faults.appDelayMs = (path) => (WORKER_SCRIPT.test(path) ? 1000 : 0);
    const z = 30;
    assert.ok(z > contents.floorTop, `z ${z} above the floor's top ${contents.floorTop}`);
    const reachedAtRoot = (a: Bbox): string[] => {
      const q = { ground: growBbox(viewBbox(fitBbox(a, W, H)), MARGIN), zMin: z, zMax: z };
      return contents.root.children.flatMap((n) => ('ref' in n && boxMeets(n.bbox, q) ? [n.ref] : []));
    };
    const [view] = pickPair((a) => reachedAtRoot(a).length >= 1, (a) => [a]);
    const p = await open(view, z);
    assert.equal(await waitIdle(p.page), true);
    for (const ref of reachedAtRoot(view)) {
      const asked = server.log.slice(logStart).filter((e) => e.path === `/cube/${ref}`);
      assert.equal(asked.length, 1, `${ref} fetched once`);
      assertAskedBeforeScript(ref, asked[0]);
    }
    await assertMatchesSlicer(p, view, z, 'above the floor, its sub-index files fetched by the map');
  });

  test('a floor chunk the map could not fetch for the worker (a 503) the worker fetches itself, and the map comes complete', async () => {
    server.faults.appDelayMs = (path) => (WORKER_SCRIPT.test(path) ? 500 : 0);
    const [view] = pickPair((a) => floorOnScreen(a).length >= 2, (a) => [a]);
    const failing = floorOnScreen(view)[0]!.file;
    server.faults.unavailableOnce = new Set([failing]);
    const p = await open(view, 0, {}, [/Failed to load resource: the server responded with a status of 503/]);
    const errors = await recordErrors(p);
    assert.equal(await waitIdle(p.page), true);
    const asked = chunkRequests().filter((r) => fileOf(r) === failing);
    assert.deepEqual(asked.map((r) => r.outcome), [503, 200], `${failing}: the map's request, then the worker's`);
    assert.deepEqual(await errors(), [], 'nothing for the page to hear of');
    await assertMatchesSlicer(p, view, 0, 'at the floor, one chunk fetched by the worker');
  });

  test('a floor chunk the server refuses (a 404) when the map fetches it for the worker is not asked for again: the view draws from the cube\'s chunks', async () => {
    server.faults.appDelayMs = (path) => (WORKER_SCRIPT.test(path) ? 1000 : 0);
    const [view] = pickPair((a) => floorOnScreen(a).length >= 2, (a) => [a]);
    const missing = floorOnScreen(view)[0]!.file;
    server.faults.notFound.add(missing);
    const p = await open(view, 0, {}, [/Failed to load resource: the server responded with a status of 404/]);
    assert.equal(await waitIdle(p.page), true);
    const asked = chunkRequests().filter((r) => fileOf(r) === missing);
    assert.deepEqual(asked.map((r) => r.outcome), [404], `${missing}: the map's request alone`);
    assertAskedBeforeScript(`${missing}, by the map,`, asked[0]);
    await assertMatchesSlicer(p, view, 0, 'at the floor, one floor chunk missing');
  });

  test('a floor chunk refused with 429 and Retry-After: 2 when the map fetches it for the worker is asked for again two seconds later, by the worker', async () => {
    server.faults.appDelayMs = (path) => (WORKER_SCRIPT.test(path) ? 1000 : 0);
    const [view] = pickPair((a) => floorOnScreen(a).length >= 2, (a) => [a]);
    const limited = floorOnScreen(view)[0]!.file;
    server.faults.tooManyOnce.set(limited, 2);
    const p = await open(view, 0, {}, [/Failed to load resource: the server responded with a status of 429/]);
    assert.equal(await waitIdle(p.page), true);
    // Without the map passing the wait on, the worker would ask as soon as its script came, a second after.
    const asked = askedAgainAfter429(limited, `${limited}: the map's request, then the worker's`);
    assertAskedBeforeScript(`${limited}, by the map,`, asked[0]);
    await assertMatchesSlicer(p, view, 0, 'at the floor, one floor chunk asked for twice');
  });

  test('at the floor the cube\'s chunks come after the floor\'s, as the margin, and a zoom out draws from them without fetching more', async () => {
    const [view] = pickPair((a) => needed(a, 0).visible.length >= 3, (a) => [a]);
    const p = await open(view, 0);
    assert.equal(await waitIdle(p.page), true);
    const floorFiles = files(contents.floorLeaves);
    // The margin is the cube's chunks over the view grown by MARGIN, all of them (those under the view too).
    const margin = needed(view, 0).all;
    await eventually(() => margin.every((l) => countBy(chunkRequests()).has(l.file)), 'the margin fetched');
    const order = chunkRequests().map(fileOf);
    const firstCube = order.findIndex((f) => !floorFiles.has(f));
    assert.ok(firstCube > 0, 'a floor chunk first');
    assert.ok(order.slice(firstCube).every((f) => !floorFiles.has(f)), `the cube's chunks after every floor chunk: ${order.join(' ')}`);
    assert.deepEqual(new Set(order.slice(firstCube)), files(margin));
    // With the cube's chunks on the GPU beside the floor's, the frame draws the floor once.
    await untilOnGpu(p.page, margin.map((l) => l.file));
    assert.equal(await waitIdle(p.page), true);
    const { visible } = await p.page.evaluate(() => engine.neededChunks());
    assert.ok(visible.length > 0 && visible.every((f) => floorFiles.has(f) || f.startsWith('l-')), `on screen: ${visible.join(' ')}`);
    assert.equal((await p.page.evaluate(() => engine.stats())).chunks, visible.length, 'only the chunks on screen are drawn');
    // The slice just above the floor's top over the same ground: on screen the cube's chunks,
    // here already but for those whose triangles start between the floor and the slice.
    const before = chunkRequests().length;
    const z = contents.floorTop * 1.5;
    await goTo(p, view, z);
    assert.equal(await waitIdle(p.page), true);
    const later = chunkRequests().slice(before).map(fileOf);
    const marginFiles = files(margin);
    for (const l of needed(view, z).visible) assert.ok(marginFiles.has(l.file) || later.includes(l.file), `${l.file} on screen`);
    const now = files(needed(view, z).all);
    for (const f of later) assert.ok(now.has(f) && !marginFiles.has(f), `${f}: fetched again, or not the cube's over the view`);
    await assertMatchesSlicer(p, view, z, 'just above the floor');
  });

  test('where the map\'s frames are slow (a slow device), a view rests one and a half frames before its margin is fetched', async () => {
    const z = 30;
    const frameMs = 600;
    const east = (x: Bbox, d: number): Bbox => [x[0] + d, x[1], x[2] + d, x[3]];
    /** Chunks the margin of a pan of `x` 12 m east needs that the margin of `x` did not. */
    const newMargin = (x: Bbox): string[] => needed(east(x, 12), z).all.map((l) => l.file).filter((f) => !files(needed(x, z).all).has(f));
    // A pan whose chunks on screen are all fetched already: its margin waits for the rest alone.
    // (The small moves before it stay within the chunks of a.)
    const [a, b] = pickPair((x, y) => fresh(x, y, z).length === 0 && newMargin(x).length >= 1, (x) => [east(x, 12)]);
    // Every animation frame comes frameMs after it was asked for.
    const slowFrames = `window.requestAnimationFrame = (cb) => setTimeout(() => cb(performance.now()), ${frameMs}); window.cancelAnimationFrame = (id) => clearTimeout(id);`;
    const p = await open(a, z, {}, [], slowFrames);
    assert.equal(await waitIdle(p.page), true);
    await untilOnGpu(p.page, needed(a, z).all.map((l) => l.file));
    // A few small moves, one a frame, as a pan or a zoom draws them: the map learns its pace.
    await p.page.evaluate(async ([aa, zz]) => {
      for (let i = 1; i <= 4; i++) {
        map.fitBoundsProjected([aa[0] + i / 10, aa[1], aa[2] + i / 10, aa[3]], { sliceZ: zz, duration: 0 });
        await map.once('render');
      }
    }, [a, z] as const);
    await p.page.evaluate(([bb, zz]) => map.fitBoundsProjected(bb, { sliceZ: zz, duration: 0 }), [b, z] as const);
    const panned = Date.now();
    const later = newMargin(a);
    await untilOnGpu(p.page, later);
    const asked = chunkRequests().filter((r) => later.includes(fileOf(r)));
    assert.equal(asked.length, later.length, 'each new margin chunk asked for once');
    const first = Math.min(...asked.map((r) => r.start));
    // Not after marginRestMs (300 ms) as on a fast device.
    assert.ok(first - panned >= 1.5 * frameMs - 200, `the margin asked for ${first - panned} ms after the pan`);
  });

  test('chunks on screen and nearest the view centre are fetched first', async () => {
    const bbox = box(0.35, 0.3, 120, 90);
    const z = 60;
    const p = await open(bbox, z, { concurrency: 1 });
    assert.equal(await waitIdle(p.page), true);
    const v = fitBbox(bbox, W, H);
    const n = needed(bbox, z);
    const onScreen = new Set(n.visible.map((l) => l.file));
    const interim = files(floorOnScreen(bbox));
    const leafOf = new Map([...contents.leaves, ...contents.floorLeaves].map((l) => [l.file, l]));
    // One request at a time, so the server sees them in the order the map chose.
    const order = chunkRequests().map(fileOf);
    assert.ok(order.length >= 5);
    // The floor on screen first, if fetched (the first view's interim floor, just above the
    // floor's top); then the view's own on screen; then by the ground distance from the view
    // centre to the chunk's box (every chunk needed meets the flat slice's z, so z does not order them).
    const distance = (f: string): number => {
      const b = leafOf.get(f)!.bbox;
      return Math.hypot(Math.max(b[0] - v.centerX, 0, v.centerX - b[3]), Math.max(b[1] - v.centerY, 0, v.centerY - b[4]));
    };
    const rank = (f: string): [number, number] => [interim.has(f) ? -1 : onScreen.has(f) ? 0 : 1, distance(f)];
    for (let i = 1; i < order.length; i++) {
      const a = rank(order[i - 1]!), b = rank(order[i]!);
      assert.ok(a[0] < b[0] || (a[0] === b[0] && a[1] <= b[1] + 1e-12), `request ${i}: ${order[i - 1]} (${a}) before ${order[i]} (${b})`);
    }
  });

  test('panning away aborts the requests for the view left behind', async () => {
    server.faults.delayMs = (f) => (/^[cb]-/.test(f) ? 1500 : 0);
    const z = 30;
    const only = (a: Bbox, b: Bbox): Set<string> => {
      const out = files(needed(a, z).all);
      for (const l of needed(b, z).all) out.delete(l.file);
      return out;
    };
    const [west, east] = pickPair((a, b) => only(a, b).size >= 3 && needed(a, z).visible.length >= 3);
    const westOnly = only(west, east);
    const p = await open(west, z);
    await p.page.waitForFunction(() => [...engine.chunkStatuses().values()].filter((s) => s === 'requested').length >= 3);
    await goTo(p, east, z);
    assert.equal(await waitIdle(p.page), true, 'the new view is complete');
    const west200 = chunkRequests().filter((e) => westOnly.has(fileOf(e)));
    assert.ok(west200.length >= 3, `${west200.length} requests for the west view`);
    for (const e of west200) assert.equal(e.outcome, 'aborted', `${e.path} was ${e.outcome}, not aborted`);
    const statuses = new Map(await p.page.evaluate(() => [...engine.chunkStatuses()]));
    for (const f of westOnly) {
      const s = statuses.get(f);
      assert.ok(s === undefined || s === 'not-requested', `${f}: ${s}`);
    }
    await assertMatchesSlicer(p, east, z, 'east');
  });

  test('while chunks are in flight the map keeps drawing what it has', async () => {
    const z = 30;
    // A pan by half the view's width that needs chunks the first view did not fetch.
    const [a, b] = pickPair((x, y) => fresh(x, y, z).length >= 1, (x) => [[x[0] + 35, x[1], x[2] + 35, x[3]]]);
    const newOnes = fresh(a, b, z);
    const p = await open(a, z);
    assert.equal(await waitIdle(p.page), true);
    server.faults.delayMs = (f) => (/^[cb]-/.test(f) ? 2000 : 0);
    await p.page.evaluate(() => {
      (globalThis as unknown as { frames: number }).frames = 0;
      map.on('render', () => (globalThis as unknown as { frames: number }).frames++);
    });
    await goTo(p, b, z);
    await p.page.waitForFunction((files) => files.some((f) => engine.chunkStatuses().get(f) === 'requested'), newOnes.map((l) => l.file));
    const during = await readIds(p.page);
    const inFlight = await p.page.evaluate((files) => files.filter((f) => engine.chunkStatuses().get(f) === 'requested').length, newOnes.map((l) => l.file));
    assert.ok(inFlight >= 1, 'still in flight while reading');
    assert.equal(await p.page.evaluate(() => map.loaded()), false);
    // The half of the new view the old chunks cover is drawn already.
    let drawn = 0;
    for (const v of during.upper) if (v !== 0) drawn++;
    assert.ok(drawn > W * H * 0.3, `${drawn} pixels drawn while loading`);
    assert.ok((await p.page.evaluate(() => (globalThis as unknown as { frames: number }).frames)) >= 1);
    assert.equal(await waitIdle(p.page), true);
    await assertMatchesSlicer(p, b, z, 'after loading');
  });

  /**
   * Opens a view of at least 6 chunks at z with its chunks coming one after another, 100 ms
   * apart (drawn as they come, the images would be about that far apart), recording the map's
   * 'render' and 'complete' events from its first frame: when, and after how many animation
   * frames.
   */
  async function openSlowly(z: number): Promise<{ a: Bbox; visible: string[]; p: MapPage }> {
    const a = candidates().find((x) => needed(x, z).visible.length >= 6);
    assert.ok(a, 'a view of at least 6 chunks');
    const visible = needed(a, z).visible.map((l) => l.file);
    server.faults.delayMs = (f) => (visible.includes(f) ? 150 + 100 * visible.indexOf(f) : 0);
    // The page's map is assigned to window after it is made, before its first frame: the
    // listeners are on from that frame on.
    const record = `(() => {
      const evs = [];
      let rafs = 0;
      const tick = () => { rafs++; requestAnimationFrame(tick); };
      requestAnimationFrame(tick);
      globalThis.evs = evs;
      globalThis.rafs = () => rafs;
      Object.defineProperty(globalThis, 'map', { configurable: true, get() { return this.m; }, set(m) {
        this.m = m;
        m.on('render', (e) => evs.push({ type: 'render', frame: e.frame, at: performance.now(), raf: rafs }));
        m.on('complete', (e) => evs.push({ type: 'complete', frame: e.frame, at: performance.now(), raf: rafs }));
      } });
    })()`;
    logStart = server.log.length;
    mp = await openMap(browser, server.url, { source: 'cube/', bbox: a.join(','), z }, { initScript: record });
    return { a, visible, p: mp };
  }
  type Recorded = { type: string; frame: number; at: number; raf: number };
  const recorded = (p: MapPage): Promise<Recorded[]> => p.page.evaluate(() => (globalThis as unknown as { evs: Recorded[] }).evs);

  test('before the first complete map, what has come is drawn at most every 250 ms, and the map then comes complete', async () => {
    const z = 30;
    const { a, visible, p } = await openSlowly(z);
    assert.equal(await waitIdle(p.page), true);
    const evs = await recorded(p);
    const done = evs.find((e) => e.type === 'complete');
    assert.ok(done, JSON.stringify(evs));
    const before = evs.filter((e) => e.type === 'render' && e.frame < done.frame);
    // The map fills in while it loads: more than the first (empty) image before the complete one.
    assert.ok(before.length >= 2, `${before.length} incomplete images before the complete one: ${JSON.stringify(evs)}`);
    for (let i = 1; i < before.length; i++) {
      // Timed when each image is drawn, 250 ms and more after the last one began: less the
      // difference of their drawing times (tens of ms on a software GPU).
      assert.ok(before[i]!.at - before[i - 1]!.at >= 200, `incomplete images ${before[i - 1]!.frame} and ${before[i]!.frame} ${Math.round(before[i]!.at - before[i - 1]!.at)} ms apart: ${JSON.stringify(evs)}`);
    }
    // Every chunk of the view was fetched, once.
    const fetched = countBy(chunkRequests());
    for (const f of visible) assert.equal(fetched.get(f), 1, f);
    await assertMatchesSlicer(p, a, z, 'the first complete map');
  });

  test('a view changed before the first complete map is drawn at once', async () => {
    const z = 30;
    const { a, p } = await openSlowly(z);
    // Once the first image is on screen, a pan of 5 m: a new view.
    await p.page.waitForFunction(() => (globalThis as unknown as { evs: Recorded[] }).evs.some((e) => e.type === 'render'));
    const b: Bbox = [a[0] + 5, a[1], a[2] + 5, a[3]];
    const pan = await p.page.evaluate(([bb, zz]) => {
      const at = performance.now(), raf = (globalThis as unknown as { rafs: () => number }).rafs();
      map.fitBoundsProjected(bb, { sliceZ: zz, duration: 0 });
      return { at, raf };
    }, [b, z] as const);
    assert.equal(await waitIdle(p.page), true);
    const evs = await recorded(p);
    const done = evs.find((e) => e.type === 'complete')!;
    assert.ok(done.at > pan.at, `the pan came before the first complete map (else this test tells nothing): ${JSON.stringify(evs)}`);
    const next = evs.find((e) => e.type === 'render' && e.at > pan.at)!;
    // Drawn in the next animation frame or the one after (the counter's and the map's callbacks
    // run in either order), not held back for up to 250 ms (some 15 frames).
    assert.ok(next.raf - pan.raf <= 2, `the pan's first image came ${next.raf - pan.raf} animation frames later: ${JSON.stringify(evs)}`);
    await assertMatchesSlicer(p, b, z, 'after the pan');
  });

  test("'complete' fires once per view, for the frame that shows all its chunks: at once for a pan within the margin, after the late chunks otherwise", async () => {
    const z = 30;
    // A pan within the prefetch margin (nothing new to fetch), then one half a view east that needs chunks not yet fetched.
    const east = (x: Bbox, d: number): Bbox => [x[0] + d, x[1], x[2] + d, x[3]];
    const late = (x: Bbox): string[] => fresh(east(x, 12), east(x, 47), z).map((l) => l.file).filter((f) => !files(needed(x, z).all).has(f));
    const [a, b] = pickPair((x, y) => fresh(x, y, z).length === 0 && late(x).length >= 1, (x) => [east(x, 12)]);
    const c = east(a, 47);
    const newOnes = late(a);
    const p = await open(a, z);
    assert.equal(await waitIdle(p.page), true);
    // The margin comes once the view has rested (sourceOptions.marginRestMs), after 'idle'.
    await untilOnGpu(p.page, needed(a, z).all.map((l) => l.file));
    type Ev = { type: string; frame: number; loaded?: boolean; late?: (string | undefined)[]; drew?: { frame: number; chunks: number } };
    const events = async (): Promise<Ev[]> => p.page.evaluate(() => (globalThis as unknown as { evs: Ev[] }).evs.splice(0));
    await p.page.evaluate((late) => {
      const evs: Ev[] = [];
      (globalThis as unknown as { evs: Ev[] }).evs = evs;
      map.on('render', (e) => evs.push({ type: 'render', frame: (e as { frame: number }).frame }));
      map.on('complete', (e) => {
        const { frame, chunks } = engine.stats();
        evs.push({ type: 'complete', frame: (e as { frame: number }).frame, loaded: map.loaded(), late: late.map((f) => engine.chunkStatuses().get(f)), drew: { frame, chunks } });
      });
      map.on('idle', () => evs.push({ type: 'idle', frame: -1 }));
    }, newOnes);

    await goTo(p, b, z);
    assert.equal(await waitIdle(p.page), true);
    const small = await events();
    const renders = small.filter((e) => e.type === 'render');
    const completes = small.filter((e) => e.type === 'complete');
    assert.equal(completes.length, 1, JSON.stringify(small));
    assert.equal(completes[0]!.frame, renders[0]!.frame, 'the first frame of the new view already shows it all: no frame waits for the worker to say so');
    assert.ok(small.indexOf(completes[0]!) < small.findIndex((e) => e.type === 'idle'), "'complete' before 'idle'");

    server.faults.delayMs = (f) => (newOnes.includes(f) ? 800 : 0);
    await goTo(p, c, z);
    assert.equal(await waitIdle(p.page), true);
    const big = await events();
    const bigCompletes = big.filter((e) => e.type === 'complete');
    assert.equal(bigCompletes.length, 1, JSON.stringify(big));
    const done = bigCompletes[0]!;
    assert.ok(done.frame > big.find((e) => e.type === 'render')!.frame, 'the frames drawn while the late chunks were in flight were not complete');
    assert.equal(done.loaded, true);
    assert.deepEqual(done.late, newOnes.map(() => 'gpu'), 'the late chunks are on the GPU when the view is complete');
    // And the frame it names drew them: as many surface chunks as meet the view.
    assert.equal(done.drew!.frame, done.frame, 'no frame drawn since the one it names');
    assert.ok(done.drew!.chunks >= needed(c, z).visible.length, `the complete frame drew ${done.drew!.chunks} surface chunks, the view meets ${needed(c, z).visible.length}`);
    await assertMatchesSlicer(p, c, z, 'complete');
  });

  test('a small GPU memory budget evicts the least recently used chunks and fetches them again', async () => {
    const z = 30;
    // With the line chunks the view needs (the map fetches them with the surface chunks).
    const bytes = (ls: ChunkLeaf[]): number => ls.reduce((s, l) => s + gpuBytes.get(l.file)!, 0);
    const withLines = (b: Bbox): number => {
      const m = growBbox(viewBbox(fitBbox(b, W, H)), MARGIN);
      return bytes(needed(b, z).all) + contents.lines.filter((l) => boxMeets(l.bbox, { ground: m, zMin: z, zMax: z })).reduce((s, l) => s + gpuBytes.get(l.file)!, 0);
    };
    // Room for either view with its margin, never for both.
    const budgetFor = (x: Bbox, y: Bbox): number => Math.max(withLines(x), withLines(y)) * 1.05;
    const onlyA = (x: Bbox, y: Bbox): ChunkLeaf[] => needed(x, z).visible.filter((l) => !files(needed(y, z).all).has(l.file));
    const [a, b] = pickPair((x, y) => onlyA(x, y).length >= 2 && bytes(needed(x, z).all) + bytes(needed(y, z).all) > 1.3 * budgetFor(x, y));
    const nb = needed(b, z);
    const budget = budgetFor(a, b);
    const aOnly = onlyA(a, b);
    const p = await open(a, z, { budget: Math.round(budget) });
    assert.equal(await waitIdle(p.page), true);
    const idsA = await readIds(p.page);
    await goTo(p, b, z);
    assert.equal(await waitIdle(p.page), true);
    // Margin chunks may still be arriving; wait until all of b's are in.
    await untilOnGpu(p.page, nb.all.map((l) => l.file));
    const stats = await p.page.evaluate(() => engine.stats());
    assert.ok(stats.gpuBytes <= budget, `${stats.gpuBytes} bytes on the GPU, budget ${budget}`);
    const statuses = new Map(await p.page.evaluate(() => [...engine.chunkStatuses()]));
    const evicted = aOnly.filter((l) => statuses.get(l.file) === 'evicted');
    assert.ok(evicted.length >= 1, `none of ${aOnly.length} chunks only a needed was evicted: ${aOnly.map((l) => statuses.get(l.file))}`);
    await goTo(p, a, z);
    assert.equal(await waitIdle(p.page), true);
    const counts = countBy(chunkRequests());
    for (const l of evicted) assert.equal(counts.get(l.file), 2, `${l.file} fetched again after eviction`);
    const idsA2 = await readIds(p.page);
    assert.deepEqual(idsA2.upper, idsA.upper, 'the same map as before');
  });

  test('with 30% of chunk requests failing, retries still give a complete map', async () => {
    server.faults.chunkFailRate = 0.3;
    server.faults.seed = 7;
    const z = 120;
    const p = await open(ext(), z, { retries: 12, backoff: 10 });
    // Chromium reports each failed request on the console; those are the injected faults.
    p.expect(/Failed to load resource: the server responded with a status of 503/);
    p.expect(/Failed to load resource: net::ERR_(EMPTY_RESPONSE|CONNECTION_(RESET|CLOSED))/);
    assert.equal(await waitIdle(p.page), true, 'complete');
    const rs = chunkRequests();
    const failures = rs.filter((e) => e.outcome === 503 || e.outcome === 'network');
    assert.ok(failures.length >= 0.15 * rs.length, `${failures.length} of ${rs.length} requests failed`);
    const ok = countBy(rs.filter((e) => e.outcome === 200));
    for (const l of needed(ext(), z).visible) assert.equal(ok.get(l.file), 1, `${l.file} answered once`);
    await assertMatchesSlicer(p, ext(), z, 'despite failures');
  });

  test('a chunk that is not found gives an error event and is not asked for again', async () => {
    const z = 40;
    const [start, target] = pickPair((x, y) => fresh(x, y, z).length >= 2);
    const missing = needed(target, z).visible.find((l) => !needed(start, z).all.some((m) => m.file === l.file))!;
    assert.ok(missing);
    server.faults.notFound.add(missing.file);
    const p = await open(start, z, { retries: 3, backoff: 10 });
    p.expect(/Failed to load resource: the server responded with a status of 404/);
    assert.equal(await waitIdle(p.page), true);
    const errorsSeen = await recordErrors(p);
    await goTo(p, target, z);
    assert.equal(await waitIdle(p.page), false, 'idle, but not complete');
    const errors = await errorsSeen();
    assert.deepEqual(errors.map((e) => [e.kind, e.status, e.file]), [['http', 404, missing.file]]);
    assert.equal(countBy(chunkRequests()).get(missing.file), 1, '4xx is not retried');
    const status = await p.page.evaluate((f) => engine.chunkStatuses().get(f), missing.file);
    assert.equal(status, 'failed');
  });

  test('a chunk that keeps failing with 503 is retried, then reported', async () => {
    const z = 40;
    const [start, target] = pickPair((x, y) => fresh(x, y, z).length >= 2);
    const down = needed(target, z).visible.find((l) => !needed(start, z).all.some((m) => m.file === l.file))!;
    server.faults.unavailable.add(down.file);
    const p = await open(start, z, { retries: 3, backoff: 10 });
    p.expect(/Failed to load resource: the server responded with a status of 503/);
    assert.equal(await waitIdle(p.page), true);
    const errorsSeen = await recordErrors(p);
    await goTo(p, target, z);
    assert.equal(await waitIdle(p.page), false);
    const errors = await errorsSeen();
    assert.deepEqual(errors.map((e) => [e.kind, e.status, e.file]), [['http', 503, down.file]]);
    assert.equal(countBy(chunkRequests()).get(down.file), 4, 'the first attempt and 3 retries');
  });

  test('chunks that failed while the network was down are asked for again once the browser is back online, each once, with the view unmoved: it comes complete and equals the CPU slicer', async () => {
    const z = 40;
    const [start, target] = pickPair((x, y) => fresh(x, y, z).length >= 2);
    const p = await open(start, z, { retries: 1, backoff: 10 }, [/net::ERR_INTERNET_DISCONNECTED/]);
    assert.equal(await waitIdle(p.page), true);
    const errorsSeen = await recordErrors(p);
    const onGpu = await p.page.evaluate(() => [...engine.chunkStatuses()].filter(([, s]) => s === 'gpu').map(([f]) => f));
    const context = p.page.context();
    await context.setOffline(true);
    await goTo(p, target, z);
    assert.equal(await waitIdle(p.page), false, 'offline: idle, but not complete');
    const lost = [...new Set((await errorsSeen()).filter((e) => e.kind === 'network').map((e) => e.file!))].sort();
    const onScreen = needed(target, z).visible.map((l) => l.file);
    assert.ok(lost.filter((f) => onScreen.includes(f)).length >= 2, `chunks on screen lost: ${lost.join(', ')}`);
    const askedBefore = server.log.length;

    await context.setOffline(false);
    await untilOnGpu(p.page, onScreen);
    assert.equal(await waitIdle(p.page), true, 'complete, the view unmoved');
    const askedAgain = countBy(server.log.slice(askedBefore).filter((e) => /^\/cube\/[cb]-/.test(e.path)));
    for (const f of lost.filter((f) => onScreen.includes(f))) assert.equal(askedAgain.get(f), 1, `${f} asked for again once`);
    // (The margin's chunks may fail after the errors were read, or not have been asked for yet.)
    assert.deepEqual([...askedAgain.keys()].filter((f) => onGpu.includes(f)), [], 'no chunk the map had is asked for again');
    await assertMatchesSlicer(p, target, z, 'back online');
  });

  test('a chunk refused with 429 and Retry-After: 2 is asked again two seconds later, not after the backoff, and the view comes complete', async () => {
    const z = 40;
    const [start, target] = pickPair((x, y) => fresh(x, y, z).length >= 2);
    const limited = needed(target, z).visible.find((l) => !needed(start, z).all.some((m) => m.file === l.file))!;
    server.faults.tooManyOnce.set(limited.file, 2);
    // A backoff of 10 ms: without Retry-After the second request would follow the first at once.
    const p = await open(start, z, { retries: 3, backoff: 10 }, [/Failed to load resource: the server responded with a status of 429/]);
    assert.equal(await waitIdle(p.page), true);
    const errorsSeen = await recordErrors(p);
    await goTo(p, target, z);
    assert.equal(await waitIdle(p.page), true);
    askedAgainAfter429(limited.file, `${limited.file}: refused, then asked again`);
    assert.deepEqual(await errorsSeen(), [], 'nothing for the page to hear of');
    await assertMatchesSlicer(p, target, z, 'after the 429');
  });

  test('a worker script that cannot be loaded fails the map with an error that says so, and the map goes idle', async () => {
    server.faults.appNotFound = (path) => WORKER_SCRIPT.test(path);
    // index.json comes late, so that the worker has failed before it (as it did once in CI).
    server.faults.delayMs = (file) => (file === 'index.json' ? 500 : 0);
    const [view] = pickPair((a) => floorOnScreen(a).length >= 1, (a) => [a]);
    const p = await open(view, 0, {}, [/Failed to load resource: the server responded with a status of 404/]);
    // Polled by time, not by animation frames (which did not see it come here).
    await p.page.waitForFunction("document.getElementById('info').textContent !== ''", undefined, { polling: 100 });
    assert.equal((await p.page.textContent('#info')) ?? '', "worker error: the map's worker could not be started");
    // waitIdle waits for the metadata first: it comes although the worker failed before the
    // index did (the CRS that 'meta' waits for is loaded when no first map will come).
    assert.equal(await waitIdle(p.page), false, 'idle, incomplete');
    assert.deepEqual(await p.page.evaluate(() => map.getMetadata()?.extent), contents.meta.extent);
    const alert = await p.page.textContent('.ssc-load-error');
    assert.match(alert ?? '', /The map's worker script could not be loaded, so http:\/\/127\.0\.0\.1:\d+\/cube\/index\.json cannot be shown: the script must be served beside vario-map\.js/);
  });

  test('a map whose worker and index both fail shows one load error, the first', async () => {
    server.faults.appNotFound = (path) => WORKER_SCRIPT.test(path);
    logStart = server.log.length;
    mp = await openMap(browser, server.url, { source: 'no-such-cube/' }, { expect: [/Failed to load resource: the server responded with a status of 404/] });
    await mp.page.evaluate(() => map.whenIdle());
    // Both failures have had their turn (the index's 404 and the worker's): one box.
    await mp.page.waitForFunction("document.querySelectorAll('.ssc-load-error').length > 0", undefined, { polling: 100 });
    await new Promise((resolve) => setTimeout(resolve, 500));
    assert.equal(await mp.page.locator('.ssc-load-error').count(), 1);
    assert.equal(server.log.slice(logStart).filter((e) => WORKER_SCRIPT.test(e.path) || e.path === '/no-such-cube/index.json').length, 2, 'the worker and the index each asked for');
  });

  test('a missing index gives an error event', async () => {
    logStart = server.log.length;
    mp = await openMap(browser, server.url, { source: 'no-such-cube/' });
    mp.expect(/Failed to load resource: the server responded with a status of 404/);
    await mp.page.waitForFunction("document.getElementById('info').textContent !== ''");
    const text = (await mp.page.textContent('#info')) ?? '';
    assert.match(text, /^http error: HTTP 404 for http:\/\/127\.0\.0\.1:\d+\/no-such-cube\/index\.json/);
    assert.equal(server.log.slice(logStart).filter((e) => e.path === '/no-such-cube/index.json').length, 1, 'a 404 is not retried');
  });

  test('corrupt chunks are reported and not drawn', async () => {
    const z = 40;
    const [start, target] = pickPair((x, y) => fresh(x, y, z).length >= 2);
    const [badHash, badMagic] = needed(target, z).visible.filter((l) => !needed(start, z).all.some((m) => m.file === l.file));
    assert.ok(badHash && badMagic);
    server.faults.corrupt.set(badHash.file, (b) => {
      const c = Buffer.from(b);
      c[16] = c[16]! ^ 0xff; // the low bits of the origin x: it still decodes, only the hash can tell
      return c;
    });
    server.faults.corrupt.set(badMagic.file, (b) => {
      const c = Buffer.from(b);
      c.writeUInt32LE(0x12345678, 0);
      return c;
    });
    const p = await open(start, z);
    assert.equal(await waitIdle(p.page), true);
    const errorsSeen = await recordErrors(p);
    await goTo(p, target, z);
    assert.equal(await waitIdle(p.page), false);
    const errors = await errorsSeen();
    const byFile = new Map(errors.map((e) => [e.file, e]));
    assert.equal(byFile.get(badHash.file)?.kind, 'corrupt');
    assert.match(byFile.get(badHash.file)!.message, /SHA-256/);
    assert.equal(byFile.get(badMagic.file)?.kind, 'corrupt');
    assert.match(byFile.get(badMagic.file)!.message, /magic/);
    const statuses = new Map(await p.page.evaluate(() => [...engine.chunkStatuses()]));
    assert.equal(statuses.get(badHash.file), 'failed');
    assert.equal(statuses.get(badMagic.file), 'failed');
    const counts = countBy(chunkRequests());
    assert.equal(counts.get(badHash.file), 1);
    // The rest of the view is drawn.
    for (const l of needed(target, z).visible) {
      if (l !== badHash && l !== badMagic) assert.equal(statuses.get(l.file), 'gpu');
    }
  });

  test('chunks served as gzip without Content-Encoding are decompressed', async () => {
    server.faults.gzipWithoutEncoding = true;
    const leaf = contents.leaves[0]!;
    // What the browser will get: gzip bytes, no Content-Encoding.
    const head = await new Promise<{ enc: string | undefined; magic: number }>((resolve, reject) => {
      const req = request(`${server.cubeUrl}${leaf.file}`, { headers: { 'accept-encoding': 'identity' } }, (res) => {
        const parts: Buffer[] = [];
        res.on('data', (d: Buffer) => parts.push(d));
        res.on('end', () => resolve({ enc: res.headers['content-encoding'], magic: Buffer.concat(parts).readUInt16BE(0) }));
      });
      req.on('error', reject);
      req.end();
    });
    assert.equal(head.enc, undefined);
    assert.equal(head.magic, 0x1f8b);
    const bbox = box(0.3, 0.3, 120, 90);
    const p = await open(bbox, 50);
    assert.equal(await waitIdle(p.page), true);
    await assertMatchesSlicer(p, bbox, 50, 'gzip bodies');
  });
});
