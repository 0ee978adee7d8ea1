// Which chunks to fetch, in what order, and what became of each. Runs in the worker.
// - a view asks the index for the chunks under it (plus a margin) over its z range;
// - each chunk has one status; a chunk is never requested twice at once;
// - a request for a chunk that left the view (and its margin) is aborted;
// - the nearest to the view centre and base z go first, the on-screen ones before the margin.
import type { ChunkLeaf } from '../shared/cube-index.js';
import { boxMeets, chunkPriority } from '../shared/index-query.js';
import { ChunkCorrupt, fetchChunk } from './chunk-fetch.js';
import { FetchFailure } from './fetch-retry.js';
import type { IndexTree } from './index-tree.js';
import type { ChunkStatus, FromWorker, SourceErrorInfo, SourceOptions, ViewRequest } from './worker-protocol.js';

interface Entry {
  leaf: ChunkLeaf;
  status: ChunkStatus;
  /** The request in flight (its identity tells a stale completion from the current one). */
  controller: AbortController | null;
  priority: number;
}

export type Post = (msg: FromWorker, transfer?: Transferable[]) => void;

const MARGIN_TIER = 1e6;

export class ChunkScheduler {
  private readonly entries = new Map<string, Entry>();
  private needed = new Set<string>();
  private inFlight = 0;
  private view: ViewRequest | null = null;

  constructor(
    private readonly tree: IndexTree,
    private readonly opts: SourceOptions,
    private readonly post: Post,
  ) {}

  setView(view: ViewRequest): void {
    this.view = view;
    const t0 = performance.now();
    const q = { ground: view.margin, zMin: view.zMin, zMax: view.zMax };
    const res = this.tree.query(q);
    const queryMs = performance.now() - t0;
    const visibleQ = { ground: view.visible, zMin: view.zMin, zMax: view.zMax };
    const halfDiag = Math.hypot(view.visible[2] - view.visible[0], view.visible[3] - view.visible[1]) / 2;
    const zScale = Math.max(1, view.zMax - view.zMin);
    const visible: string[] = [];
    const margin: string[] = [];
    const needed = new Set<string>();
    for (const leaf of res.leaves) {
      let e = this.entries.get(leaf.file);
      if (!e) {
        e = { leaf, status: 'not-requested', controller: null, priority: 0 };
        this.entries.set(leaf.file, e);
      }
      const onScreen = boxMeets(leaf.bbox, visibleQ);
      e.priority = chunkPriority(leaf.bbox, view.centerX, view.centerY, view.z, halfDiag, zScale) + (onScreen ? 0 : MARGIN_TIER);
      (onScreen ? visible : margin).push(leaf.file);
      needed.add(leaf.file);
    }
    this.needed = needed;
    for (const [file, e] of this.entries) {
      if (needed.has(file)) continue;
      if (e.status === 'requested') {
        e.controller?.abort();
        e.controller = null;
        this.setStatus(e, 'not-requested');
      } else if (e.status === 'failed') {
        // Out of view: it may be tried again when it comes back.
        this.setStatus(e, 'not-requested');
      }
    }
    this.post({ type: 'needed', seq: view.seq, visible, margin, indexComplete: res.missing.length === 0, queryMs, visited: res.visited });
    if (res.missing.length > 0) {
      this.tree.loadSubs(res.missing).then(
        () => {
          if (this.view === view) this.setView(view);
        },
        (err: unknown) => this.postError(indexError(err)),
      );
    }
    this.pump();
  }

  uploaded(file: string): void {
    const e = this.entries.get(file);
    if (e && e.status === 'received') this.setStatus(e, 'gpu');
  }

  evicted(files: string[]): void {
    for (const file of files) {
      const e = this.entries.get(file);
      if (e && (e.status === 'gpu' || e.status === 'received')) this.setStatus(e, 'evicted');
    }
    this.pump();
  }

  private setStatus(e: Entry, status: ChunkStatus): void {
    if (e.status === status) return;
    e.status = status;
    this.post({ type: 'status', file: e.leaf.file, status });
  }

  private pump(): void {
    if (this.inFlight >= this.opts.concurrency) return;
    const waiting: Entry[] = [];
    for (const file of this.needed) {
      const e = this.entries.get(file)!;
      if (e.status === 'not-requested' || e.status === 'evicted') waiting.push(e);
    }
    waiting.sort((a, b) => a.priority - b.priority);
    for (const e of waiting) {
      if (this.inFlight >= this.opts.concurrency) break;
      this.start(e);
    }
  }

  private start(e: Entry): void {
    const controller = new AbortController();
    e.controller = controller;
    this.inFlight++;
    this.setStatus(e, 'requested');
    fetchChunk(e.leaf, this.tree.url(e.leaf.file), this.opts, controller.signal)
      .then(
        (chunk) => {
          if (e.controller !== controller) return; // aborted meanwhile
          e.controller = null;
          this.setStatus(e, 'received');
          this.post({ type: 'chunk', chunk }, [chunk.buffer]);
        },
        (err: unknown) => {
          if (e.controller !== controller) return;
          e.controller = null;
          if (err instanceof FetchFailure && err.kind === 'abort') {
            this.setStatus(e, 'not-requested');
            return;
          }
          this.setStatus(e, 'failed');
          this.postError(chunkError(err, e.leaf.file, this.tree.url(e.leaf.file)));
        },
      )
      .finally(() => {
        this.inFlight--;
        this.pump();
      });
  }

  private postError(error: SourceErrorInfo): void {
    this.post({ type: 'error', error });
  }
}

function chunkError(err: unknown, file: string, url: string): SourceErrorInfo {
  if (err instanceof ChunkCorrupt) return { kind: 'corrupt', message: err.message, url, file };
  if (err instanceof FetchFailure) {
    const info: SourceErrorInfo = { kind: err.kind === 'http' ? 'http' : 'network', message: `${err.message} (after ${err.attempts} attempt${err.attempts === 1 ? '' : 's'})`, url, file };
    if (err.status !== undefined) info.status = err.status;
    return info;
  }
  return { kind: 'network', message: `${file}: ${(err as Error).message}`, url, file };
}

export function indexError(err: unknown): SourceErrorInfo {
  if (err instanceof FetchFailure) {
    const info: SourceErrorInfo = { kind: err.kind === 'http' ? 'http' : 'network', message: err.message, url: err.url };
    if (err.status !== undefined) info.status = err.status;
    return info;
  }
  return { kind: 'index', message: (err as Error).message, url: '' };
}
