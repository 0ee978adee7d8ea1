// The map's side of the chunk worker: starts it, reads the cube's index.json for the map and the
// worker, fetches the first view's floor chunks for the worker (its head start), forwards views
// and GPU notices, mirrors every chunk's status, and turns the worker's messages into events.
import type { CubeIndex, CubeMeta } from '../../../format/cube-index.js';
import { Evented } from '../events.js';
import { createChunkWorker } from './create-worker.js';
import { indexError } from './index-error.js';
import { cubeFileUrl, indexUrl } from './index-url.js';
import { HeadStartFetches } from './head-start.js';
import { firstViewFiles } from './floor-choice.js';
import { readIndex } from './read-index.js';
import type { ChunkStatus, Payload, FeatureInfo, FromWorker, NeededChunks, SourceErrorInfo, SourceOptions, ToWorker, ViewRequest } from './worker-protocol.js';

export interface ChunkSourceEvents {
  meta: CubeMeta;
  chunk: Payload;
  needed: NeededChunks;
  status: { file: string; status: ChunkStatus };
  error: SourceErrorInfo;
  /** The index could not be loaded (after 'error'): the map has nothing to show. */
  failed: SourceErrorInfo;
  /** The head start's last body went to the worker (or its fetch failed). */
  'handed-over': undefined;
}

export const defaultSourceOptions: SourceOptions = { concurrency: 6, retries: 5, backoffMs: 250, maxBackoffMs: 4000, marginRestMs: 300 };

export class ChunkSource extends Evented<ChunkSourceEvents> {
  readonly url: string;
  private readonly worker: Worker;
  private readonly statuses = new Map<string, ChunkStatus>();
  // Questions to the worker awaiting their answer, by id.
  private readonly requests = new Map<number, { resolve: (answer: unknown) => void; reject: (e: Error) => void }>();
  private nextRequest = 1;
  meta: CubeMeta | null = null;
  private readonly opts: SourceOptions;
  /** index.json, once read (the worker has its own copy). */
  private index: CubeIndex | null = null;
  private headStarted = false;
  /** The first view's floor chunks, being fetched for the worker (headStart). */
  private headStarts: HeadStartFetches | null = null;
  /** The map was removed: an index that comes late is not taken. */
  private destroyed = false;
  /** The worker could not be started: nothing is fetched for it. */
  private workerGone = false;
  /** The page is online again: what failed for want of a network is asked for again (the worker's ChunkScheduler.retryFailed). */
  private readonly onOnline = (): void => this.send({ type: 'online' });

  constructor(url: string, options: Partial<SourceOptions> = {}) {
    super();
    this.url = indexUrl(url, location.href);
    this.worker = createChunkWorker();
    this.worker.addEventListener('message', (ev: MessageEvent<FromWorker>) => this.receive(ev.data));
    this.worker.addEventListener('error', (ev: Event) => {
      // A worker whose script could not be had (missing beside the library, or refused by the
      // page's Content-Security-Policy) fires a plain Event: nothing will be fetched or drawn.
      // An exception inside a running worker comes as an ErrorEvent with its message.
      const message = ev instanceof ErrorEvent && ev.message ? ev.message : null;
      const error: SourceErrorInfo = { kind: 'worker', message: message ? `the map's worker failed: ${message}` : "the map's worker could not be started", url: this.url };
      this.fire('error', error);
      if (message !== null) return;
      this.workerGone = true;
      this.headStarts?.cancelAll();
      this.fire('failed', error);
    });
    this.opts = { ...defaultSourceOptions, ...options };
    this.send({ type: 'init', url: this.url, options: this.opts });
    addEventListener('online', this.onOnline);
    // index.json is read here while the worker's own script loads, not by the worker after it:
    // on a slow network the first map comes a round trip sooner (bench:session), and the first
    // view's floor chunks can be asked for before the worker runs (setView).
    readIndex(this.url, this.opts).then(
      (index) => {
        if (this.destroyed) return;
        this.index = index;
        this.send({ type: 'index', index });
        this.meta = index.meta;
        this.fire('meta', index.meta);
      },
      (err: unknown) => {
        if (this.destroyed) return;
        const error = indexError(err, this.url);
        this.send({ type: 'index-unavailable', error });
        this.fire('error', error);
        this.fire('failed', error);
      },
    );
  }

  setView(view: ViewRequest): void {
    if (this.index && !this.headStarted && !this.workerGone) {
      this.headStarted = true;
      this.headStart(firstViewFiles(this.index, view));
    }
    this.send({ type: 'view', view });
  }

