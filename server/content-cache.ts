// Strong ETags from file contents, and the bytes of small files, remembered per file version
// (device, inode, size, times) so a rewritten file is hashed again and an unchanged one never.
import { createHash } from 'node:crypto';
import type { Stats } from 'node:fs';
import type { FileHandle } from 'node:fs/promises';
import { sameVersion, versionKey } from './file-version.js';

export interface Content {
  etag: string; // strong: the same bytes always give the same tag, whatever the file's times
  size: number;
  lastModifiedMs: number; // whole seconds
  lastModified: string; // the same as an HTTP date, formatted once rather than per response
  bytes: Buffer | undefined; // held in memory only for small files
}

interface Entry {
  stats: Stats; // the version the content was read from
  content: Content;
}

const HASH_CHUNK = 256 * 1024;

function etagOf(hash: ReturnType<typeof createHash>): string {
  // 128 bits of SHA-256 is ample to tell versions of one file apart.
  return `"${hash.digest('base64url').slice(0, 22)}"`;
}

export class ContentCache {
  // Map order is recency order: a hit moves its entry to the end, eviction takes the front.
  private readonly entries = new Map<string, Entry>();
  private readonly loading = new Map<string, Promise<Content>>();
  private bytesHeld = 0;

  constructor(
    private readonly maxBytes: number,
    private readonly maxFileBytes: number,
    private readonly maxEntries = 10_000,
  ) {}

  /** The content of exactly this version of the file, if already known. */
  peek(realPath: string, stats: Stats): Content | undefined {
    const entry = this.entries.get(realPath);
    if (!entry || !sameVersion(entry.stats, stats)) return undefined;
    this.entries.delete(realPath);
    this.entries.set(realPath, entry);
    return entry.content;
  }

  /** Reads and hashes an open file whose fstat is `stats`; concurrent loads share one read. */
  load(realPath: string, handle: FileHandle, stats: Stats): Promise<Content> {
    const key = `${realPath}\0${versionKey(stats)}`;
    let pending = this.loading.get(key);
    if (!pending) {
      pending = this.read(handle, stats).then((content) => {
        this.remember(realPath, stats, content);
        return content;
      });
      const settle = (): void => void this.loading.delete(key);
      pending.then(settle, settle);
      this.loading.set(key, pending);
    }
    return pending;
  }

  private async read(handle: FileHandle, stats: Stats): Promise<Content> {
    const lastModifiedMs = Math.floor(stats.mtimeMs / 1000) * 1000;
    const lastModified = new Date(lastModifiedMs).toUTCString();
    const hash = createHash('sha256');
    if (stats.size <= this.maxFileBytes) {
      const bytes = await handle.readFile();
      hash.update(bytes);
      return { etag: etagOf(hash), size: bytes.length, lastModifiedMs, lastModified, bytes };
    }
    const buf = Buffer.allocUnsafe(HASH_CHUNK);
    let position = 0;
    for (;;) {
      const { bytesRead } = await handle.read(buf, 0, buf.length, position);
      if (bytesRead === 0) break;
      hash.update(buf.subarray(0, bytesRead));
      position += bytesRead;
    }
    return { etag: etagOf(hash), size: position, lastModifiedMs, lastModified, bytes: undefined };
  }

  private remember(realPath: string, stats: Stats, content: Content): void {
    const old = this.entries.get(realPath);
    if (old) {
      this.bytesHeld -= old.content.bytes?.length ?? 0;
      this.entries.delete(realPath);
    }
    this.entries.set(realPath, { stats, content });
    this.bytesHeld += content.bytes?.length ?? 0;
    for (const [key, entry] of this.entries) {
      if (this.bytesHeld <= this.maxBytes && this.entries.size <= this.maxEntries) break;
      this.bytesHeld -= entry.content.bytes?.length ?? 0;
      this.entries.delete(key);
    }
  }
}
