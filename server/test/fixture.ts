// A hand-made map directory for the server tests, with a secret beside it that must never be
// served. Contents are small and known, so every expectation is written out, not computed by
// the code under test.
import { brotliCompressSync, gzipSync } from 'node:zlib';
import { chmodSync, mkdirSync, mkdtempSync, renameSync, rmSync, symlinkSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';

export const SECRET = 'SECRET-OUTSIDE-THE-ROOT';
export const CORS_ORIGIN = 'https://map.example.org'; // the origin the nginx template allows
export const CHUNK = 'c-3fa9b2c1d4e5f607.bin'; // content-hashed, so immutable
export const SUB_INDEX = 's-0a1b2c3d4e5f6a7b.json'; // a content-hashed sub-index
export const CHUNK_SIZE = 300_000;

export interface Fixture {
  dir: string; // holds root/ and the secrets
  root: string;
  /** The bytes of each file under root, by URL path, siblings included. */
  files: Map<string, Buffer>;
  remove(): void;
}

function chunkBytes(): Buffer {
  // Deterministic, partly compressible, like float coordinates: a sawtooth with noise.
  const b = Buffer.alloc(CHUNK_SIZE);
  let x = 12345;
  for (let i = 0; i < b.length; i++) {
    x = (x * 1103515245 + 12345) & 0x7fffffff;
    b[i] = i % 4 === 3 ? x & 0xff : (i >> 6) & 0xff;
  }
  return b;
}

export function makeFixture(): Fixture {
  const dir = mkdtempSync(path.join(tmpdir(), 'ssc-serve-'));
  // nginx workers run as another user when the tests run as root: let them read.
  chmodSync(dir, 0o755);
  const root = path.join(dir, 'root');
  const files = new Map<string, Buffer>();
  const put = (urlPath: string, data: Buffer | string): Buffer => {
    const bytes = Buffer.isBuffer(data) ? data : Buffer.from(data);
    const file = path.join(root, ...urlPath.split('/'));
    mkdirSync(path.dirname(file), { recursive: true });
    writeFileSync(file, bytes);
    files.set(urlPath, bytes);
    return bytes;
  };
  const withSiblings = (urlPath: string, data: Buffer | string, which: ('br' | 'gz')[] = ['br', 'gz']): void => {
    const bytes = put(urlPath, data);
    if (which.includes('br')) put(urlPath + '.br', brotliCompressSync(bytes));
    if (which.includes('gz')) put(urlPath + '.gz', gzipSync(bytes));
  };

  mkdirSync(root, { recursive: true });
  writeFileSync(path.join(dir, 'secret.txt'), SECRET);
  mkdirSync(path.join(dir, 'outside'));
  writeFileSync(path.join(dir, 'outside', 'inner.json'), JSON.stringify({ secret: SECRET }));

  const index = JSON.stringify({ version: 1, chunks: Array.from({ length: 200 }, (_, i) => ({ id: i, file: CHUNK, box: [i, i, i + 1, i + 1] })) });
  withSiblings('/index.json', index);
  withSiblings('/meta.json', JSON.stringify({ name: 'fixture', crs: 'EPSG:28992', scale: [1000, 50000] }));
  withSiblings('/' + SUB_INDEX, JSON.stringify({ children: [1, 2, 3] }));
  withSiblings('/' + CHUNK, chunkBytes());
  withSiblings('/only-gzip.json', JSON.stringify({ only: 'gzip', pad: 'x'.repeat(500) }), ['gz']);
  withSiblings('/index.html', '<!doctype html><title>map</title><script src="app-5e6f7a8b.js"></script>\n');
  withSiblings('/app-5e6f7a8b.js', 'console.log("map");\n'.repeat(20));
  withSiblings('/style.css', 'body { margin: 0; }\n'.repeat(20));
  withSiblings('/module.wasm', Buffer.from([0x00, 0x61, 0x73, 0x6d, 0x01, 0x00, 0x00, 0x00]));
  withSiblings('/icon.svg', '<svg xmlns="http://www.w3.org/2000/svg"/>\n');
  withSiblings('/site.webmanifest', '{"name":"map"}\n');
  put('/logo.png', Buffer.from('89504e470d0a1a0a0000000d49484452', 'hex'));
  put('/notes.txt', 'plain text\n');
  put('/empty.json', '');
  put('/noext', 'no extension');
  put('/a file.json', '{"spaced":true}');
  put('/.hidden.json', JSON.stringify({ secret: SECRET }));
  put('/sub/index.html', '<p>sub</p>\n');
  put('/sub/data.json', '{"sub":1}');
  mkdirSync(path.join(root, 'empty-dir'));
  // Symlinks: two out of the root (refused) and one within it (fine for our server).
  symlinkSync('../secret.txt', path.join(root, 'link-out.txt'));
  symlinkSync('../outside', path.join(root, 'link-dir'));
  symlinkSync('index.json', path.join(root, 'link-in.json'));
  // A sibling that points out of the root must not be picked for the file it sits next to.
  put('/evil.json', '{"evil":false}');
  symlinkSync('../secret.txt', path.join(root, 'evil.json.br'));

  return { dir, root, files, remove: () => rmSync(dir, { recursive: true, force: true }) };
}

/** The bytes of one fixture file; throws for a name the fixture does not have. */
export function bytesOf(fx: Fixture, urlPath: string): Buffer {
  const b = fx.files.get(urlPath);
  if (!b) throw new Error(`no fixture file ${urlPath}`);
  return b;
}

/** Replaces `file` by a symlink to `target` in one step, as a deploy script would. */
export function swapForSymlink(file: string, target: string): void {
  const tmp = `${file}.swap-tmp`;
  symlinkSync(target, tmp);
  renameSync(tmp, file);
}

/** Writes a new file over `file` in one step, as the preprocessing does. */
export function replaceFile(file: string, text: string): void {
  writeFileSync(`${file}.tmp`, text);
  renameSync(`${file}.tmp`, file);
}