  /**
   * What the first view asks for first (its floor chunks; above the floor, its interim floor
   * and the sub-index files its query reaches: firstViewFiles), fetched here and handed to the
   * worker (head-start.ts): on a slow network its script (33 kB gzip) comes a round trip and
   * more after index.json, and these need not wait for it. All of them at once: the browser
   * queues them as the worker would, and nlcd_zion's first complete map on Slow 4G came in
   * 2,492 ms, against 2,560 with its first six floor chunks alone (medians of 7). The worker is
   * told before the view (messages keep their order), so it asks for none of them again.
   */
  private headStart(files: string[]): void {
    const urls = files.map((f) => cubeFileUrl(f, this.url));
    if (urls.length === 0) return;
    this.send({ type: 'head-start', urls });
    this.headStarts = new HeadStartFetches(
      urls,
      this.opts,
      (url, result) => this.worker.postMessage({ type: 'head-start-result', url, result } satisfies ToWorker, result instanceof ArrayBuffer ? [result] : []),
      () => this.fire('handed-over', undefined),
    );
  }

  /** The map still fetches some of the first view's chunks for the worker (headStart). */
  get handingOver(): boolean {
    return this.headStarts?.pending ?? false;
  }

  /** The chunk went to the GPU. */
  uploaded(file: string): void {
    this.statuses.set(file, 'gpu');
    this.send({ type: 'uploaded', file });
  }

  /** The chunks left the GPU (budget, or a lost context): fetched again when needed. */
  evicted(files: string[]): void {
    if (files.length === 0) return;
    for (const f of files) this.statuses.set(f, 'evicted');
    this.send({ type: 'evicted', files });
  }

  status(file: string): ChunkStatus {
    return this.statuses.get(file) ?? 'not-requested';
  }

  allStatuses(): Map<string, ChunkStatus> {
    return new Map(this.statuses);
  }

  features(faces: number[]): Promise<(FeatureInfo | null)[]> {
    return this.ask<(FeatureInfo | null)[]>((id) => ({ type: 'features', id, faces }));
  }

  /** The attributes of input features (null: none stored). */
  attributes(features: number[]): Promise<(Record<string, unknown> | null)[]> {
    return this.ask<(Record<string, unknown> | null)[]>((id) => ({ type: 'attributes', id, features }));
  }

  /** Absolute URLs of every file received so far (index, pages, chunks), oldest first. */
  loadedUrls(): Promise<string[]> {
    return this.ask<string[]>((id) => ({ type: 'loaded-urls', id }));
  }

  destroy(): void {
    this.destroyed = true;
    removeEventListener('online', this.onOnline);
    this.headStarts?.cancelAll();
    this.worker.terminate();
    for (const r of this.requests.values()) r.reject(new Error('the map was removed'));
    this.requests.clear();
  }

  private ask<T>(message: (id: number) => ToWorker): Promise<T> {
    const id = this.nextRequest++;
    return new Promise<T>((resolve, reject) => {
      this.requests.set(id, { resolve: resolve as (answer: unknown) => void, reject });
      this.send(message(id));
    });
  }

  private answer(id: number, answer: unknown, error?: string): void {
    const r = this.requests.get(id);
    this.requests.delete(id);
    if (error !== undefined) r?.reject(new Error(error));
    else r?.resolve(answer);
  }

  private send(msg: ToWorker): void {
    this.worker.postMessage(msg);
  }

  private receive(msg: FromWorker): void {
    switch (msg.type) {
      case 'needed':
        this.fire('needed', msg);
        break;
      case 'status':
        // A file the worker left behind (its view moved on) is not fetched for it any more.
        if (msg.status === 'not-requested') this.headStarts?.cancel(cubeFileUrl(msg.file, this.url));
        this.statuses.set(msg.file, msg.status);
        this.fire('status', { file: msg.file, status: msg.status });
        break;
      case 'chunk':
        this.statuses.set(msg.chunk.file, 'received');
        this.fire('chunk', msg.chunk);
        break;
      case 'error':
        this.fire('error', msg.error);
        break;
      case 'features':
        this.answer(msg.id, msg.features, msg.error);
        break;
      case 'attributes':
        this.answer(msg.id, msg.properties, msg.error);
        break;
      case 'loaded-urls':
        this.answer(msg.id, msg.urls);
        break;
    }
  }
}
