// A cube that cannot be loaded is said in the map's container, naming the URL and the cause
// (not found, a server that refuses this origin or does not answer, a file that is not a
// cube), as well as by the `error` event; and `source` names a cube's directory with or
// without its trailing slash.
import assert from 'node:assert/strict';
import { writeFile } from 'node:fs/promises';
import path from 'node:path';
import { after, afterEach, before, describe, test } from 'node:test';
import { freePort } from '../server/nginx-process.js';
import { createStaticServer, type StaticServer } from '../server/static-server.js';
import { openMap, type MapPage } from './helpers/browser.js';
import { LIB_PAGE_HEAD, startLibSite, type LibSite } from './helpers/lib-site.js';
import { checkAndClose } from './helpers/test-bed.js';
import type { TestServer } from './helpers/test-server.js';
import { idle, type VarioWindow } from './helpers/vario-page.js';

// The map with the source (and retries) of the query string; every error event in window.errors.
const PAGE = `${LIB_PAGE_HEAD}
  <script type="module">
    import { VarioMap } from './lib/vario-map.js';
    const q = new URLSearchParams(location.search);
    const retries = q.get('retries');
    window.errors = [];
    window.map = new VarioMap({ container: 'map', source: q.get('source'), ...(retries === null ? {} : { sourceOptions: { retries: Number(retries) } }) });
    map.on('error', (e) => window.errors.push(e));
  </script>
</body>
</html>
`;

interface ErrorEvent {
  kind: string;
  url: string;
  status?: number;
  message: string;
}

describe('load errors in the container, and the source URL (bgt_otterlo_400m)', () => {
  let lib: LibSite;
  let server: TestServer;
  // Another origin, without CORS headers.
  let foreign: StaticServer;
  let foreignUrl: string;
  let mp: MapPage | null = null;

  before(async () => {
    lib = await startLibSite({ 'errors.html': PAGE });
    server = lib.server;
    await writeFile(path.join(lib.dir, 'not-a-cube.json'), JSON.stringify({ type: 'FeatureCollection', features: [] }));
    foreign = createStaticServer({ root: lib.cube.dir });
    foreignUrl = `http://127.0.0.1:${(await foreign.listen(0, '127.0.0.1')).port}/`;
  });

  afterEach(async () => {
    await checkAndClose(mp);
    mp = null;
  });

  after(async () => {
    await foreign?.close();
    await lib?.close();
  });

  /** Opens the page on a source that fails; its alert's text and the error events. */
  async function failing(params: Record<string, string | number>, expected: RegExp): Promise<{ text: string; errors: ErrorEvent[] }> {
    mp = await openMap(lib.browser, server.url, params, { page: 'errors.html' });
    mp.expect(expected);
    const alert = mp.page.getByRole('alert');
    await alert.waitFor({ state: 'visible', timeout: 30_000 });
    const text = await alert.innerText();
    const errors = await mp.page.evaluate(() => (globalThis as unknown as { errors: ErrorEvent[] }).errors);
    // A page waiting for the map is not left waiting.
    assert.equal(await mp.page.evaluate(() => (globalThis as unknown as VarioWindow).map.whenIdle().then((r) => r.complete)), false);
    return { text, errors };
  }

  test('a 404 names the URL and says it was not found', async () => {
    const url = `${server.url}missing/index.json`;
    const { text, errors } = await failing({ source: 'missing' }, /Failed to load resource.*404/);
    assert.match(text, /The map could not be loaded/);
    assert.ok(text.includes(`${url} was not found (HTTP 404)`), text);
    assert.deepEqual(errors.map((e) => [e.kind, e.url, e.status]), [['http', url, 404]]);
  });

  test('a JSON file that is not a cube names the URL and says so', async () => {
    const url = `${server.url}not-a-cube.json`;
    const { text, errors } = await failing({ source: 'not-a-cube.json' }, /^$/);
    assert.ok(text.includes(`${url} is not a cube`), text);
    assert.deepEqual(errors.map((e) => [e.kind, e.url]), [['index', url]]);
  });

  test('a server that refuses this origin (no CORS header) names the URL and CORS', async () => {
    const url = `${foreignUrl}index.json`;
    const { text, errors } = await failing({ source: foreignUrl, retries: 0 }, /CORS policy|Failed to load resource/);
    assert.ok(text.includes(`${url} could not be fetched`), text);
    assert.match(text, /CORS/);
    assert.deepEqual(errors.map((e) => [e.kind, e.url]), [['network', url]]);
  });

  test('a server that does not answer names the URL', async () => {
    const url = `http://127.0.0.1:${await freePort()}/cube/index.json`;
    const { text, errors } = await failing({ source: url, retries: 1 }, /Failed to load resource|ERR_CONNECTION_REFUSED/);
    assert.ok(text.includes(`${url} could not be fetched: the server did not answer`), text);
    assert.deepEqual(errors.map((e) => [e.kind, e.url]), [['network', url]]);
  });

  test("source: 'cube' (no trailing slash) loads the cube's index.json and completes", async () => {
    mp = await openMap(lib.browser, server.url, { source: 'cube' }, { page: 'errors.html' });
    await idle(mp.page);
    const page = mp.page;
    assert.equal(await page.evaluate(() => (globalThis as unknown as VarioWindow).map.whenIdle().then((r) => r.complete)), true);
    assert.equal(await page.evaluate(() => (globalThis as unknown as { map: { getSourceUrl(): string } }).map.getSourceUrl()), `${server.cubeUrl}index.json`);
    assert.equal(await page.getByRole('alert').count(), 0);
    assert.deepEqual(await page.evaluate(() => (globalThis as unknown as { errors: unknown[] }).errors), []);
  });
});
