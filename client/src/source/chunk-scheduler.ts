// Which chunks to fetch, in what order, and what became of each. Runs in the worker.
// - a view asks the index for the chunks under it (plus a margin) over its z range;
// - each chunk has one status; a chunk is never requested twice at once;
// - at most `concurrency` requests are on the network or waiting to be retried: one leaves the
//   count when its body has come, before it is checked and decoded;
// - a request for a chunk that left the view (and its margin) is aborted;
// - the nearest to the view centre and base z go first, the on-screen ones before the margin,
//   then those of the views ahead (a flight's path), in the order they will be shown;
// - the margin waits until every on-screen chunk is on the GPU (or failed): on a slow link it
//   would share its bandwidth, and the map uploads every chunk that has come before it calls a
//   frame complete, so it would hold back the complete map. It also waits until the view has
//   rested (`marginRestMs`, or one and a half of the map's frames where they take longer,
//   restMs): during a zoom or a pan each view's margin is soon left behind, and fetching it
//   only costs data (bench:session, bgt_otterlo_1800m: 2.18 -> 1.90 MB). The views ahead do
//   not wait: during a flight some on-screen chunk is nearly always coming, and the path must
//   be fetched ahead;
// - below the floor's top the floor chunks go on screen, and the cube's chunks are the margin
//   (floorShown): the first map at the base scale takes a fifth of the bytes. The cube's
//   sub-index files wait, as the margin does, until the floor chunks on screen are on the GPU
//   (and, a floor too large for index.json, until its own sub-index files have come or failed:
//   the margin's chunks wait for those too);
// - just above the floor's top, until a view's chunks on screen have all been on the GPU once,
//   the floor chunks on screen go first, drawn under the view meanwhile (interimFloor): a
//   complete picture of the base scale for a fifth of the bytes, refined as the view's own come.
import type { ChunkLeaf, LineChunkLeaf } from '../../../format/cube-index.js';
import { boxMeets, queryLineChunks, viewPriority, type QueryBox, type QueryResult } from '../../../format/index-query.js';
import { ChunkCorrupt, fetchChunk } from './chunk-fetch.js';
import { fetchLineChunk } from './line-chunk-fetch.js';
import { floorChoice, interimApplies, interimFloor, underView } from './floor-choice.js';
import { FailedFiles } from './failed-files.js';
import { FetchFailure, type RetryOptions } from './fetch-retry.js';
import { indexError } from './index-error.js';
import type { IndexTree } from './index-tree.js';
import type { ChunkStatus, FromWorker, SourceErrorInfo, SourceOptions, ViewRequest } from './worker-protocol.js';

/** A surface chunk or a line chunk: fetched, ranked and tracked alike. */
type Leaf = ChunkLeaf | LineChunkLeaf;
const isLineLeaf = (l: Leaf): l is LineChunkLeaf => 'lines' in l;

interface Entry {
  leaf: Leaf;
  status: ChunkStatus;
  /** The request in flight (its identity tells a stale completion from the current one). */
  controller: AbortController | null;
  priority: number;
}

// A chunk's buffer is moved to the map, not copied. ArrayBuffer rather than the DOM's
// Transferable: the unit tests compile this module for Node.
export type Post = (msg: FromWorker, transfer?: ArrayBuffer[]) => void;

const MARGIN_TIER = 1e6;
/** The interim floor's chunks rank from -INTERIM_TIER: before the view's own. */
const INTERIM_TIER = 1e6;
/** Chunks of the i-th view ahead rank from AHEAD_TIER + i * MARGIN_TIER. */
const AHEAD_TIER = 1e8;
/** A view has rested once it has lasted this many of the map's frames (and marginRestMs). */
const REST_FRAMES = 1.5;

export class ChunkScheduler {
  private readonly entries = new Map<string, Entry>();
  private needed = new Set<string>();
  /**
   * Chunks whose last fetch failed: floor chunks among them are not chosen again (floorShown),
   * unless the page comes back online and their failure may pass (retryFailed).
   */
  private readonly failed = new FailedFiles();
  private inFlight = 0;
  private view: ViewRequest | null = null;
  /** When the view last changed (performance.now()), and the timer that starts the margin once it has rested. */
  private viewSince = 0;
  private restTimer: ReturnType<typeof setTimeout> | null = null;
  /** The cube's sub-index files a view at the floor reaches: loaded once its floor chunks on screen are on the GPU, and the floor's sub-index files have come or failed (pump). */
  private marginSubs: string[] = [];
  /** The floor's sub-index files the view reaches (its floor on screen, or its interim floor): until they have come or failed, that floor's chunks are not all known. */
  private floorSubs: string[] = [];
  /** The view's chunks on screen (without the interim floor); null while its list is not whole. */
  private visibleFiles: string[] | null = null;
  /** A view's chunks on screen have all been on the GPU: no interim floor from then on. */
  private firstShown = false;

