// Malformed, slow, idle and impatient clients: each gets a 4xx or is cut off, and the server
// goes on answering everyone else. Timeouts are short here so the suite finishes quickly;
// nothing asserts how long anything took.
import assert from 'node:assert/strict';
import { truncateSync, writeFileSync } from 'node:fs';
import { connect } from 'node:net';
import path from 'node:path';
import { request as httpRequest } from 'node:http';
import { after, before, describe, it } from 'node:test';
import { CHUNK, makeFixture, type Fixture } from './fixture.js';
import { rawExchange, request, slowClient } from './http-client.js';
import { startOurs, type Started } from './start-server.js';

let fx: Fixture;
let ours: Started;
const BIG = 64 << 20; // far more than the socket buffers on both ends hold

before(async () => {
  fx = makeFixture();
  writeFileSync(path.join(fx.root, 'big.bin'), '');
  truncateSync(path.join(fx.root, 'big.bin'), BIG);
  ours = await startOurs({
    root: fx.root,
    headersTimeoutMs: 400,
    requestTimeoutMs: 400,
    keepAliveTimeoutMs: 200,
    stallTimeoutMs: 500,
    timeoutCheckIntervalMs: 50,
    maxCachedFileBytes: 0, // stream every file, to exercise aborted streams
  });
});
after(async () => {
  await ours.server.close();
  fx.remove();
});

const sleep = (ms: number): Promise<void> => new Promise((r) => setTimeout(r, ms));

function openConnections(): Promise<number> {
  return new Promise((resolve, reject) => ours.server.server.getConnections((err, n) => (err ? reject(err) : resolve(n))));
}

async function stillServes(): Promise<void> {
  const r = await request(ours.base, '/index.json');
  assert.equal(r.status, 200);
}

describe('malformed requests get a 4xx', () => {
  const malformed: [string, string][] = [
    ['not HTTP at all', 'GARBAGE\r\n\r\n'],
    ['a lowercase method', 'get /index.json HTTP/1.1\r\nHost: x\r\n\r\n'],
    ['an unknown method', 'BREW /index.json HTTP/1.1\r\nHost: x\r\n\r\n'],
    ['a space in the path', 'GET /in dex.json HTTP/1.1\r\nHost: x\r\n\r\n'],
    ['an unknown HTTP version', 'GET /index.json HTTP/9.9\r\nHost: x\r\n\r\n'],
    ['no Host in HTTP/1.1', 'GET /index.json HTTP/1.1\r\nConnection: close\r\n\r\n'],
    ['a header without a colon', 'GET /index.json HTTP/1.1\r\nHost: x\r\nBad Header\r\n\r\n'],
    ['a space in a header name', 'GET /index.json HTTP/1.1\r\nHost: x\r\nBad Header: y\r\n\r\n'],
    ['a NUL in a header', 'GET /index.json HTTP/1.1\r\nHost: x\r\nX-A: a\0b\r\n\r\n'],
    ['bare LF line ends', 'GET /index.json HTTP/1.1\nHost: x\n\n'],
    ['Content-Length with Transfer-Encoding', 'GET /index.json HTTP/1.1\r\nHost: x\r\nContent-Length: 5\r\nTransfer-Encoding: chunked\r\n\r\n'],
    ['two different Content-Lengths', 'GET /index.json HTTP/1.1\r\nHost: x\r\nContent-Length: 1\r\nContent-Length: 2\r\n\r\nab'],
    ['a broken percent escape', 'GET /%zz HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n'],
    ['invalid UTF-8 in the path', 'GET /%ff%fe.json HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n'],
    ['an encoded slash', 'GET /sub%2fdata.json HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n'],
    ['a target that is not a path', 'GET index.json HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n'],
  ];
  for (const [what, bytes] of malformed) {
    it(what, async () => {
      const r = await rawExchange(ours.port, bytes);
      assert.ok(r.status !== undefined && r.status >= 400 && r.status < 500, `status ${r.status}: ${r.text.slice(0, 80)}`);
      await stillServes();
    });
  }

  it('a request head over 16 KiB gets 431', async () => {
    const r = await rawExchange(ours.port, `GET /index.json HTTP/1.1\r\nHost: x\r\nX-Big: ${'a'.repeat(20_000)}\r\n\r\n`);
    assert.equal(r.status, 431);
    await stillServes();
  });

  it('CONNECT gets 405', async () => {
    const r = await rawExchange(ours.port, 'CONNECT example.org:443 HTTP/1.1\r\nHost: example.org:443\r\n\r\n');
    assert.equal(r.status, 405);
    await stillServes();
  });
});

