// One origin for the demo: the built client at / ("/" being demo.html) and a cube directory
// under a path (default /chunks/), each with the static server's rules for its own root. npm
// start serves the map with it; the offline test stops it and starts it again on the same port,
// which must stay the same origin for the service worker and its caches.
import { createServer, type Server } from 'node:http';
import type { AddressInfo } from 'node:net';
import { createStaticHandler } from './static-server.js';

export interface SiteServerOptions {
  /** The built client (dist/client). */
  clientDir: string;
  cubeDir: string;
  /** Where the cube appears, without a trailing slash (default /chunks). */
  cubePath?: string;
  onError?: (err: unknown) => void;
}

export interface SiteServer {
  readonly server: Server;
  /** Starts listening on 127.0.0.1 unless told otherwise; resolves to the port. */
  listen(port?: number, host?: string): Promise<number>;
  close(): Promise<void>;
}

export function createSiteServer(o: SiteServerOptions): SiteServer {
  const cubePath = o.cubePath ?? '/chunks';
  const errors = o.onError ? { onError: o.onError } : {};
  const client = createStaticHandler({ root: o.clientDir, ...errors });
  const cube = createStaticHandler({ root: o.cubeDir, ...errors });
  const server = createServer((req, res) => {
    const url = req.url ?? '/';
    if (url === cubePath || url.startsWith(`${cubePath}/`) || url.startsWith(`${cubePath}?`)) {
      req.url = url.slice(cubePath.length) || '/';
      cube(req, res);
    } else {
      if (url === '/' || url.startsWith('/?')) req.url = `/demo.html${url.slice(1)}`;
      client(req, res);
    }
  });
  return {
    server,
    listen(port = 0, host = '127.0.0.1') {
      return new Promise<number>((resolve, reject) => {
        server.once('error', reject);
        server.listen(port, host, () => {
          server.off('error', reject);
          resolve((server.address() as AddressInfo).port);
        });
      });
    },
    close() {
      return new Promise<void>((resolve) => {
        server.closeAllConnections();
        server.close(() => resolve());
      });
    },
  };
}
