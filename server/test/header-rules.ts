// The serving rules every host of a map directory must follow, as tests that run against any
// server of the fixture: ours (header-rules.test.ts) and nginx with the documented config
// (nginx-config.test.ts). Expectations are written out by hand from the fixture's files.
import assert from 'node:assert/strict';
import type { IncomingHttpHeaders } from 'node:http';
import { describe, it } from 'node:test';
import { bytesOf, CHUNK, CHUNK_SIZE, CORS_ORIGIN, SECRET, SUB_INDEX, type Fixture } from './fixture.js';
import { rawBody, rawExchange, request, type Reply } from './http-client.js';
import { rawGet, TRAVERSAL_TARGETS } from './traversal-attempts.js';

export interface Target {
  base: string;
  port: number;
}

const IMMUTABLE = 'public, max-age=31536000, immutable';
const BROWSER_ENCODINGS = 'gzip, deflate, br, zstd';

/** Lowercased comma-separated tokens of a header, whether sent once or several times. */
export function tokens(value: string | string[] | undefined): string[] {
  const joined = Array.isArray(value) ? value.join(',') : (value ?? '');
  return joined
    .split(',')
    .map((s) => s.trim().toLowerCase())
    .filter((s) => s !== '');
}

function header(h: IncomingHttpHeaders, name: string): string | undefined {
  const v = h[name];
  return Array.isArray(v) ? v.join(', ') : v;
}