describe('unusual but valid requests are served', () => {
  for (const [what, bytes] of [
    ['absolute-form', 'GET http://127.0.0.1/index.json HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n'],
    ['HTTP/1.0 without Host', 'GET /index.json HTTP/1.0\r\n\r\n'],
    ['an Upgrade we ignore', 'GET /index.json HTTP/1.1\r\nHost: x\r\nConnection: Upgrade, close\r\nUpgrade: websocket\r\n\r\n'],
    ['doubled slashes', 'GET //sub//data.json HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n'],
    ['a query string', 'GET /index.json?v=2 HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n'],
  ] as const) {
    it(what, async () => {
      assert.equal((await rawExchange(ours.port, bytes)).status, 200);
    });
  }
});

describe('slow and idle clients are cut off while others are served', () => {
  it('a slowloris client trickling its headers', async () => {
    // Ten clients each send a byte every 20 ms of a 100 KB head they would take 30 minutes
    // to finish; the server must close them long before, and serve others meanwhile.
    const slow = Array.from({ length: 10 }, () => slowClient(ours.port, 20));
    for (let i = 0; i < 5; i++) await stillServes();
    for (const s of await Promise.all(slow)) {
      assert.ok(s.bytesSent < 100_000, 'the server, not the client, ended it');
      assert.ok(s.status === undefined || s.status === 408, `status ${s.status}`);
    }
    await stillServes();
  });

  it('a client that connects and says nothing', async () => {
    const closed = await new Promise<boolean>((resolve) => {
      const socket = connect({ host: '127.0.0.1', port: ours.port });
      socket.on('error', () => undefined);
      // Read whatever comes (a 408, perhaps): a paused socket would never see the end.
      socket.resume();
      socket.on('close', () => resolve(true));
    });
    assert.ok(closed);
    await stillServes();
  });

  it('an idle keep-alive connection after a response', async () => {
    const socket = connect({ host: '127.0.0.1', port: ours.port });
    const text = await new Promise<string>((resolve) => {
      let received = '';
      socket.on('data', (c: Buffer) => (received += c.toString('latin1')));
      socket.on('error', () => undefined);
      socket.on('close', () => resolve(received));
      socket.write('GET /meta.json HTTP/1.1\r\nHost: x\r\n\r\n');
    });
    assert.match(text, /^HTTP\/1\.1 200 /);
    await stillServes();
  });

  it('a client that stops reading in the middle of a large file', async () => {
    const socket = connect({ host: '127.0.0.1', port: ours.port });
    let received = 0;
    socket.on('data', (c: Buffer) => (received += c.length));
    socket.on('error', () => undefined);
    const closed = new Promise<void>((resolve) => socket.on('close', () => resolve()));
    socket.write('GET /big.bin HTTP/1.1\r\nHost: x\r\n\r\n');
    socket.pause();
    await stillServes();
    // Wait (the test runner's timeout bounds this) until the server has let go of it...
    while ((await openConnections()) > 0) await sleep(50);
    // ...and the client, reading again, finds the response cut short.
    socket.resume();
    await closed;
    assert.ok(received < BIG, `received ${received} of ${BIG} bytes`);
    await stillServes();
  });

  it('a client that hangs up in the middle of a large file', async () => {
    await new Promise<void>((resolve, reject) => {
      const req = httpRequest({ host: '127.0.0.1', port: ours.port, path: '/' + CHUNK, agent: false }, (res) => {
        res.once('data', () => {
          req.destroy();
          resolve();
        });
      });
      req.on('error', (err: NodeJS.ErrnoException) => (err.code === 'ECONNRESET' ? undefined : reject(err)));
      req.end();
    });
    await stillServes();
    const whole = await request(ours.base, '/' + CHUNK);
    assert.equal(whole.body.length, Number(whole.headers['content-length']));
  });
});

it('reported no internal errors', () => assert.deepEqual(ours.errors, []));
