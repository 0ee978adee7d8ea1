// fetch with retries: server errors (5xx), network failures, 408 (Request Timeout) and 429 (Too
// Many Requests: a CDN's answer to a burst) are retried with exponential backoff, since they are
// usually passing; other client errors (4xx) are not, they will not change. A server that says
// when to come back (Retry-After) is not asked sooner: asking a CDN that rate-limits the map
// sooner only prolongs the limit.
import { gunzipIfNeeded } from './gunzip.js';
import type { HeadStart, HeadStartResult } from './head-start.js';

export interface RetryOptions {
  /** Retries after the first attempt. */
  retries: number;
  /** Wait before the first retry; doubled for each next one. */
  backoffMs: number;
  maxBackoffMs: number;
  /** Told the URL of every body received whole (the worker lists them for offline caching; the scheduler frees the request's place). */
  onLoaded?: (url: string) => void;
  /** Bodies fetched elsewhere for this worker (head-start.ts): a URL among them is not asked for again. */
  headStart?: Pick<HeadStart, 'take' | 'giveBack'>;
}

export type FetchFailureKind = 'http' | 'network' | 'abort';

/** A failure that will not change, so it is not asked again: a client error (4xx) other than 408 and 429, which pass. */
export const isLasting = (status: number): boolean => status < 500 && status !== 408 && status !== 429;

/**
 * A failure the network's return may mend: a network failure, or a passing HTTP status whose
 * retries ran out. Not a lasting 4xx, a body that does not read, or an abort.
 */
export const mayPass = (err: unknown): boolean => err instanceof FetchFailure && (err.kind === 'network' || (err.kind === 'http' && err.status !== undefined && !isLasting(err.status)));

/**
 * The longest a Retry-After is followed; a longer one waits this long. A chunk asked for again
 * minutes later would come to a view long since left (a request no longer needed is aborted,
 * its wait too).
 */
export const RETRY_AFTER_MAX_MS = 60_000;

/**
 * The wait a response's Retry-After asks for, in ms from `now` (ms since the epoch), at most
 * RETRY_AFTER_MAX_MS: delay seconds or an HTTP date (RFC 9110 §10.2.3); undefined when it has
 * none, or none that reads. A cross-origin host must list the header in
 * Access-Control-Expose-Headers for the map to see it.
 */
export function retryAfterMs(res: Response, now: number): number | undefined {
  const v = res.headers.get('Retry-After')?.trim();
  if (!v) return undefined;
  if (/^\d+$/.test(v)) return Math.min(RETRY_AFTER_MAX_MS, Number(v) * 1000);
  // Only an IMF-fixdate, as servers send it: Date.parse reads much else ("1.5", "soon 2030").
  if (!/^[A-Z][a-z]{2}, \d{2} [A-Z][a-z]{2} \d{4} \d{2}:\d{2}:\d{2} GMT$/.test(v)) return undefined;
  const at = Date.parse(v);
  return Number.isNaN(at) ? undefined : Math.min(RETRY_AFTER_MAX_MS, Math.max(0, at - now));
}

export class FetchFailure extends Error {
  constructor(
    message: string,
    readonly kind: FetchFailureKind,
    readonly url: string,
    readonly status?: number,
    readonly attempts = 1,
    /** A passing failure's Retry-After, ms from when it came (retryAfterMs). */
    readonly retryAfterMs?: number,
  ) {
    super(message);
    this.name = 'FetchFailure';
  }
}

function sleep(ms: number, signal?: AbortSignal): Promise<void> {
  return new Promise((resolve, reject) => {
    if (signal?.aborted) return reject(new FetchFailure('aborted', 'abort', ''));
    const t = setTimeout(() => {
      signal?.removeEventListener('abort', onAbort);
      resolve();
    }, ms);
    const onAbort = (): void => {
      clearTimeout(t);
      reject(new FetchFailure('aborted', 'abort', ''));
    };
    signal?.addEventListener('abort', onAbort, { once: true });
  });
}