  constructor(
    private readonly tree: IndexTree,
    private readonly opts: SourceOptions & Pick<RetryOptions, 'onLoaded' | 'headStart'>,
    private readonly post: Post,
  ) {}

  setView(view: ViewRequest): void {
    // The same view again (its sub-index files came in) has not moved.
    if (this.view?.seq !== view.seq) this.viewSince = performance.now();
    this.view = view;
    const t0 = performance.now();
    const q = { ground: view.margin, zMin: view.zMin, zMax: view.zMax };
    const visibleQ = { ground: view.visible, zMin: view.zMin, zMax: view.zMax };
    const cube = this.tree.query(q);
    // Below the floor's top: the floor chunks on screen, and the cube's as the margin.
    const floor = this.floorShown(cube, visibleQ);
    const lineLeaves = this.lineLeaves(q);
    const queryMs = performance.now() - t0;
    const visible: string[] = [];
    const margin: string[] = [];
    const ahead: string[] = [];
    const needed = new Set<string>();
    // Below the floor's top the cube's sub-index files are the margin's (floorShown): they wait
    // with it, not to share the link with the floor chunks on screen.
    const missing = new Set(floor ? floor.missing : cube.missing);
    this.marginSubs = floor ? cube.missing : [];
    const want = (leaf: Leaf, priority: number): void => {
      let e = this.entries.get(leaf.file);
      if (!e) {
        e = { leaf, status: 'not-requested', controller: null, priority: 0 };
        this.entries.set(leaf.file, e);
      }
      e.priority = priority;
      needed.add(leaf.file);
    };
    const rank = view.visible;
    // Just above the floor's top, a first view's floor on screen, drawn under it meanwhile (its
    // sub-index files, in a cube large enough to have some, loaded with the cube's).
    const under = floor || this.firstShown || !interimApplies(this.tree.index, view) ? null : this.usableFloor(underView(view.visible));
    const interim = interimFloor(this.tree.index, view, under, cube, (leaves, box) => this.bytesToFetch(leaves, box));
    for (const m of under?.missing ?? []) missing.add(m);
    this.floorSubs = (floor ?? under)?.missing ?? [];
    for (const leaf of interim) want(leaf, viewPriority(leaf.bbox, rank, view) - INTERIM_TIER);
    for (const leaf of floor?.leaves ?? []) {
      want(leaf, viewPriority(leaf.bbox, rank, view));
      visible.push(leaf.file);
    }
    for (const leaf of [...cube.leaves, ...lineLeaves]) {
      const onScreen = (!floor || isLineLeaf(leaf)) && boxMeets(leaf.bbox, visibleQ);
      want(leaf, viewPriority(leaf.bbox, rank, view) + (onScreen ? 0 : MARGIN_TIER));
      (onScreen ? visible : margin).push(leaf.file);
    }
    (view.ahead ?? []).forEach((a, i) => {
      const aq = { ground: a.box, zMin: a.zMin, zMax: a.zMax };
      const aCube = this.tree.query(aq);
      const r = this.floorShown(aCube, aq) ?? aCube;
      for (const m of r.missing) missing.add(m);
      for (const leaf of [...r.leaves, ...this.lineLeaves(aq)]) {
        if (needed.has(leaf.file)) continue;
        want(leaf, AHEAD_TIER + i * MARGIN_TIER + viewPriority(leaf.bbox, a.box, a));
        ahead.push(leaf.file);
      }
    });
    this.needed = needed;
    // Until the view's sub-index files have come, its list on screen is not whole.
    this.visibleFiles = (floor ?? cube).missing.length === 0 ? visible : null;
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
    this.post({ type: 'needed', seq: view.seq, visible, margin, ahead, interim: interim.map((l) => l.file), indexComplete: (floor ?? cube).missing.length === 0, queryMs, visited: cube.visited + (floor?.visited ?? 0) });
    this.loadSubs([...missing]);
    this.pump();
  }

