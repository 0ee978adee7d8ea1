// Answers one request: method, path, file, representation (encoding), conditionals, range,
// then the body from memory or from the open file. Every rule in one readable order.
import type { IncomingMessage, ServerResponse } from 'node:http';
import { open, type FileHandle } from 'node:fs/promises';
import { pipeline } from 'node:stream/promises';
import { siblingCodings } from './accept-encoding.js';
import { parseRange } from './byte-range.js';
import type { CachePolicy } from './cache-control.js';
import { chooseFile, type Choice } from './choose-file.js';
import { contentTypeFor } from './content-types.js';
import type { Content, ContentCache } from './content-cache.js';
import { ALLOWED_METHODS, ALLOWED_REQUEST_HEADERS, EXPOSED_HEADERS, PREFLIGHT_MAX_AGE_S, type CorsPolicy } from './cors.js';
import { sameFile } from './file-version.js';
import type { LookupCache } from './lookup-cache.js';
import { isNotModified, rangeApplies } from './preconditions.js';
import { parseTargetPath, pathForSegments } from './url-path.js';

export interface HandlerConfig {
  cors: CorsPolicy;
  cachePolicy: CachePolicy;
  contents: ContentCache;
  lookups: LookupCache;
  onError: (err: unknown) => void;
}

type Headers = Record<string, string | number>;
type FileChoice = Extract<Choice, { kind: 'file' }>;

const STATUS_TEXT: Readonly<Record<number, string>> = {
  400: 'bad request',
  404: 'not found',
  405: 'method not allowed',
  416: 'range not satisfiable',
  500: 'internal server error',
};

function addVary(headers: Headers, field: string): void {
  headers.vary = headers.vary === undefined ? field : `${headers.vary}, ${field}`;
}

function sendText(req: IncomingMessage, res: ServerResponse, status: number, headers: Headers): void {
  const body = `${status} ${STATUS_TEXT[status] ?? ''}\n`;
  res.writeHead(status, {
    ...headers,
    'content-type': 'text/plain; charset=utf-8',
    'content-length': Buffer.byteLength(body),
    'cache-control': 'no-cache',
  });
  res.end(req.method === 'HEAD' ? undefined : body);
}

/** Headers every response carries: nosniff, and CORS when the origin is allowed. */
function baseHeaders(config: HandlerConfig, req: IncomingMessage): Headers {
  const headers: Headers = { 'x-content-type-options': 'nosniff' };
  if (!config.cors.enabled) return headers;
  const origin = req.headers.origin;
  const allowed = config.cors.allowOrigin(origin);
  if (allowed !== undefined) {
    headers['access-control-allow-origin'] = allowed;
    headers['access-control-expose-headers'] = EXPOSED_HEADERS;
  }
  if (config.cors.variesByOrigin) addVary(headers, 'Origin');
  return headers;
}

function allowHeader(config: HandlerConfig): string {
  return config.cors.enabled ? `${ALLOWED_METHODS}, OPTIONS` : ALLOWED_METHODS;
}

function single(value: string | string[] | undefined): string | undefined {
  return Array.isArray(value) ? value[0] : value;
}

export function createRequestHandler(config: HandlerConfig): (req: IncomingMessage, res: ServerResponse) => void {
  return (req, res) => {
    handle(config, req, res).catch((err: unknown) => {
      config.onError(err);
      // With the CORS headers: a map on another origin then reads the 500 and retries, where
      // without them it saw an opaque network failure.
      if (!res.headersSent) sendText(req, res, 500, baseHeaders(config, req));
      else res.destroy();
    });
  };
}

