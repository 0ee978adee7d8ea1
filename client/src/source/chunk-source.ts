// The map's side of the chunk worker: starts it, forwards views and GPU notices, mirrors every
// chunk's status, and turns the worker's messages into events.
import type { CubeMeta } from '../../../format/cube-index.js';
import { Evented } from '../events.js';
import { createChunkWorker } from './create-worker.js';
import { fetchBytes } from './fetch-retry.js';
import { indexError } from './index-error.js';
import { indexUrl } from './index-url.js';
import type { ChunkStatus, Payload, FeatureInfo, FromWorker, NeededChunks, SourceErrorInfo, SourceOptions, ToWorker, ViewRequest } from './worker-protocol.js';

export interface ChunkSourceEvents {
  meta: CubeMeta;
  chunk: Payload;
  needed: NeededChunks;
  status: { file: string; status: ChunkStatus };
  error: SourceErrorInfo;
  /** The index could not be loaded (after 'error'): the map has nothing to show. */
  failed: SourceErrorInfo;
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

  constructor(url: string, options: Partial<SourceOptions> = {}) {
    super();
    this.url = indexUrl(url, location.href);
    this.worker = createChunkWorker();
    this.worker.addEventListener('message', (ev: MessageEvent<FromWorker>) => this.receive(ev.data));
    this.worker.addEventListener('error', (ev) => this.fire('error', { kind: 'index', message: `chunk worker failed: ${ev.message}`, url: this.url }));
    const opts = { ...defaultSourceOptions, ...options };
    this.send({ type: 'init', url: this.url, options: opts });
    // index.json is fetched here while the worker's own script loads, not by the worker after
    // it: on a slow network the first map comes a round trip sooner (bench:session).
    fetchBytes(this.url, opts).then(
      (body) => this.worker.postMessage({ type: 'index', body } satisfies ToWorker, [body]),
      (err: unknown) => this.send({ type: 'index-unavailable', error: indexError(err, this.url) }),
    );
  }

  setView(view: ViewRequest): void {
    this.send({ type: 'view', view });
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
      case 'meta':
        this.meta = msg.meta;
        this.fire('meta', msg.meta);
        break;
      case 'needed':
        this.fire('needed', msg);
        break;
      case 'status':
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
      case 'index-failed':
        this.fire('error', msg.error);
        this.fire('failed', msg.error);
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
