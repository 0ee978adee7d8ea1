// createStaticServer: the chunk directory over HTTP/1.1 with node:http, hardened against slow
// and malformed clients, and listening on loopback unless told otherwise.
//
// Hand-written, not a library, by issue 10's rule (a library unless it falls below 0.8x nginx
// or loses a hardening test), measured in Nov 2026: sirv 3.0.2 serves index.json at 0.2-0.6x
// nginx in bench:serve (ours 0.6-1.0 in the same runs; the chunk is bandwidth-bound, near 1
// for all), follows symlinks out of the root (a file, a directory, a .br sibling), answers
// suffix and multiple ranges wrongly and from the compressed copies, ignores If-Range and q=0,
// and sends weak ETags; @fastify/static 10 measured 0.35-0.40x, with weak ETags, ranges of the
// compressed copies and symlinks out of the root followed too. Memory for small files
// (content-cache.ts) and remembered lookups (lookup-cache.ts) are what keep ours near nginx.
import { realpathSync, statSync } from 'node:fs';
import { createServer, type IncomingMessage, type Server, type ServerResponse } from 'node:http';
import type { AddressInfo, Socket } from 'node:net';
import { CachePolicy } from './cache-control.js';
import { ContentCache } from './content-cache.js';
import { watchConnections } from './connection-watchdog.js';
import { CorsPolicy, type CorsOrigins } from './cors.js';
import { LookupCache } from './lookup-cache.js';
import { createRequestHandler } from './request-handler.js';

export interface StaticServerOptions {
  /** The directory to serve. Nothing outside it is ever read, symlinks included. */
  root: string;
  /** Origins allowed to read cross-origin: '*' or a list; absent or empty means no CORS. */
  cors?: CorsOrigins;
  /** File names that never change (content-hashed); default: a hex run of 8 or more. */
  immutablePattern?: RegExp;
  /** Time a client has to send its request head (default 10 s); slowloris ends here. */
  headersTimeoutMs?: number;
  /** Time a client has to send its whole request (default 30 s). */
  requestTimeoutMs?: number;
  /** An idle keep-alive connection is closed after this (default 5 s). */
  keepAliveTimeoutMs?: number;
  /** A response whose client stopped reading is abandoned after this (default 30 s). */
  stallTimeoutMs?: number;
  /** How often the timeouts above are checked (default 1 s; Node's own is 30 s). */
  timeoutCheckIntervalMs?: number;
  /** Request line plus headers, in bytes (default 16 KiB); larger gets 431. */
  maxHeaderBytes?: number;
  /** Open connections at most (default 4096); more are refused at accept. */
  maxConnections?: number;
  /** Memory for the bytes of small files (default 64 MiB). */
  cacheBytes?: number;
  /** Files up to this size are served from memory (default 1 MiB); larger are streamed. */
  maxCachedFileBytes?: number;
  /**
   * How long a file found inside the root is served again without looking at the disk
   * (default 100 ms). A file rewritten, replaced or deleted may be served as it was for this
   * long; 0 looks at every request. Nothing outside the root is served either way.
   */
  revalidateAfterMs?: number;
  /** Unexpected failures (a 500 or a broken stream); default: printed to stderr. */
  onError?: (err: unknown) => void;
}

export interface StaticServer {
  /** Starts listening; port 0 picks a free port. Host defaults to 127.0.0.1. */
  listen(port?: number, host?: string): Promise<AddressInfo>;
  /** Stops accepting, lets running responses finish for a moment, then closes everything. */
  close(): Promise<void>;
  /** The bound address once listening, else null. */
  readonly address: AddressInfo | null;
  /** http://host:port/ once listening, else null. */
  readonly url: string | null;
  /** The underlying node:http server, for tests and embedding. */
  readonly server: Server;
}

const CLOSE_GRACE_MS = 2000;

function rootOf(dir: string): string {
  const real = realpathSync(dir);
  if (!statSync(real).isDirectory()) throw new Error(`${dir} is not a directory`);
  return real;
}

/** What a static server's request handler needs: no connection handling. */
export type StaticHandlerOptions = Pick<StaticServerOptions, 'root' | 'cors' | 'immutablePattern' | 'cacheBytes' | 'maxCachedFileBytes' | 'revalidateAfterMs' | 'onError'>;

/** The request handler alone (the serving rules for one root), for a server that routes. */
export function createStaticHandler(options: StaticHandlerOptions): (req: IncomingMessage, res: ServerResponse) => void {
  const root = rootOf(options.root);
  return createRequestHandler({
    cors: new CorsPolicy(options.cors),
    cachePolicy: new CachePolicy(options.immutablePattern),
    contents: new ContentCache(options.cacheBytes ?? 64 << 20, options.maxCachedFileBytes ?? 1 << 20),
    lookups: new LookupCache(root, { revalidateAfterMs: options.revalidateAfterMs }),
    onError: options.onError ?? ((err) => console.error('static server:', err)),
  });
}

export function createStaticServer(options: StaticServerOptions): StaticServer {
  const handler = createStaticHandler(options);
  const headersTimeout = options.headersTimeoutMs ?? 10_000;
  const keepAliveTimeout = options.keepAliveTimeoutMs ?? 5_000;
  const checkEvery = options.timeoutCheckIntervalMs ?? 1_000;
  const server = createServer(
    {
      headersTimeout,
      // Node refuses a request timeout shorter than the headers timeout.
      requestTimeout: Math.max(options.requestTimeoutMs ?? 30_000, headersTimeout),
      keepAliveTimeout,
      connectionsCheckingInterval: checkEvery,
      maxHeaderSize: options.maxHeaderBytes ?? 16 * 1024,
      requireHostHeader: true,
    },
    handler,
  );
  server.maxConnections = options.maxConnections ?? 4096;
  watchConnections(server, { headersMs: headersTimeout, keepAliveMs: keepAliveTimeout, stallMs: options.stallTimeoutMs ?? 30_000, checkEveryMs: checkEvery });
  // CONNECT is not for us; without a listener node would drop the socket with no answer.
  server.on('connect', (_req, socket: Socket) => {
    socket.end('HTTP/1.1 405 Method Not Allowed\r\nAllow: GET, HEAD\r\nContent-Length: 0\r\nConnection: close\r\n\r\n');
  });

  let address: AddressInfo | null = null;
  return {
    server,
    get address() {
      return address;
    },
    get url() {
      if (!address) return null;
      const host = address.family === 'IPv6' ? `[${address.address}]` : address.address;
      return `http://${host}:${address.port}/`;
    },
    listen(port = 0, host = '127.0.0.1') {
      return new Promise<AddressInfo>((resolve, reject) => {
        const onError = (err: Error): void => reject(err);
        server.once('error', onError);
        server.listen(port, host, () => {
          server.off('error', onError);
          address = server.address() as AddressInfo;
          resolve(address);
        });
      });
    },
    close() {
      return new Promise<void>((resolve, reject) => {
        if (!server.listening) {
          resolve();
          return;
        }
        const force = setTimeout(() => server.closeAllConnections(), CLOSE_GRACE_MS);
        force.unref();
        server.close((err) => {
          clearTimeout(force);
          address = null;
          if (err) reject(err);
          else resolve();
        });
        server.closeIdleConnections();
      });
    },
  };
}
