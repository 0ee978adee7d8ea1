// ssc serve <dir> [--port N] [--host 127.0.0.1] [--cors <origins>]: the map directory over
// HTTP until Ctrl-C (or SIGTERM), then a graceful close.
import { statSync } from 'node:fs';
import { parseArgs } from 'node:util';
import { CorsConfigError, parseCorsOrigins, type CorsOrigins } from '../../server/cors.js';
import { createStaticServer } from '../../server/static-server.js';
import { InputError } from '../io/errors.js';
import { parseNumber, UsageError } from './args.js';

export const usage = `ssc serve <dir> [options]
  --port <n>          TCP port (default 8080; 0 picks a free one)
  --host <address>    address to listen on (default 127.0.0.1: this machine only)
  --cors <origins>    let pages on other sites read the map: * or a comma-separated list
                      of origins, e.g. https://maps.example.org,http://localhost:5173
  --revalidate-ms <n> how long a checked file may be answered from memory before it is
                      looked at again (default 100; 0 checks the disk on every request)
Serves the directory as the map client expects: content types, ETags, precompressed .br and
.gz siblings, ranges, a year of caching for content-hashed names and revalidation for the
rest. Nothing outside <dir> is served. Stop with Ctrl-C.`;

export async function run(argv: string[]): Promise<void> {
  const { values, positionals } = parseArgs({
    args: argv,
    allowPositionals: true,
    options: {
      port: { type: 'string' },
      host: { type: 'string' },
      cors: { type: 'string' },
      'revalidate-ms': { type: 'string' },
    },
  });
  if (positionals.length !== 1) throw new UsageError('give one directory to serve');
  const dir = positionals[0]!;
  const port = parseNumber(values.port ?? '8080', '--port', { min: 0, integer: true })!;
  if (port > 65535) throw new UsageError('--port must be at most 65535');
  const host = values.host ?? '127.0.0.1';
  const revalidateAfterMs = parseNumber(values['revalidate-ms'], '--revalidate-ms', { min: 0 });
  let cors: CorsOrigins | undefined;
  if (values.cors !== undefined) {
    cors = parseCorsOrigins(values.cors);
    if (cors !== '*' && cors.length === 0) throw new UsageError('--cors needs * or at least one origin');
  }

  let isDir: boolean;
  try {
    isDir = statSync(dir).isDirectory();
  } catch {
    throw new InputError('no such directory', { file: dir });
  }
  if (!isDir) throw new InputError('not a directory', { file: dir });

  let server;
  try {
    server = createStaticServer({ root: dir, ...(cors === undefined ? {} : { cors }), ...(revalidateAfterMs === undefined ? {} : { revalidateAfterMs }) });
  } catch (err) {
    if (err instanceof CorsConfigError) throw new UsageError(`--cors: ${err.message}`);
    throw err;
  }
  try {
    await server.listen(port, host);
  } catch (err) {
    const code = (err as NodeJS.ErrnoException).code;
    if (code === 'EADDRINUSE' || code === 'EACCES' || code === 'EADDRNOTAVAIL') {
      throw new InputError(`cannot listen on ${host}:${port} (${code})`);
    }
    throw err;
  }
  process.stdout.write(`serving ${dir} at ${server.url}${cors ? ` (CORS: ${cors === '*' ? '*' : cors.join(', ')})` : ''}\n`);

  const signal = await new Promise<NodeJS.Signals>((resolve) => {
    process.once('SIGINT', resolve);
    process.once('SIGTERM', resolve);
  });
  process.stdout.write(`${signal}: closing\n`);
  await server.close();
}