  /**
   * Sub-index files the view reaches, loaded; the view is asked again once they have all come or
   * failed (each failure reported), if any came or one of the floor's failed (the cube's chunks
   * then draw the floor, usableFloor): one that fails holds back none of the others. Else what
   * waited for them (the margin, below the floor's top) goes on (pump).
   */
  private loadSubs(refs: string[]): void {
    if (refs.length === 0) return;
    const view = this.view;
    void Promise.allSettled(refs.map((ref) => this.tree.loadSub(ref))).then((results) => {
      // A failure the page's coming back online may have mended is not recorded: asked again.
      const failed = (i: number): boolean => results[i]!.status === 'rejected' && this.tree.hasFailed(refs[i]!);
      results.forEach((r, i) => {
        if (r.status === 'rejected' && failed(i)) this.postError(indexError(r.reason));
      });
      const floorFailed = refs.some((ref, i) => failed(i) && this.floorSubs.includes(ref));
      const again = refs.some((_, i) => !failed(i)); // came, or to be asked again
      if ((floorFailed || again) && view && this.view === view) this.setView(view);
      else this.pump();
    });
  }

  /**
   * Below the floor's top, the floor chunks a view shows on screen (docs/FORMAT.md, "Floor
   * chunks"): the floor the cube's chunks there hold among others' triangles, in fewer bytes.
   * The cube's chunks are then the margin: the next view may as well be a zoom out, for which
   * the floor's are no use, as a pan, which the cube's serve too. Null (the cube's on screen
   * too) by floorChoice's rule, or when there is no floor.
   */
  private floorShown(cube: QueryResult, onScreen: QueryBox): QueryResult | null {
    return floorChoice(this.usableFloor(onScreen), cube, (leaves) => this.bytesToFetch(leaves, onScreen));
  }

  /**
   * The floor's query, or null (no floor to draw) where one of its sub-index files failed: the
   * cube's chunks, which hold the floor too, serve instead, as they do for a failed floor chunk.
   */
  private usableFloor(q: QueryBox): QueryResult | null {
    const floor = this.tree.floorQuery(q);
    return floor && floor.missing.some((ref) => this.tree.hasFailed(ref)) ? null : floor;
  }

  /** Bytes of `leaves` meeting `onScreen` not received yet; Infinity when one of them has failed. */
  private bytesToFetch(leaves: readonly ChunkLeaf[], onScreen: QueryBox): number {
    let bytes = 0;
    for (const leaf of leaves) {
      if (!boxMeets(leaf.bbox, onScreen)) continue;
      if (this.failed.has(leaf.file)) return Infinity;
      const status = this.entries.get(leaf.file)?.status ?? 'not-requested';
      if (status !== 'received' && status !== 'gpu') bytes += leaf.bytes;
    }
    return bytes;
  }

  /** The line chunks a query box needs (none in a cube without lines). */
  private lineLeaves(q: QueryBox): LineChunkLeaf[] {
    return queryLineChunks(this.tree.index.lines ?? [], q);
  }

  /**
   * The network is back (the page's 'online' event, ChunkSource): the files whose last fetch
   * failed for a cause that may pass (a network failure; a 5xx, 408 or 429 after the retries)
   * are asked for again where the view needs them, and a floor given up for one of them may be
   * drawn again. A lasting failure (another 4xx, a corrupt body) stays: it would fail again.
   * Without this, a chunk that failed stayed failed while the view kept it, and a floor's
   * while the worker lived: a phone back from a tunnel kept the holes.
   */
  retryFailed(): void {
    for (const file of this.failed.backOnline()) {
      const e = this.entries.get(file);
      if (e?.status === 'failed') this.setStatus(e, 'not-requested');
    }
    this.tree.backOnline();
    if (this.view) this.setView(this.view);
  }

  /** The chunks the view (with its margin and the views ahead) needs. */
  get neededFiles(): ReadonlySet<string> {
    return this.needed;
  }

