// Remembers which names were found inside the root, so that a request for a known name costs
// no disk access within `revalidateAfterMs`, and one stat after it, instead of realpath and
// stat through Node's thread pool on every request.
//
// Why a remembered answer is safe: an entry only ever holds a file that was inside the root
// when it was checked, with that file's stat (device, inode, size, times). What is served from
// an entry is either the bytes read from that very version (ContentCache), or a file opened
// by its real path whose fstat must show the same device and inode (request-handler.ts). So a
// symlink swapped in to point outside the root can make the answer out of date, never make it
// come from outside: within the bound the old file is served, after it the name is checked
// again in full and refused.
//
// Why a bound rather than a look at the disk for every request: even one synchronous stat per
// name costs about a quarter of a small response (some 20 µs of 80 for index.json and its .br
// on the benchmark's VM), and keeps index.json under half of nginx's throughput. Within
// `revalidateAfterMs` (default 100 ms) a rewritten, renamed or deleted file may still be
// served as it was; with 0 every request stats the name, and any change on disk is seen by
// the next request. Missing names are never remembered, so a new file is found at once and a
// new index.json never names a chunk we deny having.
import type { Stats } from 'node:fs';
import { stat } from 'node:fs/promises';
import path from 'node:path';
import { performance } from 'node:perf_hooks';
import { sameVersion } from './file-version.js';
import { isInside, resolveInside, type Resolved } from './resolve-file.js';

// What a full check found: the real path inside the root, and its stat at the time.
type Found = Exclude<Resolved, { kind: 'missing' }>;

interface Entry {
  found: Found;
  seenAt: number; // when a stat of the name last showed `found`'s version, on the monotonic clock
}

export interface LookupCacheOptions {
  /** How long a name's remembered answer is used without a stat (default 100 ms; 0: never). */
  revalidateAfterMs?: number;
  /** Names remembered at most (default 10,000); the oldest go first. */
  maxEntries?: number;
  /** A monotonic clock in milliseconds, for tests; a wall clock set back would stretch the bound. */
  now?: () => number;
}

export const DEFAULT_REVALIDATE_AFTER_MS = 100;
const MISSING: Resolved = { kind: 'missing' };

export class LookupCache {
  // Insertion order is age: when full, the oldest entry goes, and costs one full check later.
  private readonly entries = new Map<string, Entry>();
  private readonly revalidateAfterMs: number;
  private readonly maxEntries: number;
  private readonly now: () => number;

  constructor(
    private readonly root: string, // a real path
    options: LookupCacheOptions = {},
  ) {
    this.revalidateAfterMs = options.revalidateAfterMs ?? DEFAULT_REVALIDATE_AFTER_MS;
    this.maxEntries = options.maxEntries ?? 10_000;
    this.now = options.now ?? (() => performance.now());
  }

  /** The same answer as resolveInside(root, segments), or that answer as it was at most the bound ago. */
  resolve(segments: readonly string[]): Promise<Resolved> {
    const candidate = path.join(this.root, ...segments);
    if (!isInside(this.root, candidate)) return Promise.resolve(MISSING);
    const entry = this.entries.get(candidate);
    const now = this.now();
    if (entry === undefined) return this.check(candidate, segments, now);
    if (now - entry.seenAt < this.revalidateAfterMs) return Promise.resolve(entry.found);
    return this.revalidate(candidate, segments, entry, now);
  }

  /** Drops what is remembered for a name, so that its next lookup is a full check. */
  forget(segments: readonly string[]): void {
    this.entries.delete(path.join(this.root, ...segments));
  }

  /** One stat of the name, in the thread pool like every other wait on the disk here. */
  private async revalidate(candidate: string, segments: readonly string[], entry: Entry, startedAt: number): Promise<Resolved> {
    let stats: Stats;
    try {
      stats = await stat(candidate);
    } catch {
      this.entries.delete(candidate); // gone, or no longer reachable: realpath fails too
      return MISSING;
    }
    // The name still leads to the very version that was checked: the same file, unchanged.
    // Renaming, linking or writing moves a file's ctime, and a symlink swapped in along the
    // name leads to another inode, so either sends the name through the full check.
    if (sameVersion(entry.found.stats, stats)) {
      entry.seenAt = startedAt;
      return entry.found;
    }
    return this.check(candidate, segments, startedAt);
  }

  private async check(candidate: string, segments: readonly string[], startedAt: number): Promise<Resolved> {
    const resolved = await resolveInside(this.root, segments);
    this.entries.delete(candidate);
    if (resolved.kind === 'missing') return resolved;
    // Dated from before the check began, so the bound is never stretched by the check's wait.
    this.entries.set(candidate, { found: resolved, seenAt: startedAt });
    if (this.entries.size > this.maxEntries) {
      const oldest = this.entries.keys().next();
      if (!oldest.done) this.entries.delete(oldest.value);
    }
    return resolved;
  }
}
