// Runs nginx with server/nginx.conf.template filled in, for the nginx test and the serving
// benchmark: a private runtime directory, a free loopback port, daemon off, stopped by us.
import { spawn } from 'node:child_process';
import { chmodSync, existsSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { createServer, connect } from 'node:net';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

export const NGINX_BIN = '/usr/sbin/nginx';
// Compiled to dist/server/, the template stays in server/.
// Beside this file when run from source; from dist/server, the source copy two levels up.
const here = path.dirname(fileURLToPath(import.meta.url));
export const TEMPLATE_PATH = [path.join(here, 'nginx.conf.template'), path.resolve(here, '../../server/nginx.conf.template')].find((p) => existsSync(p)) ?? path.join(here, 'nginx.conf.template');

export interface TemplateValues {
  listen: string;
  root: string;
  runtimeDir: string;
}

export function fillTemplate(template: string, v: TemplateValues): string {
  const values: Record<string, string> = { LISTEN: v.listen, ROOT: v.root, RUNTIME_DIR: v.runtimeDir };
  return template.replace(/\{\{([A-Z_]+)\}\}/g, (whole, name: string) => {
    const value = values[name];
    if (value === undefined) throw new Error(`nginx template: unknown placeholder ${whole}`);
    return value;
  });
}

export interface RunningNginx {
  port: number;
  url: string;
  configPath: string;
  stop(): Promise<void>;
}

/** A port on 127.0.0.1 that nothing listens on (taken, then given back). */
export function freePort(): Promise<number> {
  return new Promise((resolve, reject) => {
    const probe = createServer();
    probe.once('error', reject);
    probe.listen(0, '127.0.0.1', () => {
      const address = probe.address();
      probe.close(() => (address && typeof address === 'object' ? resolve(address.port) : reject(new Error('no port'))));
    });
  });
}

/** True when something accepts connections on 127.0.0.1:port. */
export function accepts(port: number): Promise<boolean> {
  return new Promise((resolve) => {
    const socket = connect({ host: '127.0.0.1', port });
    socket.once('connect', () => {
      socket.destroy();
      resolve(true);
    });
    socket.once('error', () => resolve(false));
  });
}

const sleep = (ms: number): Promise<void> => new Promise((r) => setTimeout(r, ms));

/**
 * Starts nginx serving `root`. `adjust` may edit the filled-in config (the benchmark pins one
 * worker). Rejects with nginx's own message if it does not come up within a few seconds.
 */
export async function startNginx(root: string, adjust: (config: string) => string = (c) => c): Promise<RunningNginx> {
  const runtimeDir = mkdtempSync(path.join(tmpdir(), 'ssc-nginx-'));
  // Workers run as an unprivileged user when nginx starts as root.
  chmodSync(runtimeDir, 0o755);
  const port = await freePort();
  const configPath = path.join(runtimeDir, 'nginx.conf');
  const config = adjust(fillTemplate(readFileSync(TEMPLATE_PATH, 'utf8'), { listen: `127.0.0.1:${port}`, root, runtimeDir }));
  writeFileSync(configPath, config);

  const child = spawn(NGINX_BIN, ['-p', runtimeDir, '-c', configPath, '-g', 'daemon off;'], { stdio: ['ignore', 'ignore', 'pipe'] });
  let stderr = '';
  child.stderr.setEncoding('utf8').on('data', (s: string) => (stderr += s));
  const exited = new Promise<void>((resolve) => child.once('exit', () => resolve()));
  let running = true;
  void exited.then(() => (running = false));

  const cleanup = (): void => rmSync(runtimeDir, { recursive: true, force: true });
  const stop = async (): Promise<void> => {
    if (running) {
      child.kill('SIGTERM');
      await exited;
    }
    cleanup();
  };

  for (let i = 0; i < 100 && running; i++) {
    if (await accepts(port)) return { port, url: `http://127.0.0.1:${port}/`, configPath, stop };
    await sleep(50);
  }
  const log = existsSync(path.join(runtimeDir, 'error.log')) ? readFileSync(path.join(runtimeDir, 'error.log'), 'utf8') : '';
  await stop();
  throw new Error(`nginx did not start: ${(stderr + log).trim() || 'no message'}`);
}
