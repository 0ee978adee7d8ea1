// The browser tests' server: one origin on 127.0.0.1 that serves the built client at / and a
// cube directory at /cube/, both through the project's createStaticServer, with a fault
// injecting proxy in front: failing or slow chunk requests, 404s, corrupt bodies, gzip bodies
// without Content-Encoding. Every request is logged with what became of it (answered, failed,
// or aborted by the browser). Responses are marked no-store so that a chunk fetched again
// really reaches the server (the real server lets immutable chunks be cached forever).
import { createServer, request as httpRequest, type IncomingMessage, type Server, type ServerResponse } from 'node:http';
import type { AddressInfo } from 'node:net';
import { createStaticServer, type StaticServer } from '../../server/static-server.js';

export interface LoggedRequest {
  path: string;
  /** HTTP status sent, 'network' (socket destroyed on purpose) or 'aborted' (by the client). */
  outcome: number | 'network' | 'aborted';
  start: number;
  end: number;
}

export interface Faults {
  /** Share of chunk requests (c-*.bin, and the floor's b-*.bin) that fail, half with 503, half by a dropped connection. */
  chunkFailRate: number;
  /** Seed of the failure choices (deterministic per run). */
  seed: number;
  /** Paths (under /cube/, e.g. "c-abc.bin") answered with 404. */
  notFound: Set<string>;
  /** Paths answered with 503, every time. */
  unavailable: Set<string>;
  /** Paths answered with 503 the first time they are asked for. */
  unavailableOnce: Set<string>;
  /** Paths answered with 429 (Too Many Requests) the first time they are asked for, with Retry-After: this many seconds. */
  tooManyOnce: Map<string, number>;
  /** Delay before answering a cube request, ms (e.g. to abort it meanwhile). */
  delayMs: (file: string) => number;
  /** A cube request waits, after its delay, until the promise given for its file settles (a gate the test opens), at most HELD_MAX_MS. */
  heldUntil: (file: string) => Promise<void> | undefined;
  /** Delay before answering a request for the app's own files (path from the site's root, e.g. the worker's script), ms. */
  appDelayMs: (path: string) => number;
  /** The app's own files answered with 404 (path from the site's root). */
  appNotFound: (path: string) => boolean;
  /** Cube files whose body is changed before it is sent. */
  corrupt: Map<string, (body: Buffer) => Buffer>;
  /** Chunks are sent as their .gz copy without a Content-Encoding header. */
  gzipWithoutEncoding: boolean;
}

export interface TestServer {
  url: string;
  /** The cube's URL (a directory, ending in /). */
  cubeUrl: string;
  log: LoggedRequest[];
  faults: Faults;
  /** Requests for a cube file, e.g. requestsFor('c-') for the cube's chunks. */
  requestsFor(prefix: string): LoggedRequest[];
  close(): Promise<void>;
}