  uploaded(file: string): void {
    const e = this.entries.get(file);
    if (!e || e.status !== 'received') return;
    this.setStatus(e, 'gpu');
    const v = this.visibleFiles;
    if (!this.firstShown && v && v.length > 0 && v.every((f) => this.entries.get(f)?.status === 'gpu')) this.firstShown = true;
    // Once the last on-screen chunk is up, the margin may start.
    if (e.priority < MARGIN_TIER) this.pump();
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
    const waiting: Entry[] = [];
    let onScreenComing = this.floorSubs.some((ref) => this.tree.isLoading(ref));
    for (const file of this.needed) {
      const e = this.entries.get(file)!;
      const toStart = e.status === 'not-requested' || e.status === 'evicted';
      if (toStart) waiting.push(e);
      if (e.priority < MARGIN_TIER && (toStart || e.status === 'requested' || e.status === 'received')) onScreenComing = true;
    }
    // Not held back by the view's rest as the margin's chunks are: a few files, each loaded once.
    if (!onScreenComing && this.marginSubs.length > 0) {
      const refs = this.marginSubs;
      this.marginSubs = [];
      this.loadSubs(refs);
    }
    if (this.inFlight >= this.opts.concurrency) return;
    waiting.sort((a, b) => a.priority - b.priority);
    const restLeft = this.viewSince + this.restMs() - performance.now();
    let marginWaits = false;
    for (const e of waiting) {
      if (this.inFlight >= this.opts.concurrency) break;
      if (e.priority >= MARGIN_TIER && e.priority < AHEAD_TIER && (onScreenComing || restLeft > 0)) {
        marginWaits = true;
        continue;
      }
      this.start(e);
    }
    if (marginWaits && !onScreenComing && restLeft > 0 && this.restTimer === null) {
      this.restTimer = setTimeout(() => {
        this.restTimer = null;
        this.pump();
      }, restLeft);
    }
  }

  /**
   * How long the view must rest before its margin is fetched: on a device whose frames take
   * longer than marginRestMs (a slow phone, a software GPU), each view of a zoom outlasted it
   * and fetched its margin (bench:session, nlcd_zion with frames of about 320 ms: 4.94 -> 4.36
   * MB for the session, of which 3.93 its views' own chunks).
   */
  private restMs(): number {
    const min = this.opts.marginRestMs;
    return min > 0 ? Math.max(min, REST_FRAMES * (this.view?.frameMs ?? 0)) : 0;
  }

  private start(e: Entry): void {
    const controller = new AbortController();
    const startedAt = performance.now();
    e.controller = controller;
    this.inFlight++;
    this.setStatus(e, 'requested');
    const leaf = e.leaf;
    const url = this.tree.url(leaf.file);
    // The request's place is free once its body has come: checking and decoding it (a floor
    // chunk cold in the worker: 15 ms) no longer hold the next request back. (The bodies waiting
    // to be decoded are bounded by the chunks the view needs.) A microtask, so that nothing the
    // next request does runs inside fetchBytes's error handling.
    let holding = true;
    const release = (): void => {
      if (!holding) return;
      holding = false;
      this.inFlight--;
      this.pump();
    };
    const opts = { ...this.opts, onLoaded: (u: string): void => { this.opts.onLoaded?.(u); queueMicrotask(release); } };
    (isLineLeaf(leaf) ? fetchLineChunk(leaf, url, this.tree.index.meta, opts, controller.signal) : fetchChunk(leaf, url, opts, controller.signal))
      .then(
        (chunk) => {
          if (e.controller !== controller) return; // aborted meanwhile
          e.controller = null;
          this.failed.delete(leaf.file);
          this.setStatus(e, 'received');
          const transfer = chunk.kind === 'lines' ? [chunk.segments.buffer, chunk.segmentLine.buffer, chunk.segmentRule.buffer, chunk.lineClass.buffer, chunk.lineFeature.buffer, chunk.lineRamp.buffer] : [chunk.buffer, chunk.blocks.cellBox.buffer, chunk.blocks.cellBlocks.buffer, chunk.blocks.zLow.buffer, chunk.blocks.first.buffer];
          this.post({ type: 'chunk', chunk }, transfer as ArrayBuffer[]);
        },
        (err: unknown) => {
          if (e.controller !== controller) return;
          e.controller = null;
          // Aborted, or failed for an outage the page has come back from since: asked for again.
          if ((err instanceof FetchFailure && err.kind === 'abort') || !this.failed.fail(e.leaf.file, err, startedAt)) {
            this.setStatus(e, 'not-requested');
            return;
          }
          this.setStatus(e, 'failed');
          this.postError(chunkError(err, e.leaf.file, this.tree.url(e.leaf.file)));
          // A view at the floor turns to the cube's chunks at once (floorShown).
          if (this.view && this.tree.index.floor) this.setView(this.view);
        },
      )
      // Pumped again either way: the chunk's end (received, failed) may let the margin start.
      .finally(() => (holding ? release() : this.pump()));
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
