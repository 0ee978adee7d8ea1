// A stand-in for the global fetch in unit tests: the test answers each request, at once or
// later (a request held open), and an abort signal rejects a pending request as fetch does.

/** A response; an Error for a network failure (fetch rejects); 'hold' to answer later. */
export type Answer = Response | Error | 'hold';

export interface FakeRequest {
  readonly url: string;
  readonly signal: AbortSignal | undefined;
  /** Answers a held request. */
  answer(a: Response | Error): void;
  /** Answered, failed or aborted. */
  readonly settled: boolean;
}

export interface FakeFetch {
  /** Every request in the order made. */
  readonly requests: FakeRequest[];
  /** Their URLs. */
  urls(): string[];
  /** Requests not settled yet, oldest first. */
  open(): FakeRequest[];
  /** The most requests ever open at once. */
  readonly maxOpen: number;
}

/** The fetch before any fake: what the end of every test puts back (two fakes in one test end first-in first-out). */
const realFetch = globalThis.fetch;

/**
 * Replaces globalThis.fetch until the test ends. `respond` gets the URL and how many times it
 * has been requested so far (1 for the first request).
 */
export function installFakeFetch(t: { after(fn: () => void): void }, respond: (url: string, attempt: number) => Answer): FakeFetch {
  const requests: (FakeRequest & { settled: boolean })[] = [];
  const attempts = new Map<string, number>();
  let maxOpen = 0;
  const fake = (input: string | URL | Request, init?: RequestInit): Promise<Response> => {
    const url = typeof input === 'string' ? input : input instanceof URL ? input.href : input.url;
    const signal = init?.signal ?? undefined;
    const attempt = (attempts.get(url) ?? 0) + 1;
    attempts.set(url, attempt);
    return new Promise<Response>((resolve, reject) => {
      const req = {
        url,
        signal,
        settled: false,
        answer(a: Response | Error): void {
          if (req.settled) throw new Error(`${url} was already answered or aborted`);
          req.settled = true;
          signal?.removeEventListener('abort', onAbort);
          if (a instanceof Error) reject(a);
          else resolve(a);
        },
      };
      const onAbort = (): void => {
        if (req.settled) return;
        req.settled = true;
        reject(abortReason(signal));
      };
      requests.push(req);
      if (signal?.aborted) return onAbort();
      signal?.addEventListener('abort', onAbort, { once: true });
      maxOpen = Math.max(maxOpen, requests.filter((r) => !r.settled).length);
      const a = respond(url, attempt);
      if (a !== 'hold') req.answer(a);
    });
  };
  globalThis.fetch = fake;
  t.after(() => {
    globalThis.fetch = realFetch;
  });
  return {
    requests,
    urls: () => requests.map((r) => r.url),
    open: () => requests.filter((r) => !r.settled),
    get maxOpen() {
      return maxOpen;
    },
  };
}

/** What fetch rejects with when its signal aborts: the signal's reason, an AbortError. */
function abortReason(signal: AbortSignal | undefined): unknown {
  return signal?.reason ?? new DOMException('This operation was aborted', 'AbortError');
}

/** A response with this status (and these headers) and no body. */
export const status = (code: number, headers: Record<string, string> = {}): Response => new Response(null, { status: code, headers });

/** A 200 response with a copy of these bytes (a copy: the reader may rewrite its buffer). */
export const body = (bytes: Uint8Array | string): Response => new Response(typeof bytes === 'string' ? bytes : bytes.slice());

/** What fetch rejects with when the connection fails. */
export const networkError = (): Error => new TypeError('fetch failed');