function mulberry32(seed: number): () => number {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

/** `unref`: the wait does not keep the process alive. */
const sleep = (ms: number, unref = false): Promise<void> =>
  new Promise((r) => {
    const t = setTimeout(r, ms);
    if (unref) t.unref();
  });
/** The longest a request is held by heldUntil. */
const HELD_MAX_MS = 30_000;

/** A server that misbehaves in no way: the faults a test starts from, and goes back to after. */
export function noFaults(): Faults {
  return { chunkFailRate: 0, seed: 1, notFound: new Set(), unavailable: new Set(), unavailableOnce: new Set(), tooManyOnce: new Map(), delayMs: () => 0, heldUntil: () => undefined, appDelayMs: () => 0, appNotFound: () => false, corrupt: new Map(), gzipWithoutEncoding: false };
}

export async function startTestServer(opts: { clientDir: string; cubeDir: string }): Promise<TestServer> {
  const errors: unknown[] = [];
  const client: StaticServer = createStaticServer({ root: opts.clientDir, onError: (e) => errors.push(e) });
  const cube: StaticServer = createStaticServer({ root: opts.cubeDir, onError: (e) => errors.push(e) });
  const clientPort = (await client.listen(0, '127.0.0.1')).port;
  const cubePort = (await cube.listen(0, '127.0.0.1')).port;
  const log: LoggedRequest[] = [];
  const faults = noFaults();
  let random = mulberry32(faults.seed);
  let seedUsed = faults.seed;

  const forward = (req: IncomingMessage, res: ServerResponse, port: number, path: string, entry: LoggedRequest, transform?: (b: Buffer) => Buffer, identity = false): void => {
    const headers = { ...req.headers, host: `127.0.0.1:${port}` };
    // Revalidation would turn a refetch into a 304 the browser answers from its cache.
    delete headers['if-none-match'];
    delete headers['if-modified-since'];
    if (identity || transform) headers['accept-encoding'] = 'identity';
    const up = httpRequest({ host: '127.0.0.1', port, path, method: req.method, headers }, (upRes) => {
      const h = { ...upRes.headers, 'cache-control': 'no-store' };
      delete h.etag;
      delete h['last-modified'];
      if (transform && upRes.statusCode === 200) {
        const parts: Buffer[] = [];
        upRes.on('data', (d: Buffer) => parts.push(d));
        upRes.on('end', () => {
          const body = transform(Buffer.concat(parts));
          h['content-length'] = String(body.length);
          delete h['content-encoding'];
          res.writeHead(200, h);
          res.end(body);
        });
        return;
      }
      res.writeHead(upRes.statusCode ?? 502, h);
      upRes.pipe(res);
    });
    up.on('error', () => res.destroy());
    req.on('close', () => {
      if (!res.writableFinished) up.destroy();
    });
    up.end();
    res.on('finish', () => {
      entry.outcome = res.statusCode;
      entry.end = Date.now();
    });
  };

  const front: Server = createServer((req, res) => {
    const url = new URL(req.url ?? '/', 'http://127.0.0.1');
    const entry: LoggedRequest = { path: url.pathname, outcome: 'aborted', start: Date.now(), end: 0 };
    log.push(entry);
    res.on('close', () => {
      if (!res.writableFinished && entry.outcome === 'aborted') entry.end = Date.now();
    });
    /** Answers with an error status (and these headers), logged. */
    const refuse = (status: 404 | 429 | 503, headers: Record<string, string> = {}): void => {
      entry.outcome = status;
      entry.end = Date.now();
      res.writeHead(status, { 'content-type': 'text/plain', 'cache-control': 'no-store', ...headers });
      res.end(`${status} ${status === 404 ? 'not found' : 'try again'}\n`);
    };
    if (!url.pathname.startsWith('/cube/')) {
      if (faults.appNotFound(url.pathname)) return refuse(404);
      const delay = faults.appDelayMs(url.pathname);
      if (delay > 0) void sleep(delay).then(() => res.destroyed || req.destroyed || forward(req, res, clientPort, url.pathname + url.search, entry));
      else forward(req, res, clientPort, url.pathname + url.search, entry);
      return;
    }
    const file = url.pathname.slice('/cube/'.length);
    void (async () => {
      const delay = faults.delayMs(file);
      if (delay > 0) await sleep(delay);
      const gate = faults.heldUntil(file);
      // A test that fails before opening its gate still ends: the request goes after HELD_MAX_MS.
      if (gate) await Promise.race([gate.catch(() => undefined), sleep(HELD_MAX_MS, true)]);
      if (res.destroyed || req.destroyed) return; // the browser gave up meanwhile
      if (faults.notFound.has(file)) return refuse(404);
      if (faults.unavailable.has(file) || faults.unavailableOnce.delete(file)) return refuse(503);
      const retryAfter = faults.tooManyOnce.get(file);
      if (retryAfter !== undefined && faults.tooManyOnce.delete(file)) return refuse(429, { 'retry-after': String(retryAfter) });
      if (/^[cb]-[0-9a-f]+\.bin$/.test(file) && faults.chunkFailRate > 0) {
        if (seedUsed !== faults.seed) {
          seedUsed = faults.seed;
          random = mulberry32(faults.seed);
        }
        const r = random();
        if (r < faults.chunkFailRate) {
          if (r < faults.chunkFailRate / 2) {
            refuse(503);
          } else {
            entry.outcome = 'network';
            entry.end = Date.now();
            req.socket.destroy();
          }
          return;
        }
      }
      const corrupt = faults.corrupt.get(file);
      if (faults.gzipWithoutEncoding && /^[cb]-[0-9a-f]+\.bin$/.test(file)) {
        forward(req, res, cubePort, `/${file}.gz`, entry, (b) => b, true);
      } else {
        forward(req, res, cubePort, `/${file}${url.search}`, entry, corrupt);
      }
    })();
  });
  await new Promise<void>((resolve) => front.listen(0, '127.0.0.1', resolve));
  const port = (front.address() as AddressInfo).port;
  const url = `http://127.0.0.1:${port}/`;
  return {
    url,
    cubeUrl: `${url}cube/`,
    log,
    faults,
    requestsFor: (prefix) => log.filter((e) => e.path.startsWith(`/cube/${prefix}`)),
    async close() {
      front.closeAllConnections();
      await new Promise<void>((resolve) => front.close(() => resolve()));
      await client.close();
      await cube.close();
      if (errors.length > 0) throw new Error(`the static server reported: ${errors.map(String).join('; ')}`);
    },
  };
}
