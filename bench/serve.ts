// npm run bench:serve [-- runs=N seconds=S]: requests per second and p99 latency of `ssc serve`,
// of sirv (the library issue 10 weighs against it, bench/sirv-server.ts) and of nginx
// (docs/deploy.md's config, one worker like our one process) serving the same files on
// loopback: index.json and a ~256 KiB chunk, at 1, 16 and 64 connections, asking with a
// browser's Accept-Encoding. Every run is bounded in time and in requests; medians of the runs
// are printed with throughput ratios to nginx. Without nginx, the node servers are measured alone.
import autocannon from 'autocannon';
import { spawn } from 'node:child_process';
import { createHash } from 'node:crypto';
import { chmodSync, existsSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { brotliCompressSync, gzipSync } from 'node:zlib';
import { hashName } from '../preprocess/ssc/build-cube.js';
import { NGINX_BIN, startNginx } from '../server/nginx-process.js';
import { median, root as repoRoot } from './datasets.js';

const args = process.argv.slice(2);
const option = (name: string, fallback: number): number => Number(args.find((a) => a.startsWith(`${name}=`))?.slice(name.length + 1) ?? fallback);
const RUNS = option('runs', 5);
const SECONDS = option('seconds', 2);
const MAX_REQUESTS = 300_000; // per run: the count bound beside the time bound
const CONNECTIONS = [1, 16, 64];
const HEADERS = { 'accept-encoding': 'gzip, deflate, br, zstd' };

interface Target {
  name: string;
  url: string;
  stop(): Promise<void>;
}

interface Sample {
  rps: number;
  p99ms: number;
}


/** A map directory like the preprocessing writes: content-hashed names, .br/.gz siblings. */
function writeFiles(dir: string): { index: string; chunk: string; sizes: string } {
  const put = (name: string, bytes: Buffer): Record<string, number> => {
    const br = brotliCompressSync(bytes);
    const gz = gzipSync(bytes);
    writeFileSync(path.join(dir, name), bytes);
    writeFileSync(path.join(dir, name + '.br'), br);
    writeFileSync(path.join(dir, name + '.gz'), gz);
    return { identity: bytes.length, br: br.length, gz: gz.length };
  };
  // Chunk: float32 coordinates scattered over a few km, which compress about as little as
  // a real chunk's vertices do.
  const floats = new Float32Array((256 * 1024) / 4);
  let x = 2463534242; // xorshift32: deterministic, and random enough for compressors
  for (let i = 0; i < floats.length; i++) {
    x ^= x << 13;
    x ^= x >>> 17;
    x ^= x << 5;
    floats[i] = 190_000 + ((x >>> 0) / 2 ** 32) * 5000;
  }
  const chunkBytes = Buffer.from(floats.buffer);
  const chunk = hashName('c', chunkBytes, 'bin');
  const leaves = Array.from({ length: 150 }, (_, i) => ({ bbox: [i, i, 0, i + 1, i + 1, 1], file: chunk, bytes: chunkBytes.length, triangles: 9000 + i, sha256: createHash('sha256').update(String(i)).digest('hex') }));
  const index = Buffer.from(JSON.stringify({ format: 'ssc-index', version: 1, root: { bbox: [0, 0, 0, 150, 150, 1], children: leaves } }));
  const s1 = put('index.json', index);
  const s2 = put(chunk, chunkBytes);
  const kib = (n: number | undefined): string => `${((n ?? 0) / 1024).toFixed(1)} KiB`;
  const sizes = `index.json ${kib(s1.identity)} (br ${kib(s1.br)}), ${chunk} ${kib(s2.identity)} (br ${kib(s2.br)})`;
  return { index: 'index.json', chunk, sizes };
}

/**
 * A node server in its own process, as `ssc serve` runs in use (and off the benchmark's event
 * loop); it prints "at <url>" once listening.
 */
function startNode(name: string, args: string[]): Promise<Target> {
  const child = spawn(process.execPath, args, { stdio: ['ignore', 'pipe', 'inherit'] });
  const exited = new Promise<void>((resolve) => child.once('exit', () => resolve()));
  return new Promise((resolve, reject) => {
    let out = '';
    child.stdout.setEncoding('utf8').on('data', (s: string) => {
      out += s;
      const m = /at (http:\/\/\S+\/)/.exec(out);
      const stop = async (): Promise<void> => {
        child.kill('SIGTERM');
        await exited;
      };
      if (m) resolve({ name, url: m[1]!, stop });
    });
    void exited.then(() => reject(new Error(`${name} exited: ${out}`)));
  });
}

async function measure(url: string, connections: number, seconds: number): Promise<Sample> {
  const r = await autocannon({ url, connections, duration: seconds, maxOverallRequests: MAX_REQUESTS, headers: HEADERS, timeout: 10 });
  if (r.errors > 0 || r.non2xx > 0) throw new Error(`${url} at ${connections} connections: ${r.errors} errors, ${r.non2xx} non-2xx responses`);
  return { rps: r.requests.total / r.duration, p99ms: r.latency.p99 };
}

const dir = mkdtempSync(path.join(tmpdir(), 'ssc-bench-serve-'));
chmodSync(dir, 0o755); // nginx's workers run as another user when started as root
const targets: Target[] = [];
try {
  const files = writeFiles(dir);
  targets.push(await startNode('ours', [path.join(repoRoot, 'bin/ssc.js'), 'serve', dir, '--port', '0']));
  targets.push(await startNode('sirv', [fileURLToPath(new URL('./sirv-server.js', import.meta.url)), dir]));
  if (existsSync(NGINX_BIN)) {
    const nginx = await startNginx(dir, (config) => config.replace('worker_processes auto;', 'worker_processes 1;'));
    targets.push({ name: 'nginx', url: nginx.url, stop: () => nginx.stop() });
  } else {
    console.log(`${NGINX_BIN} not found (apt-get install nginx): measuring the node servers alone`);
  }
  console.log(`bench:serve, node ${process.version}, ${RUNS} runs of ${SECONDS} s (at most ${MAX_REQUESTS} requests) per case, medians`);
  console.log(`files: ${files.sizes}; Accept-Encoding: ${HEADERS['accept-encoding']}`);

  // Warm up both servers (JIT, ETag hashing, page cache) before anything is recorded.
  for (const t of targets) for (const f of [files.index, files.chunk]) await measure(t.url + f, 16, 1);

  const samples = new Map<string, Sample[]>();
  for (let run = 0; run < RUNS; run++) {
    for (const file of [files.index, files.chunk]) {
      for (const connections of CONNECTIONS) {
        // Interleaved, so drift in the machine's state affects every server alike.
        for (const t of targets) {
          const key = `${t.name}|${file}|${connections}`;
          samples.set(key, [...(samples.get(key) ?? []), await measure(t.url + file, connections, SECONDS)]);
        }
      }
    }
  }

  const col = (s: string, w: number): string => s.padStart(w);
  const nginx = targets.find((t) => t.name === 'nginx');
  const others = targets.filter((t) => t !== nginx);
  const header = ['file', 'conns', ...targets.flatMap((t) => [`${t.name} req/s`, `${t.name} p99 ms`]), ...(nginx ? others.map((t) => `${t.name}/nginx`) : [])];
  const widths = header.map((h, i) => Math.max(h.length, i === 0 ? 22 : 8));
  console.log('\n' + header.map((h, i) => (i === 0 ? h.padEnd(widths[i]!) : col(h, widths[i]!))).join('  '));
  for (const file of [files.index, files.chunk]) {
    for (const connections of CONNECTIONS) {
      const cells = [file.padEnd(widths[0]!), col(String(connections), widths[1]!)];
      const rps = new Map<Target, number>();
      targets.forEach((t, i) => {
        const s = samples.get(`${t.name}|${file}|${connections}`)!;
        const r = median(s.map((x) => x.rps));
        rps.set(t, r);
        // autocannon measures latency in whole milliseconds.
        const p99 = median(s.map((x) => x.p99ms));
        cells.push(col(r.toFixed(0), widths[2 + 2 * i]!), col(p99 < 1 ? '<1' : p99.toFixed(0), widths[3 + 2 * i]!));
      });
      if (nginx) {
        others.forEach((t, i) => cells.push(col((rps.get(t)! / rps.get(nginx)!).toFixed(2), widths[2 + 2 * targets.length + i]!)));
      }
      console.log(cells.join('  '));
    }
  }
} finally {
  for (const t of targets) await t.stop();
  rmSync(dir, { recursive: true, force: true });
}
