// The head start on the first view: the map fetches the floor chunks its first view shows for
// the worker, while the worker's script still loads (on a slow network it comes a round trip and
// more after index.json, docs/CLIENT.md "Chunk loading"), and hands the bodies over. Both
// halves of the exchange are here: the map's (HeadStartFetches) and the worker's (HeadStart),
// which a request for one of those files waits on instead of asking the network again.
import { FetchFailure, fetchBytes, isLasting, type RetryOptions } from './fetch-retry.js';

/**
 * What became of the map's fetch of a file: its body; the status of a client error (4xx) that
 * will not change (isLasting), so the worker fails the file without asking again; or any other
 * failure (5xx, 408, 429, network, cancelled), which the worker's own request, with its retries,
 * takes over: at once (null), or not before `retryAt` (ms since the epoch, which the map and its
 * worker share) where the server's Retry-After said so.
 */
export type HeadStartResult = ArrayBuffer | number | { retryAt: number } | null;

/** The result the map posts for a failed fetch (HeadStartResult). */
export function failedResult(err: unknown, now: number): HeadStartResult {
  if (!(err instanceof FetchFailure)) return null;
  if (err.kind === 'http' && err.status !== undefined && isLasting(err.status)) return err.status;
  return err.retryAfterMs === undefined ? null : { retryAt: now + err.retryAfterMs };
}

/**
 * The map's half: each file fetched once, at once (the worker, which retries, fetches one that
 * fails other than with a lasting 4xx itself), each result posted to the worker as it comes;
 * `done` once every one has been posted.
 */
export class HeadStartFetches {
  private readonly controllers = new Map<string, AbortController>();

  constructor(urls: readonly string[], retry: RetryOptions, post: (url: string, result: HeadStartResult) => void, done: () => void) {
    const once = { ...retry, retries: 0 };
    for (const url of urls) {
      const controller = new AbortController();
      this.controllers.set(url, controller);
      fetchBytes(url, once, controller.signal).then(
        (body) => post(url, body),
        (err: unknown) => post(url, failedResult(err, Date.now())),
      ).finally(() => {
        this.controllers.delete(url);
        if (this.controllers.size === 0) done();
      });
    }
  }

  /** Some result has not been posted yet. */
  get pending(): boolean {
    return this.controllers.size > 0;
  }

  /** The worker left the file behind (its view moved on): its fetch stops. */
  cancel(url: string): void {
    this.controllers.get(url)?.abort();
  }

  /** The map was removed. */
  cancelAll(): void {
    for (const c of this.controllers.values()) c.abort();
  }
}

/**
 * The worker's half: the results of the map's fetches for it, by URL, until a request takes
 * them or the worker's view no longer needs them (keepOnly).
 */
export class HeadStart {
  /** By URL: the result to come, until a request takes it. */
  private readonly results = new Map<string, Promise<HeadStartResult>>();
  /** By URL: how to hand the result over, until it comes (taken or not). */
  private readonly settles = new Map<string, (result: HeadStartResult) => void>();

  /** The map is fetching these URLs. */
  expect(urls: readonly string[]): void {
    for (const url of urls) {
      if (this.results.has(url) || this.settles.has(url)) continue;
      this.results.set(url, new Promise<HeadStartResult>((resolve) => this.settles.set(url, resolve)));
    }
  }

  /** The result of the map's fetch of an expected URL came. */
  arrived(url: string, result: HeadStartResult): void {
    this.settles.get(url)?.(result);
    this.settles.delete(url);
  }

  /** The result of the map's fetch of `url`, once (a second request asks the network); undefined when it fetches none. */
  take(url: string): Promise<HeadStartResult> | undefined {
    const result = this.results.get(url);
    this.results.delete(url);
    return result;
  }

  /** Some result has not been taken yet: only then is there anything for keepOnly to let go. */
  get holding(): boolean {
    return this.results.size > 0;
  }

  /** Forgets the results not taken yet whose URL `keep` does not keep (the view that wanted them moved on). */
  keepOnly(keep: (url: string) => boolean): void {
    for (const url of [...this.results.keys()]) if (!keep(url)) this.results.delete(url);
  }

  /** A result taken by a request that was aborted before it came: the next request for the URL takes it. */
  giveBack(url: string, result: Promise<HeadStartResult>): void {
    if (!this.results.has(url)) this.results.set(url, result);
  }
}
