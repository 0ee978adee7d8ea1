// The cube's R-tree in the worker: the root from index.json, sub-index files fetched the first
// time a query reaches them (once each, however many queries ask meanwhile).
import { parseSubIndex, type CubeIndex, type InnerNode } from '../../../format/cube-index.js';
import { queryIndex, type QueryBox, type QueryResult } from '../../../format/index-query.js';
import { FailedFiles } from './failed-files.js';
import { fetchJson, type RetryOptions } from './fetch-retry.js';
import { floorQuery } from './floor-choice.js';
import { cubeFileUrl } from './index-url.js';
import { readIndex } from './read-index.js';

export class IndexTree {
  private readonly subs = new Map<string, InnerNode>();
  private readonly loading = new Map<string, Promise<void>>();
  /**
   * Sub-index files whose last load failed. loadSub may be asked for them again; the scheduler
   * asks again for the floor's only once the page is back online, where their failure may pass
   * (ChunkScheduler.usableFloor, retryFailed).
   */
  private readonly failed = new FailedFiles();

  private constructor(
    readonly index: CubeIndex,
    private readonly indexUrl: string,
    private readonly retry: RetryOptions,
  ) {}

  static async load(indexUrl: string, retry: RetryOptions): Promise<IndexTree> {
    return IndexTree.of(await readIndex(indexUrl, retry), indexUrl, retry);
  }

  /** The index of `indexUrl`, read elsewhere (the map reads it while the worker starts, ChunkSource). */
  static of(index: CubeIndex, indexUrl: string, retry: RetryOptions): IndexTree {
    return new IndexTree(index, indexUrl, retry);
  }

  url(file: string): string {
    return cubeFileUrl(file, this.indexUrl);
  }

  query(q: QueryBox): QueryResult {
    return queryIndex(this.index.root, q, (ref) => this.subs.get(ref));
  }

  /** The floor chunks a query needs, or null when the cube has none or the query reaches above their top. */
  floorQuery(q: QueryBox): QueryResult | null {
    return floorQuery(this.index, q, (ref) => this.subs.get(ref));
  }

  /** A sub-index file asked for, not in yet, and not failed. */
  isLoading(ref: string): boolean {
    return this.loading.has(ref) && !this.subs.has(ref);
  }

  /** A sub-index file whose last load failed. */
  hasFailed(ref: string): boolean {
    return this.failed.has(ref);
  }

  /** The page is back online: the failures that may pass are forgotten (FailedFiles). */
  backOnline(): void {
    this.failed.backOnline();
  }

  /** Loads a sub-index file, unless it is loaded or loading already; resolves when it is in. */
  loadSub(ref: string): Promise<void> {
    let p = this.loading.get(ref);
    if (!p) {
      const startedAt = performance.now();
      p = fetchJson(this.url(ref), this.retry).then((json) => {
        this.subs.set(ref, parseSubIndex(json, ref));
        this.failed.delete(ref);
      });
      // A failed load may be asked for again; one the page's coming back online may have
      // mended is not recorded (hasFailed stays false), so the next query asks again.
      p.catch((err: unknown) => {
        this.loading.delete(ref);
        this.failed.fail(ref, err, startedAt);
      });
      this.loading.set(ref, p);
    }
    return p;
  }
}
