// `ssc serve` from the command line: it prints where it listens, serves the directory with
// the CORS origins given, stops cleanly on SIGTERM, and explains bad arguments.
import assert from 'node:assert/strict';
import { spawn } from 'node:child_process';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { runSsc, sscNodeArgs } from '../../testing/run-ssc.js';
import { makeFixture, type Fixture } from './fixture.js';
import { request } from './http-client.js';


let fx: Fixture;
before(() => {
  fx = makeFixture();
});
after(() => fx.remove());

test('serves a directory until SIGTERM', async () => {
  const child = spawn(process.execPath, sscNodeArgs(['serve', fx.root, '--port', '0', '--cors', 'https://a.example,https://b.example']), { stdio: ['ignore', 'pipe', 'pipe'] });
  let stdout = '';
  let stderr = '';
  child.stderr.setEncoding('utf8').on('data', (s: string) => (stderr += s));
  const exited = new Promise<number | null>((resolve) => child.once('exit', (code) => resolve(code)));
  const url = await new Promise<string>((resolve, reject) => {
    child.stdout.setEncoding('utf8').on('data', (s: string) => {
      stdout += s;
      const m = /at (http:\/\/127\.0\.0\.1:\d+\/)/.exec(stdout);
      if (m) resolve(m[1]!);
    });
    void exited.then((code) => reject(new Error(`ssc serve exited (${code}): ${stderr}`)));
  });
  try {
    const r = await request(url, '/index.json', { headers: { origin: 'https://b.example', 'accept-encoding': 'br' } });
    assert.equal(r.status, 200);
    assert.equal(r.headers['content-encoding'], 'br');
    assert.equal(r.headers['access-control-allow-origin'], 'https://b.example');
  } finally {
    child.kill('SIGTERM');
  }
  assert.equal(await exited, 0, stderr);
});

test('--help shows the options', () => {
  const r = runSsc(['serve', '--help']);
  assert.equal(r.code, 0);
  for (const option of ['--port', '--host', '--cors']) assert.ok(r.stdout.includes(option), option);
});

test('bad arguments are usage errors (exit 2) that say what is wrong', () => {
  const cases: [string[], RegExp][] = [
    [['serve'], /give one directory/],
    [['serve', fx.root, '--port', 'eighty'], /--port must be an integer/],
    [['serve', fx.root, '--port', '70000'], /--port must be at most 65535/],
    [['serve', fx.root, '--cors', 'https://a.example/app'], /--cors: not an origin/],
    [['serve', fx.root, '--cors', ','], /--cors needs/],
  ];
  for (const [args, message] of cases) {
    const r = runSsc(args);
    assert.equal(r.code, 2, args.join(' '));
    assert.match(r.stderr, message, args.join(' '));
  }
});

test('a missing directory is an input error (exit 1)', () => {
  const r = runSsc(['serve', path.join(fx.dir, 'nope')]);
  assert.equal(r.code, 1);
  assert.match(r.stderr, /no such directory/);
});