export function describeHeaderRules(target: () => Target, fixture: () => Fixture): void {
  const get = (path: string, headers: Record<string, string> = {}, method = 'GET'): Promise<Reply> =>
    request(target().base, path, { method, headers });
  const bytes = (path: string): Buffer => bytesOf(fixture(), path);

  it('sends each file with its content type, its length and its exact bytes', async () => {
    const expected: [string, string][] = [
      ['/index.json', 'application/json'],
      ['/meta.json', 'application/json'],
      ['/' + SUB_INDEX, 'application/json'],
      ['/' + CHUNK, 'application/octet-stream'],
      ['/index.html', 'text/html; charset=utf-8'],
      ['/app-5e6f7a8b.js', 'text/javascript; charset=utf-8'],
      ['/style.css', 'text/css; charset=utf-8'],
      ['/module.wasm', 'application/wasm'],
      ['/icon.svg', 'image/svg+xml'],
      ['/site.webmanifest', 'application/manifest+json'],
      ['/logo.png', 'image/png'],
      ['/notes.txt', 'text/plain; charset=utf-8'],
      ['/noext', 'application/octet-stream'],
      ['/empty.json', 'application/json'],
    ];
    for (const [path, type] of expected) {
      const r = await get(path);
      assert.equal(r.status, 200, path);
      assert.equal(r.headers['content-type']?.toLowerCase(), type, path);
      assert.equal(r.headers['content-encoding'], undefined, path);
      assert.equal(Number(r.headers['content-length']), bytes(path).length, path);
      assert.ok(r.body.equals(bytes(path)), `${path}: body differs from the file`);
      assert.equal(r.headers['x-content-type-options'], 'nosniff', path);
    }
  });

  it('serves a percent-encoded name and answers 404 for a missing file', async () => {
    const spaced = await get('/a%20file.json');
    assert.equal(spaced.status, 200);
    assert.ok(spaced.body.equals(bytes('/a file.json')));
    assert.equal((await get('/missing.json')).status, 404);
    assert.equal((await get('/c-0000000000000000.bin')).status, 404);
    assert.equal((await get('/index.json/')).status, 404, 'a file is not a directory');
  });

  it('lets caches keep content-hashed names for a year and revalidate everything else', async () => {
    for (const path of ['/' + CHUNK, '/' + SUB_INDEX, '/app-5e6f7a8b.js']) {
      assert.equal((await get(path)).headers['cache-control'], IMMUTABLE, path);
      assert.equal((await get(path, { 'accept-encoding': 'br' })).headers['cache-control'], IMMUTABLE, `${path} as br`);
    }
    for (const path of ['/index.json', '/meta.json', '/index.html', '/', '/style.css', '/noext', '/sub/']) {
      assert.equal((await get(path)).headers['cache-control'], 'no-cache', path);
      assert.equal((await get(path, { 'accept-encoding': 'br' })).headers['cache-control'], 'no-cache', `${path} as br`);
    }
  });

  it('gives each file a strong ETag, and a 304 without a body when it still matches', async () => {
    for (const path of ['/index.json', '/' + CHUNK]) {
      const first = await get(path);
      const etag = first.headers.etag!;
      assert.match(etag, /^"[^"]+"$/, `${path}: strong ETag`);
      const again = await get(path);
      assert.equal(again.headers.etag, etag, `${path}: same file, same ETag`);

      const cached = await get(path, { 'if-none-match': etag });
      assert.equal(cached.status, 304, path);
      assert.equal(cached.body.length, 0);
      assert.equal(cached.headers.etag, etag);
      assert.equal(cached.headers['cache-control'], first.headers['cache-control']);
      assert.equal((await get(path, { 'if-none-match': `"nope", W/${etag}` })).status, 304, `${path}: weak comparison`);
      assert.equal((await get(path, { 'if-none-match': '"some-other-version"' })).status, 200, path);
      assert.equal((await get(path, { 'if-modified-since': first.headers['last-modified']! })).status, 304, path);
    }
  });

  it('picks the brotli or gzip sibling from Accept-Encoding, brotli first', async () => {
    const cases: [string, string | undefined, 'br' | 'gzip' | undefined][] = [
      ['/index.json', BROWSER_ENCODINGS, 'br'],
      ['/index.json', 'gzip, br', 'br'],
      ['/index.json', 'GZIP', 'gzip'],
      ['/index.json', 'br;q=0, gzip', 'gzip'],
      ['/index.json', 'br;q=0.5, gzip;q=0', 'br'],
      ['/index.json', 'gzip;q=0', undefined],
      ['/index.json', 'identity', undefined],
      ['/index.json', 'deflate', undefined],
      ['/index.json', undefined, undefined],
      ['/' + CHUNK, 'br', 'br'],
      ['/' + CHUNK, 'gzip', 'gzip'],
      ['/only-gzip.json', BROWSER_ENCODINGS, 'gzip'],
      ['/only-gzip.json', 'br', undefined],
      ['/index.html', BROWSER_ENCODINGS, 'br'],
      ['/app-5e6f7a8b.js', 'gzip', 'gzip'],
      ['/style.css', BROWSER_ENCODINGS, 'br'],
      ['/module.wasm', BROWSER_ENCODINGS, 'br'],
      ['/icon.svg', 'gzip', 'gzip'],
      ['/site.webmanifest', BROWSER_ENCODINGS, 'br'],
      ['/', BROWSER_ENCODINGS, 'br'],
    ];
    for (const [path, accept, coding] of cases) {
      const r = await get(path, accept === undefined ? {} : { 'accept-encoding': accept });
      const what = `${path} with Accept-Encoding ${accept ?? '(none)'}`;
      assert.equal(r.status, 200, what);
      assert.equal(r.headers['content-encoding'], coding, what);
      const file = path === '/' ? '/index.html' : path;
      const sent = coding === 'br' ? bytes(file + '.br') : coding === 'gzip' ? bytes(file + '.gz') : bytes(file);
      assert.ok(r.body.equals(sent), `${what}: body is not the ${coding ?? 'identity'} file`);
      assert.equal(Number(r.headers['content-length']), sent.length, what);
      assert.ok(tokens(r.headers.vary).includes('accept-encoding'), `${what}: Vary`);
    }
    // The compressed copy keeps the type of the file it stands for.
    assert.equal((await get('/index.json', { 'accept-encoding': 'br' })).headers['content-type'], 'application/json');
    assert.equal((await get('/index.html', { 'accept-encoding': 'br' })).headers['content-type']?.toLowerCase(), 'text/html; charset=utf-8');
  });

  it('sends a precompressed copy asked for by its own name as it is, not as an encoding', async () => {
    const br = await get('/index.json.br', { 'accept-encoding': 'br' });
    assert.equal(br.status, 200);
    assert.equal(br.headers['content-encoding'], undefined);
    assert.equal(br.headers['content-type'], 'application/octet-stream');
    assert.ok(br.body.equals(bytes('/index.json.br')));
    const gz = await get('/index.json.gz', { 'accept-encoding': 'gzip' });
    assert.equal(gz.headers['content-encoding'], undefined);
    assert.equal(gz.headers['content-type'], 'application/gzip');
    assert.ok(gz.body.equals(bytes('/index.json.gz')));
  });

  it('gives each encoding its own ETag, so a cached gzip copy never validates brotli', async () => {
    const plain = await get('/index.json');
    const br = await get('/index.json', { 'accept-encoding': 'br' });
    const gz = await get('/index.json', { 'accept-encoding': 'gzip' });
    assert.equal(new Set([plain.headers.etag, br.headers.etag, gz.headers.etag]).size, 3);
    assert.equal((await get('/index.json', { 'accept-encoding': 'br', 'if-none-match': br.headers.etag! })).status, 304);
    assert.equal((await get('/index.json', { 'accept-encoding': 'br', 'if-none-match': gz.headers.etag! })).status, 200);
  });

  it('never takes a precompressed sibling that is a symlink out of the root', async () => {
    const r = await get('/evil.json', { 'accept-encoding': 'br' });
    assert.equal(r.status, 200);
    assert.equal(r.headers['content-encoding'], undefined);
    assert.ok(r.body.equals(bytes('/evil.json')));
    assert.ok(!r.body.toString('latin1').includes(SECRET));
  });

  it('answers HEAD with the headers of GET and no body', async () => {
    for (const [path, accept] of [['/index.json', ''], ['/index.json', 'br'], ['/' + CHUNK, '']] as const) {
      const headers: Record<string, string> = accept ? { 'accept-encoding': accept } : {};
      const g = await get(path, headers);
      const h = await get(path, headers, 'HEAD');
      assert.equal(h.status, 200);
      assert.equal(h.body.length, 0, `${path}: HEAD has no body`);
      for (const name of ['content-type', 'content-length', 'etag', 'cache-control', 'content-encoding', 'last-modified']) {
        assert.equal(header(h.headers, name), header(g.headers, name), `${path} ${accept}: ${name}`);
      }
    }
  });

  it('answers a single byte range with 206 and exactly those bytes of the uncompressed file', async () => {
    const chunk = bytes('/' + CHUNK);
    const cases: [string, number, number][] = [
      ['bytes=0-99', 0, 99],
      ['bytes=1000-1000', 1000, 1000],
      ['bytes=-100', CHUNK_SIZE - 100, CHUNK_SIZE - 1],
      [`bytes=${CHUNK_SIZE - 10}-`, CHUNK_SIZE - 10, CHUNK_SIZE - 1],
      [`bytes=${CHUNK_SIZE - 5}-${CHUNK_SIZE + 1000}`, CHUNK_SIZE - 5, CHUNK_SIZE - 1],
      ['bytes=0-', 0, CHUNK_SIZE - 1],
    ];
    for (const [range, start, end] of cases) {
      // Ask for brotli too: ranges still address the identity bytes.
      const r = await get('/' + CHUNK, { range, 'accept-encoding': BROWSER_ENCODINGS });
      assert.equal(r.status, 206, range);
      assert.equal(r.headers['content-range'], `bytes ${start}-${end}/${CHUNK_SIZE}`, range);
      assert.equal(r.headers['content-encoding'], undefined, range);
      assert.equal(Number(r.headers['content-length']), end - start + 1, range);
      assert.ok(r.body.equals(chunk.subarray(start, end + 1)), `${range}: wrong bytes`);
      assert.equal(r.headers['cache-control'], IMMUTABLE, range);
    }
  });

  it('answers 416 for a range past the end, and the whole file for several ranges', async () => {
    const past = await get('/' + CHUNK, { range: `bytes=${CHUNK_SIZE}-` });
    assert.equal(past.status, 416);
    assert.equal(past.headers['content-range'], `bytes */${CHUNK_SIZE}`);
    const far = await get('/index.json', { range: 'bytes=99999999-99999999' });
    assert.equal(far.status, 416);
    assert.equal(far.headers['content-range'], `bytes */${bytes('/index.json').length}`);
    const multi = await get('/' + CHUNK, { range: 'bytes=0-1,5-6' });
    assert.equal(multi.status, 200);
    assert.ok(multi.body.equals(bytes('/' + CHUNK)));
  });

  it('honours If-Range: the range for the same version, the whole file for another', async () => {
    const whole = await get('/' + CHUNK);
    const etag = whole.headers.etag!;
    const lastModified = whole.headers['last-modified']!;
    const same = await get('/' + CHUNK, { range: 'bytes=0-9', 'if-range': etag });
    assert.equal(same.status, 206);
    assert.ok(same.body.equals(bytes('/' + CHUNK).subarray(0, 10)));
    assert.equal((await get('/' + CHUNK, { range: 'bytes=0-9', 'if-range': lastModified })).status, 206);
    const changed = await get('/' + CHUNK, { range: 'bytes=0-9', 'if-range': '"an-older-version"' });
    assert.equal(changed.status, 200);
    assert.ok(changed.body.equals(bytes('/' + CHUNK)));
    assert.equal((await get('/' + CHUNK, { range: 'bytes=0-9', 'if-range': `W/${etag}` })).status, 200, 'weak tags never match If-Range');
    assert.equal((await get('/' + CHUNK, { range: 'bytes=0-9', 'if-range': 'Mon, 01 Jan 2001 00:00:00 GMT' })).status, 200);
  });

  it('refuses methods other than GET, HEAD (and the OPTIONS preflight) with 405 and Allow', async () => {
    for (const method of ['POST', 'PUT', 'DELETE', 'PATCH']) {
      const r = await get('/index.json', {}, method);
      assert.equal(r.status, 405, method);
      const allow = tokens(r.headers.allow);
      assert.ok(allow.includes('get') && allow.includes('head'), `${method}: Allow ${r.headers.allow}`);
    }
  });

  it("serves a directory's index.html, redirects to the slash, and never lists a directory", async () => {
    const root = await get('/');
    assert.equal(root.status, 200);
    assert.ok(root.body.equals(bytes('/index.html')));
    const sub = await get('/sub/');
    assert.equal(sub.status, 200);
    assert.ok(sub.body.equals(bytes('/sub/index.html')));
    const bare = await get('/sub');
    assert.equal(bare.status, 301);
    assert.equal(bare.headers.location, '/sub/');
    const empty = await get('/empty-dir/');
    assert.equal(empty.status, 404);
    assert.ok(!empty.body.toString().includes('index'), 'no listing');
  });

  describe('refuses every path that leads out of the root, or to a dotfile', () => {
    for (const t of TRAVERSAL_TARGETS) {
      it(t, async () => {
        const r = await rawExchange(target().port, rawGet(t));
        assert.ok(r.status !== undefined && r.status >= 400 && r.status < 500, `status ${r.status}`);
        assert.ok(!r.text.includes(SECRET), 'leaked the secret');
      });
    }
    it('and keeps serving', async () => {
      assert.equal((await get('/index.json')).status, 200);
    });
  });

  it('refuses an oversized request head with a 4xx, and keeps serving', async () => {
    const r = await rawExchange(target().port, `GET /index.json HTTP/1.1\r\nHost: 127.0.0.1\r\nX-Big: ${'a'.repeat(64 * 1024)}\r\nConnection: close\r\n\r\n`);
    assert.ok(r.status !== undefined && r.status >= 400 && r.status < 500, `status ${r.status}`);
    assert.equal(rawBody(r.text).includes('"version"'), false);
    assert.equal((await get('/index.json')).status, 200);
  });

  it('lets an allowed origin read files, their ETag, ranges and Retry-After cross-origin', async () => {
    const checks: [string, Record<string, string>, number][] = [
      ['/index.json', {}, 200],
      ['/' + CHUNK, { range: 'bytes=0-9' }, 206],
      ['/missing.json', {}, 404],
    ];
    for (const [path, extra, status] of checks) {
      const r = await get(path, { origin: CORS_ORIGIN, ...extra });
      assert.equal(r.status, status, path);
      assert.equal(r.headers['access-control-allow-origin'], CORS_ORIGIN, path);
      if (status !== 404) {
        const exposed = tokens(r.headers['access-control-expose-headers']);
        for (const name of ['etag', 'content-length', 'content-range', 'retry-after']) assert.ok(exposed.includes(name), `${path}: exposes ${name}`);
      }
      assert.ok(tokens(r.headers.vary).includes('origin'), `${path}: Vary: Origin`);
    }
    const etag = (await get('/index.json')).headers.etag!;
    const cached = await get('/index.json', { origin: CORS_ORIGIN, 'if-none-match': etag });
    assert.equal(cached.status, 304);
    assert.equal(cached.headers['access-control-allow-origin'], CORS_ORIGIN);
  });

  it('gives no cross-origin grant to other origins', async () => {
    const r = await get('/index.json', { origin: 'https://evil.example' });
    assert.equal(r.status, 200); // the file is public; only the browser's cross-origin read is refused
    assert.equal(r.headers['access-control-allow-origin'], undefined);
    const pre = await get('/index.json', { origin: 'https://evil.example', 'access-control-request-method': 'GET' }, 'OPTIONS');
    assert.equal(pre.headers['access-control-allow-origin'], undefined);
  });

  it('answers a CORS preflight for a Range request from an allowed origin', async () => {
    const r = await get('/' + CHUNK, { origin: CORS_ORIGIN, 'access-control-request-method': 'GET', 'access-control-request-headers': 'range, if-none-match' }, 'OPTIONS');
    assert.equal(r.status, 204);
    assert.equal(r.body.length, 0);
    assert.equal(r.headers['access-control-allow-origin'], CORS_ORIGIN);
    const methods = tokens(r.headers['access-control-allow-methods']);
    assert.ok(methods.includes('get') && methods.includes('head'));
    const allowedHeaders = tokens(r.headers['access-control-allow-headers']);
    for (const name of ['range', 'if-none-match', 'if-range']) assert.ok(allowedHeaders.includes(name), `allows ${name}`);
    assert.ok(Number(r.headers['access-control-max-age']) > 0);
  });
}
