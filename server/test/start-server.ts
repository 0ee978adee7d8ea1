// Starts our server on 127.0.0.1, port 0, for one test file, and stops it afterwards.
import { after, before } from 'node:test';
import { createStaticServer, type StaticServer, type StaticServerOptions } from '../static-server.js';
import { makeFixture, type Fixture } from './fixture.js';

export interface Started {
  server: StaticServer;
  base: string;
  port: number;
  /** Failures the server reported (a 500 or a broken stream); a test run expects none. */
  errors: unknown[];
}

export async function startOurs(options: StaticServerOptions): Promise<Started> {
  const errors: unknown[] = [];
  const server = createStaticServer({ onError: (err) => errors.push(err), ...options });
  const address = await server.listen(0, '127.0.0.1');
  return { server, base: server.url!, port: address.port, errors };
}

/**
 * The usual setup of a test file: a fresh fixture folder served by our server for the whole
 * file, removed afterwards. The getters are valid once the file's tests run.
 */
export function serveFixture(options: Omit<StaticServerOptions, 'root'> = {}): { fx: () => Fixture; ours: () => Started } {
  let fx: Fixture | undefined;
  let ours: Started | undefined;
  before(async () => {
    fx = makeFixture();
    ours = await startOurs({ ...options, root: fx.root });
  });
  after(async () => {
    await ours?.server.close();
    fx?.remove();
  });
  return { fx: () => fx!, ours: () => ours! };
}