async function handle(config: HandlerConfig, req: IncomingMessage, res: ServerResponse): Promise<void> {
  const headers = baseHeaders(config, req);
  const method = req.method ?? '';
  if (method === 'OPTIONS' && config.cors.enabled) {
    // A preflight: say what a cross-origin GET may carry. Disallowed origins get no grant.
    headers.allow = allowHeader(config);
    if (headers['access-control-allow-origin'] !== undefined) {
      headers['access-control-allow-methods'] = ALLOWED_METHODS;
      headers['access-control-allow-headers'] = ALLOWED_REQUEST_HEADERS;
      headers['access-control-max-age'] = PREFLIGHT_MAX_AGE_S;
    }
    delete headers['access-control-expose-headers'];
    res.writeHead(204, headers);
    res.end();
    return;
  }
  if (method !== 'GET' && method !== 'HEAD') {
    sendText(req, res, 405, { ...headers, allow: allowHeader(config) });
    return;
  }
  const target = parseTargetPath(req.url ?? '');
  if (!target.ok) {
    sendText(req, res, target.status, headers);
    return;
  }
  // Ranges address the identity bytes, so a Range request never gets a compressed sibling.
  const codings = req.headers.range !== undefined ? [] : siblingCodings(req.headers['accept-encoding']);
  // A second attempt only when the file chosen was replaced or removed since it was checked.
  for (let attempt = 1; ; attempt++) {
    const choice = await chooseFile(config.lookups, target.segments, target.trailingSlash, codings);
    if (choice.kind === 'add-slash') {
      // As every static server does, so that relative links in its index.html resolve.
      res.writeHead(301, { ...headers, location: pathForSegments(target.segments, true) + target.query, 'content-length': 0 });
      res.end();
      return;
    }
    if (choice.kind === 'missing') {
      sendText(req, res, 404, headers);
      return;
    }
    if (await serveFile(config, req, res, headers, choice)) return;
    config.lookups.forget(choice.fileSegments); // look again from scratch
    if (attempt === 2) throw new Error(`${choice.file.realPath} keeps changing while it is opened`);
  }
}

const GONE = new Set(['ENOENT', 'ENOTDIR', 'ELOOP']);

/**
 * Sends the chosen file, from memory or from disk. False, with nothing sent, when the file
 * at its real path is gone or is no longer the one that was checked to lie inside the root.
 */
async function serveFile(config: HandlerConfig, req: IncomingMessage, res: ServerResponse, headers: Headers, choice: FileChoice): Promise<boolean> {
  const { file, coding, name } = choice;
  const wantsBody = req.method === 'GET';
  let content: Content | undefined = config.contents.peek(file.realPath, file.stats);
  let handle: FileHandle | undefined;
  if (!content || (!content.bytes && wantsBody)) {
    try {
      handle = await open(file.realPath, 'r');
    } catch (err) {
      // A remembered path may be gone by now: like a replaced file, it is looked up afresh.
      if (GONE.has((err as NodeJS.ErrnoException).code ?? '')) return false;
      throw err;
    }
    try {
      const stats = await handle.stat();
      // A path checked earlier may lead elsewhere now (a rename, a symlink swapped in along
      // it); only the very file that was checked may be read.
      if (!sameFile(stats, file.stats)) {
        await handle.close();
        return false;
      }
      content = config.contents.peek(file.realPath, stats) ?? (await config.contents.load(file.realPath, handle, stats));
    } catch (err) {
      await handle.close();
      throw err;
    }
    if (content.bytes) {
      await handle.close();
      handle = undefined;
    }
  }

  try {
    addVary(headers, 'Accept-Encoding');
    headers['cache-control'] = config.cachePolicy.headerFor(name);
    headers.etag = content.etag;
    headers['last-modified'] = content.lastModified;
    headers['accept-ranges'] = 'bytes';
    if (isNotModified(req.headers['if-none-match'], req.headers['if-modified-since'], content)) {
      res.writeHead(304, headers);
      res.end();
      return true;
    }
    headers['content-type'] = contentTypeFor(name);
    if (coding !== 'identity') headers['content-encoding'] = coding;

    let start = 0;
    let end = content.size - 1;
    let status = 200;
    const rangeHeader = req.headers.range;
    if (rangeHeader !== undefined && rangeApplies(single(req.headers['if-range']), content)) {
      const range = parseRange(rangeHeader, content.size);
      if (range.kind === 'unsatisfiable') {
        sendText(req, res, 416, { ...headers, 'content-range': `bytes */${content.size}` });
        return true;
      }
      if (range.kind === 'range') {
        ({ start, end } = range);
        status = 206;
        headers['content-range'] = `bytes ${start}-${end}/${content.size}`;
      }
    }
    headers['content-length'] = Math.max(0, end - start + 1);
    res.writeHead(status, headers);
    if (!wantsBody || end < start) {
      res.end();
      return true;
    }
    if (content.bytes) {
      res.end(status === 200 ? content.bytes : content.bytes.subarray(start, end + 1));
      return true;
    }
    const stream = handle!.createReadStream({ start, end, autoClose: true });
    handle = undefined; // the stream closes it now
    await pipeline(stream, res).catch((err: unknown) => {
      // A client that hangs up mid-file is normal; only a failing read is worth reporting.
      if (!res.destroyed || (err as { code?: string }).code !== 'ERR_STREAM_PREMATURE_CLOSE') throw err;
    });
    return true;
  } finally {
    await handle?.close();
  }
}
