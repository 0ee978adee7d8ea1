// The demo map in Chromium against a real nginx (Debian's package) running the configuration
// docs/deploy.md documents (server/nginx.conf.template, filled in by server/nginx-process.ts) on
// 127.0.0.1, with one root holding the built client and a cube of bgt_otterlo_400m (with its
// .br/.gz copies) under cube/. What a user and the network would notice: the map draws, and
// draws what the project's own test server gives for the same view (equal but for sub-pixel
// effects beside edges, see assertSamePicture); chunks arrive as their precompressed copies,
// typed and cacheable for a year, and decode to the bytes the index names (floor chunks and line
// chunks too); index.json is revalidated (a reload gets 304, the chunks come from the browser's
// cache without a request); zooming in with the wheel fetches the further chunks the index says
// the new view needs, from nginx with 200; that view opened afresh below the floor's top takes
// the floor chunks on screen from nginx. No console errors. nginx missing is a failure, not a skip.
//
// Besides the browser's view of each response (context 'response' events, which include the
// chunk worker's fetches), nginx writes an access log: the one change to the documented config,
// so the test can see which requests really reached nginx and what it sent back.
import assert from 'node:assert/strict';
import { createHash } from 'node:crypto';
import { chmod, cp, mkdtemp, readdir, readFile, rm, stat } from 'node:fs/promises';
import { existsSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { after, afterEach, before, describe, test } from 'node:test';
import type { Browser, Page, Response } from 'playwright-core';
import { expectedDigest } from '../format/cube-index.js';
import { boxMeets, queryIndex } from '../format/index-query.js';
import { NGINX_BIN, startNginx, type RunningNginx } from '../server/nginx-process.js';
import { launchChromium, type MapPage } from './helpers/browser.js';
import { buildCube, clientDir, otterlo400, readCube, type BuiltCube, type CubeContents } from './helpers/cube.js';
import { hexColour, pixel, screenshot, type Rgba } from './helpers/map-page.js';
import { checkAndClose } from './helpers/test-bed.js';
import { startTestServer, type TestServer } from './helpers/test-server.js';
import { camera, idle, openDemo, settle, type VarioWindow } from './helpers/vario-page.js';

const IMMUTABLE = 'public, max-age=31536000, immutable';
const CHUNK = /^c-[0-9a-f]{16}\.bin$/;
/** Every file the map checks against its name: chunks, floor chunks, line chunks. */
const CHECKED = /^[cbl]-[0-9a-f]{16}\.bin$/;

/** One response the browser got for a cube file (cube/<file>), with both sides' headers. */
interface Seen {
  file: string;
  status: number;
  request: Record<string, string>;
  headers: Record<string, string>;
  body: Buffer | null;
}

/** One line of nginx's access log (the format set in startLoggingNginx). */
interface Logged {
  uri: string;
  status: number;
  ifNoneMatch: string;
  etag: string;
  contentEncoding: string;
  contentType: string;
  cacheControl: string;
  bytes: number;
}

/** The encoding the documented rules pick for an Accept-Encoding: brotli first, then gzip. */
function expectedEncoding(acceptEncoding: string | undefined): string {
  const listed = (acceptEncoding ?? '').split(',').map((s) => s.trim().split(';')[0]!.toLowerCase());
  if (listed.includes('br')) return 'br';
  if (listed.includes('gzip')) return 'gzip';
  return '';
}

/** Files readable by nginx's unprivileged workers whatever the umask was. */
async function makeReadable(dir: string): Promise<void> {
  await chmod(dir, 0o755);
  for (const e of await readdir(dir, { withFileTypes: true })) {
    const p = path.join(dir, e.name);
    if (e.isDirectory()) await makeReadable(p);
    else await chmod(p, 0o644);
  }
}

const sleep = (ms: number): Promise<void> => new Promise((r) => setTimeout(r, ms));

describe('the demo map served by nginx with the documented config (bgt_otterlo_400m)', () => {
  let cube: BuiltCube | undefined;
  let contents: CubeContents;
  let work: string | undefined;
  let accessLog: string;
  let nginx: RunningNginx | undefined;
  let server: TestServer | undefined;
  let browser: Browser | undefined;
  /** The demo on nginx, kept open from test to test (the later ones reload and zoom it). */
  let mp: MapPage | null = null;
  /** The browser's cube responses on mp, in order. */
  const seen: Promise<Seen>[] = [];
  let firstPicture: Rgba;
  /** The demo's URL (its hash holds the view) once the wheel test has zoomed past the base scale. */
  let closerUrl: string | null = null;

  before(async () => {
    // CI installs Debian's nginx; without it this test must fail, not pass vacuously.
    assert.ok(existsSync(NGINX_BIN), `${NGINX_BIN} not found: install Debian's nginx package (apt-get install nginx) to run this test`);
    // The classic cube: a closer view then needs chunks the first did not (a smooth cube's
    // tilted pieces reach lower in z, so the same zoom may find them all loaded already).
    cube = await buildCube(otterlo400, ['--classic']);
    contents = await readCube(cube.dir);
    work = await mkdtemp(path.join(tmpdir(), 'ssc-nginx-e2e-'));
    const root = path.join(work, 'site');
    // Copies, not symlinks: the documented config refuses every symlink (disable_symlinks on).
    // Only Vite's output: dist/client also holds tsc's Node build of the shared modules.
    await cp(path.join(clientDir, 'demo.html'), path.join(root, 'demo.html'));
    await cp(path.join(clientDir, 'assets'), path.join(root, 'assets'), { recursive: true });
    await cp(cube.dir, path.join(root, 'cube'), { recursive: true });
    await makeReadable(work);
    assert.ok(existsSync(path.join(root, 'cube/index.json.br')) && existsSync(path.join(root, 'cube/index.json.gz')), 'the cube has its precompressed copies');
    accessLog = path.join(work, 'access.log');
    const format = `log_format ssc_test '$request_uri\\t$status\\t$http_if_none_match\\t$sent_http_etag\\t$sent_http_content_encoding\\t$sent_http_content_type\\t$sent_http_cache_control\\t$body_bytes_sent';`;
    nginx = await startNginx(root, (config) => {
      const parts = config.split('access_log off;');
      if (parts.length !== 2) throw new Error('the nginx template no longer says "access_log off;" once: update this test');
      return parts.join(`${format}\n    access_log ${accessLog} ssc_test;`);
    });
    server = await startTestServer({ clientDir, cubeDir: cube.dir });
    browser = await launchChromium();
  });

  afterEach(() => {
    // The nginx page lives on across tests; each test answers for the errors logged during it.
    if (mp) assert.deepEqual(mp.problems.splice(0), [], 'no console errors or uncaught exceptions');
  });

  after(async () => {
    await mp?.close();
    await browser?.close();
    await server?.close();
    await nginx?.stop();
    await cube?.remove();
    if (work) await rm(work, { recursive: true, force: true });
  });

  function page(): Page {
    if (!mp) throw new Error('the nginx page did not open (see the first test)');
    return mp.page;
  }

  /** Records a response for a cube file, headers and (for 200) the decoded body. */
  function watch(p: Page): void {
    p.context().on('response', (r: Response) => {
      const url = new URL(r.url());
      if (!url.pathname.startsWith('/cube/')) return;
      seen.push(
        (async (): Promise<Seen> => {
          const [request, headers] = await Promise.all([r.request().allHeaders(), r.allHeaders()]);
          const body = r.status() === 200 ? await r.body().catch(() => null) : null;
          return { file: url.pathname.slice('/cube/'.length), status: r.status(), request, headers, body };
        })(),
      );
    });
  }

  /** Every leaf of the index, by file: chunks, floor chunks and line chunks. */
  function allLeaves(): Map<string, { file: string }> {
    return new Map([...contents.leaves, ...contents.floorLeaves, ...contents.lines].map((l) => [l.file, l]));
  }

  /** A response for a file the map checks against its name: the precompressed copy, typed and immutable, whose body is what the name names. */
  function assertDelivered(s: Seen | undefined, file: string, leaves: Map<string, { file: string }>): asserts s is Seen {
    assert.ok(s, `the browser got ${file}`);
    assertServedCompressed(s, 'application/octet-stream', IMMUTABLE);
    const leaf = leaves.get(file);
    assert.ok(leaf, `${file} is a leaf of the index`);
    // The worker's fetches are visible with their bodies: the decoded file is the one the index names.
    assert.ok(s.body, `${file}: body readable`);
    assert.ok(createHash('sha256').update(s.body).digest('hex').startsWith(expectedDigest(leaf)), `${file}: decodes to the file its name names`);
  }

  async function readLog(): Promise<Logged[]> {
    const text = await readFile(accessLog, 'utf8');
    return text
      .split('\n')
      .filter((l) => l.length > 0)
      .map((l) => {
        const [uri, status, ifNoneMatch, etag, contentEncoding, contentType, cacheControl, bytes] = l.split('\t');
        // nginx logs a missing value as "-" and escapes the quotes of an ETag as \x22.
        const v = (s: string | undefined): string => (s === undefined || s === '-' ? '' : s.replaceAll('\\x22', '"'));
        return { uri: v(uri), status: Number(status), ifNoneMatch: v(ifNoneMatch), etag: v(etag), contentEncoding: v(contentEncoding), contentType: v(contentType), cacheControl: v(cacheControl), bytes: Number(bytes) };
      });
  }

  /** The log from line `from` on, once `done` holds for it (nginx logs just after sending). */
  async function logFrom(from: number, done: (l: Logged[]) => boolean): Promise<Logged[]> {
    let lines: Logged[] = [];
    for (let i = 0; i < 40; i++) {
      lines = (await readLog()).slice(from);
      if (done(lines)) return lines;
      await sleep(50);
    }
    return lines;
  }

  /** Share of sampled pixels in one of the style's class colours, and how many of them show. */
  function drawn(img: Rgba): { share: number; classes: number } {
    const colours = contents.meta.style.classes.map((c) => hexColour(c.color).join());
    const shown = new Set<string>();
    let n = 0, of = 0;
    for (let j = 0; j < img.height; j += 4) {
      for (let i = 0; i < img.width; i += 4) {
        of++;
        const c = pixel(img, i, j).join();
        if (colours.includes(c)) {
          n++;
          shown.add(c);
        }
      }
    }
    return { share: n / of, classes: shown.size };
  }

  /**
   * Pixels differing between two pictures of one view, and those of them not beside a colour
   * edge in both. A shift of the picture by under a pixel changes only pixels beside an edge
   * (or on a sliver thinner than a pixel); other data, a missing chunk or another view would
   * change whole areas, away from any edge.
   */
  function compare(a: Rgba, b: Rgba): { differing: number; offEdge: number; examples: string[] } {
    assert.deepEqual([a.width, a.height], [b.width, b.height]);
    const w = a.width, h = a.height;
    const rgb = (img: Rgba, p: number): number => (img.data[4 * p]! << 16) | (img.data[4 * p + 1]! << 8) | img.data[4 * p + 2]!;
    const besideEdge = (img: Rgba, i: number, j: number): boolean => {
      const c = rgb(img, j * w + i);
      for (let y = Math.max(0, j - 1); y <= Math.min(h - 1, j + 1); y++) {
        for (let x = Math.max(0, i - 1); x <= Math.min(w - 1, i + 1); x++) if (rgb(img, y * w + x) !== c) return true;
      }
      return false;
    };
    let differing = 0, offEdge = 0;
    const examples: string[] = [];
    for (let j = 0; j < h; j++) {
      for (let i = 0; i < w; i++) {
        // A shift of a tenth of a pixel moves an anti-aliased edge (a line's, most of whose
        // pixels are edge) by a tenth of its contrast: such changes are not counted.
        if (pixel(a, i, j).every((v, k) => Math.abs(v - pixel(b, i, j)[k]!) <= 26)) continue;
        differing++;
        if (besideEdge(a, i, j) && besideEdge(b, i, j)) continue;
        offEdge++;
        if (examples.length < 8) examples.push(`(${i},${j}) ${pixel(a, i, j).join()} vs ${pixel(b, i, j).join()}`);
      }
    }
    return { differing, offEdge, examples };
  }

  /** The same picture but for sub-pixel effects on at most `share` of the screen. */
  function assertSamePicture(a: Rgba, b: Rgba, share: number, what: string): void {
    const c = compare(a, b);
    assert.equal(c.offEdge, 0, `${what}: ${c.offEdge} of ${c.differing} differing pixels are away from any edge: ${c.examples.join('; ')}`);
    assert.ok(c.differing <= share * a.width * a.height, `${what}: ${c.differing} pixels differ (at most ${share * 100} % may)`);
  }

  /** The chunk files the index says a view needs (the flat slice at z over its ground box). */
  function needed(bounds: [number, number, number, number], z: number): Set<string> {
    return new Set(queryIndex(contents.root, { ground: bounds, zMin: z, zMax: z }, (r) => contents.subs.get(r)).leaves.map((l) => l.file));
  }

  async function view(p: Page): Promise<{ bounds: [number, number, number, number]; z: number }> {
    return p.evaluate(() => {
      const m = (globalThis as unknown as VarioWindow).map;
      return { bounds: m.getBoundsProjected(), z: m.getSliceZ() };
    });
  }

  /** The expected headers of a 200 for a cube file, checked from the browser's side. */
  function assertServedCompressed(s: Seen, type: string, cacheControl: string): void {
    assert.equal(s.status, 200, `${s.file}: status`);
    const enc = expectedEncoding(s.request['accept-encoding']);
    assert.notEqual(enc, '', `${s.file}: Chromium offers br or gzip (${s.request['accept-encoding']})`);
    assert.equal(s.headers['content-encoding'], enc, `${s.file}: Content-Encoding for Accept-Encoding ${s.request['accept-encoding']}`);
    assert.equal(s.headers['content-type'], type, `${s.file}: Content-Type`);
    assert.equal(s.headers['cache-control'], cacheControl, `${s.file}: Cache-Control`);
    assert.match(s.headers['vary'] ?? '', /Accept-Encoding/i, `${s.file}: Vary`);
    assert.match(s.headers['etag'] ?? '', /^"[^"]+"$/, `${s.file}: a strong ETag`);
  }

  /** nginx's record of a 200 for a cube file: the precompressed copy's bytes, with its headers. */
  async function assertLoggedCompressed(l: Logged, type: string, cacheControl: string): Promise<void> {
    const file = l.uri.slice('/cube/'.length);
    assert.equal(l.status, 200, `${file}: nginx's status`);
    assert.ok(l.contentEncoding === 'br' || l.contentEncoding === 'gzip', `${file}: nginx sent Content-Encoding ${l.contentEncoding || 'none'}`);
    const copy = path.join(cube!.dir, `${file}.${l.contentEncoding === 'br' ? 'br' : 'gz'}`);
    assert.equal(l.bytes, (await stat(copy)).size, `${file}: nginx sent the bytes of ${path.basename(copy)}`);
    assert.equal(l.contentType, type, `${file}: nginx's Content-Type`);
    assert.equal(l.cacheControl, cacheControl, `${file}: nginx's Cache-Control`);
  }

  test('the demo draws the map, the same picture the test server gives for the same view', async () => {
    mp = await openDemo(browser!, nginx!.url, {}, { onPage: watch });
    const fromNginx = await screenshot(mp.page);
    const d = drawn(fromNginx);
    assert.ok(d.share > 0.5 && d.classes >= 4, `a map is drawn: ${(100 * d.share).toFixed(1)} % of the screen in ${d.classes} class colours`);

    const other = await openDemo(browser!, server!.url);
    try {
      assert.deepEqual(await camera(other.page), await camera(mp.page), 'both open on the same view');
      // The same bytes drawn by the same renderer (SwiftShader is deterministic) at the same view
      // and size: identical but for pixels beside edges, which an extra, jittered frame at rest
      // can change (the client sometimes draws one frame beyond ?supersampling=1).
      assertSamePicture(fromNginx, await screenshot(other.page), 0.01, 'nginx vs the test server');
    } finally {
      await checkAndClose(other);
    }
    firstPicture = fromNginx;
  });

  test('chunks and the index arrive as their precompressed copies, typed and cached as documented', async () => {
    const responses = await Promise.all(seen);
    const index = responses.filter((s) => s.file === 'index.json');
    assert.equal(index.length, 1, 'index.json fetched once');
    assertServedCompressed(index[0]!, 'application/json', 'no-cache');
    // Decoded by the browser, the body is the index on disk.
    assert.deepEqual(index[0]!.body, await readFile(path.join(cube!.dir, 'index.json')), 'index.json decodes to the file');

    const checked = responses.filter((s) => CHECKED.test(s.file));
    const chunks = checked.filter((s) => CHUNK.test(s.file));
    const leaves = allLeaves();
    assert.ok(chunks.length >= 2, `${chunks.length} chunks fetched`);
    // The line chunks come with them (this view's scale shows lines): checked the same way.
    assert.ok(checked.some((s) => s.file.startsWith('l-')), `line chunks fetched (${checked.map((s) => s.file).join(', ')})`);
    for (const c of checked) assertDelivered(c, c.file, leaves);
    // What the index says the first view needs was all fetched.
    const v = await view(page());
    for (const f of needed(v.bounds, v.z)) assert.ok(chunks.some((c) => c.file === f), `${f}, needed by the first view, was fetched`);

    // nginx's side: the same requests reached it (so the browser's events missed none of the
    // worker's fetches), each answered with the copy's bytes and the documented headers.
    const log = (await logFrom(0, (l) => l.filter((e) => e.uri.startsWith('/cube/')).length >= responses.length)).filter((e) => e.uri.startsWith('/cube/'));
    assert.deepEqual(log.map((e) => e.uri).sort(), responses.map((s) => `/cube/${s.file}`).sort(), 'the cube requests nginx logged are those the browser saw');
    for (const l of log) {
      if (l.uri === '/cube/index.json') await assertLoggedCompressed(l, 'application/json', 'no-cache');
      else await assertLoggedCompressed(l, 'application/octet-stream', IMMUTABLE);
    }
    // And the ETag the browser holds for index.json is the one nginx sent.
    assert.equal(log.find((l) => l.uri === '/cube/index.json')!.etag, index[0]!.headers['etag']);
  });

  test('a reload revalidates index.json (304) and takes the immutable chunks from the browser cache', async () => {
    const p = page();
    const etag = (await Promise.all(seen)).find((s) => s.file === 'index.json')!.headers['etag']!;
    const mark = (await readLog()).length;
    seen.length = 0;
    await p.reload();
    await idle(p);
    const log = await logFrom(mark, (l) => l.some((e) => e.uri === '/cube/index.json'));
    const index = log.filter((e) => e.uri === '/cube/index.json');
    assert.equal(index.length, 1, 'index.json asked for once');
    assert.equal(index[0]!.ifNoneMatch, etag, 'with If-None-Match: the ETag it came with');
    assert.equal(index[0]!.status, 304, 'and nginx answered 304');
    assert.deepEqual(log.filter((e) => CHECKED.test(e.uri.slice('/cube/'.length))).map((e) => e.uri), [], 'no chunk, floor chunk or line chunk request reached nginx');
    // The browser's side of the same: the conditional request, and chunks it still had.
    const responses = await Promise.all(seen);
    assert.equal(responses.find((s) => s.file === 'index.json')?.request['if-none-match'], etag, 'the browser sent If-None-Match');
    assert.ok(responses.some((s) => CHUNK.test(s.file)), 'the reloaded map used chunks (from the cache)');
    const d = drawn(await screenshot(p));
    assert.ok(d.share > 0.5 && d.classes >= 4, `the reloaded map is drawn: ${(100 * d.share).toFixed(1)} % in ${d.classes} class colours`);
    // The URL hash kept the view, rounded to a decimetre (under a tenth of a pixel here).
    assertSamePicture(firstPicture, await screenshot(p), 0.01, 'before vs after the reload');
  });

  test('zooming in with the wheel fetches the chunks the closer view needs, from nginx with 200', async () => {
    const p = page();
    const mark = (await readLog()).length;
    const fetchedBefore = new Set((await readLog()).filter((e) => e.status === 200).map((e) => e.uri.slice('/cube/'.length)).filter((f) => CHUNK.test(f)));
    seen.length = 0;
    const { baseScale } = contents.meta;
    // Real wheel notches at the centre, each zooming in by the step factor, down to the base
    // scale: there the slice reaches the bottom of the cube, held by chunks the overview lacks.
    await p.mouse.move(320, 240);
    for (let notch = 0; notch < 6 && (await camera(p)).scale >= baseScale; notch++) {
      const before = (await camera(p)).scale;
      await p.mouse.wheel(0, -100);
      await settle(p, `window.map.getScaleDenominator() < ${before * 0.75}`);
    }
    await idle(p);
    assert.ok((await camera(p)).scale < baseScale, 'zoomed in past the base scale');
    closerUrl = p.url();
    const v = await view(p);
    const expectNew = [...needed(v.bounds, v.z)].filter((f) => !fetchedBefore.has(f));
    assert.ok(expectNew.length > 0, `the closer view needs chunks not fetched before (needs ${[...needed(v.bounds, v.z)]}, had ${[...fetchedBefore]})`);

    const log = (await logFrom(mark, (l) => expectNew.every((f) => l.some((e) => e.uri === `/cube/${f}`)))).filter((e) => CHECKED.test(e.uri.slice('/cube/'.length)));
    for (const f of expectNew) {
      // The last request for it is the one that delivered it (an earlier one may have been
      // given up by the map while the view moved on).
      const last = log.filter((e) => e.uri === `/cube/${f}`).at(-1);
      assert.ok(last, `${f} fetched from nginx`);
      await assertLoggedCompressed(last, 'application/octet-stream', IMMUTABLE);
    }
    // Whatever else was asked for on the way was found (499: the browser gave up waiting).
    for (const l of log) assert.ok(l.status === 200 || l.status === 499, `${l.uri}: nginx answered ${l.status}`);
    // The browser's side: each came with its headers and decodes to the chunk the index names
    // (and so did any floor or line chunk it asked for on the way). The last response with a
    // body is the one that delivered it: an earlier request may have been given up.
    const leaves = allLeaves();
    const responses = await Promise.all(seen);
    const extra = responses.filter((s) => CHECKED.test(s.file) && !CHUNK.test(s.file)).map((s) => s.file);
    for (const f of new Set([...expectNew, ...extra])) assertDelivered(responses.findLast((x) => x.file === f && x.body !== null), f, leaves);

    // The closer view, with the chunks nginx sent, is what the test server draws there.
    const here = await camera(p);
    const other = await openDemo(browser!, server!.url);
    try {
      await other.page.evaluate((c) => (globalThis as unknown as VarioWindow).map.jumpTo({ centerProjected: [c.x, c.y], scaleDenominator: c.scale }), here);
      await idle(other.page);
      assert.deepEqual(await camera(other.page), here);
      const fromNginx = await screenshot(p);
      const d = drawn(fromNginx);
      assert.ok(d.share > 0.5 && d.classes >= 3, `the closer map is drawn: ${(100 * d.share).toFixed(1)} % in ${d.classes} class colours`);
      assertSamePicture(fromNginx, await screenshot(other.page), 0.01, 'zoomed in, nginx vs the test server');
    } finally {
      await checkAndClose(other);
    }
  });

  test('a map opened below the floor\'s top takes the floor chunks on screen from nginx, each decoding to its name', async () => {
    assert.ok(contents.floorLeaves.length > 0, 'the cube has floor chunks');
    assert.ok(closerUrl, "needs the wheel test's view past the base scale");
    seen.length = 0;
    const mark = (await readLog()).length;
    // That view, opened afresh (a new context: an empty cache) from the demo's URL, whose hash holds it.
    const fresh = await openDemo(browser!, nginx!.url, {}, { onPage: watch, hash: new URL(closerUrl).hash });
    try {
      const v = await view(fresh.page);
      assert.ok(v.z < contents.floorTop, `the slice (z ${v.z}) lies below the floor's top (${contents.floorTop})`);
      // A first view there shows the floor chunks: fewer bytes than the cube's chunks over it
      // (floorShown in client/src/source/chunk-scheduler.ts).
      const onScreen = contents.floorLeaves.filter((l) => boxMeets(l.bbox, { ground: v.bounds, zMin: v.z, zMax: v.z })).map((l) => l.file);
      assert.ok(onScreen.length > 0, 'floor chunks lie under the view');
      const leaves = allLeaves();
      const responses = await Promise.all(seen);
      for (const f of onScreen) assertDelivered(responses.findLast((x) => x.file === f && x.body !== null), f, leaves);
      const log = await logFrom(mark, (l) => onScreen.every((f) => l.some((e) => e.uri === `/cube/${f}`)));
      for (const f of onScreen) {
        const last = log.filter((e) => e.uri === `/cube/${f}`).at(-1);
        assert.ok(last, `${f} fetched from nginx`);
        await assertLoggedCompressed(last, 'application/octet-stream', IMMUTABLE);
      }
    } finally {
      await checkAndClose(fresh);
    }
  });
});
