// A benchmark's site: the built client (dist/client) in a temporary folder, served by the
// project's static server on 127.0.0.1 while the benchmark runs, then closed and removed. The
// benchmark puts its cube in the folder (cube/), where the client's page finds it.
import { cp, mkdtemp, rm } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { createStaticServer } from '../server/static-server.js';
import { root } from './datasets.js';

export interface ClientSite {
  /** The folder served; the cube goes in its cube/. */
  dir: string;
  /** The server's base URL, ending in a slash. */
  url: string;
}

/** Runs `fn` with a served client site made under a name starting with `prefix`. */
export async function withClientSite<T>(prefix: string, fn: (site: ClientSite) => Promise<T>): Promise<T> {
  const dir = await mkdtemp(path.join(tmpdir(), prefix));
  try {
    await cp(path.join(root, 'dist/client'), dir, { recursive: true, filter: (src) => !src.includes(`${path.sep}src${path.sep}`) });
    const server = createStaticServer({ root: dir });
    await server.listen(0, '127.0.0.1');
    try {
      const url = server.url;
      if (url === null) throw new Error(`the static server for ${dir} has no address after listening`);
      return await fn({ dir, url });
    } finally {
      await server.close();
    }
  } finally {
    await rm(dir, { recursive: true, force: true });
  }
}