/** `p`, or a FetchFailure of kind 'abort' as soon as `signal` aborts. */
function untilAborted<T>(p: Promise<T>, url: string, signal?: AbortSignal): Promise<T> {
  if (!signal) return p;
  const aborted = (): FetchFailure => new FetchFailure('aborted', 'abort', url);
  if (signal.aborted) return Promise.reject(aborted());
  return new Promise<T>((resolve, reject) => {
    const onAbort = (): void => reject(aborted());
    signal.addEventListener('abort', onAbort, { once: true });
    void p.then((v) => {
      signal.removeEventListener('abort', onAbort);
      resolve(v);
    });
  });
}

const isAbort = (err: unknown): boolean => err instanceof Error && err.name === 'AbortError';

const httpFailure = (url: string, status: number, attempts = 1, retryAfter?: number): FetchFailure => new FetchFailure(`HTTP ${status} for ${url}`, 'http', url, status, attempts, retryAfter);

/** The body of `url` as bytes; throws FetchFailure. */
export async function fetchBytes(url: string, opts: RetryOptions, signal?: AbortSignal): Promise<ArrayBuffer> {
  const early = opts.headStart?.take(url);
  if (early) {
    let result: HeadStartResult;
    try {
      result = await untilAborted(early, url, signal);
    } catch (err) {
      // Still coming: a later request for the URL waits for it, rather than asking again.
      opts.headStart?.giveBack(url, early);
      throw err;
    }
    if (typeof result === 'number') throw httpFailure(url, result);
    if (result instanceof ArrayBuffer) {
      opts.onLoaded?.(url);
      return result;
    }
    if (result) await sleepOrAbort(result.retryAt - Date.now(), url, 0, signal);
  }
  let attempt = 0;
  for (;;) {
    attempt++;
    let failure: FetchFailure;
    try {
      const res = await fetch(url, signal ? { signal } : {});
      if (res.ok) {
        const body = await res.arrayBuffer();
        opts.onLoaded?.(url);
        return body;
      }
      // Drain nothing: the body of an error is not needed; cancel it to free the connection.
      void res.body?.cancel().catch(() => undefined);
      if (isLasting(res.status)) throw httpFailure(url, res.status, attempt);
      failure = httpFailure(url, res.status, attempt, retryAfterMs(res, Date.now()));
    } catch (err) {
      if (err instanceof FetchFailure) throw err;
      if (isAbort(err) || signal?.aborted) throw new FetchFailure('aborted', 'abort', url, undefined, attempt);
      failure = new FetchFailure(`network error for ${url}: ${(err as Error).message}`, 'network', url, undefined, attempt);
    }
    if (attempt > opts.retries) throw failure;
    // The backoff, or longer where the server asked for it.
    const backoff = Math.min(opts.maxBackoffMs, opts.backoffMs * 2 ** (attempt - 1));
    await sleepOrAbort(Math.max(backoff, failure.retryAfterMs ?? 0), url, attempt, signal);
  }
}

/** Waits `ms` (none if 0 or less); an abort meanwhile is a FetchFailure of kind 'abort' after `attempts`. */
async function sleepOrAbort(ms: number, url: string, attempts: number, signal?: AbortSignal): Promise<void> {
  if (ms <= 0) return;
  try {
    await sleep(ms, signal);
  } catch {
    throw new FetchFailure('aborted', 'abort', url, undefined, attempts);
  }
}

/** The body of `url` as JSON (a body that is not JSON is not retried). */
export async function fetchJson(url: string, opts: RetryOptions, signal?: AbortSignal): Promise<unknown> {
  return jsonOf(await fetchBytes(url, opts, signal));
}

/** A body as JSON, gunzipped first when it is still gzip. */
async function jsonOf(body: ArrayBuffer): Promise<unknown> {
  return JSON.parse(new TextDecoder().decode(await gunzipIfNeeded(body))) as unknown;
}
