// The chunks on the GPU, within a memory budget: when over it, the least recently drawn chunks
// that the view does not need (on screen or in its prefetch margin) leave. Chunks the view needs
// stay even beyond the budget: evicting them would only fetch them again at once, forever.
import type { Payload } from '../source/worker-protocol.js';
import { GpuChunk } from './gpu-chunk.js';
import { GpuLineChunk } from './gpu-line-chunk.js';

/** A surface chunk or a line chunk on the GPU. */
export type StoredChunk = GpuChunk | GpuLineChunk;

export class ChunkStore {
  private readonly chunks = new Map<string, StoredChunk>();
  private totalBytes = 0;

  constructor(public budgetBytes: number) {}

  get bytes(): number {
    return this.totalBytes;
  }

  get size(): number {
    return this.chunks.size;
  }

  has(file: string): boolean {
    return this.chunks.has(file);
  }

  get(file: string): StoredChunk | undefined {
    return this.chunks.get(file);
  }

  values(): IterableIterator<StoredChunk> {
    return this.chunks.values();
  }

  add(gl: WebGL2RenderingContext, payload: Payload, frame: number): StoredChunk {
    const old = this.chunks.get(payload.file);
    if (old) this.remove(gl, old);
    const c = payload.kind === 'lines' ? new GpuLineChunk(gl, payload) : new GpuChunk(gl, payload);
    c.lastUsed = frame;
    this.chunks.set(c.file, c);
    this.totalBytes += c.bytes;
    return c;
  }

  /** Evicts down to the budget; returns the files evicted. */
  evict(gl: WebGL2RenderingContext, visible: ReadonlySet<string>, margin: ReadonlySet<string>): string[] {
    if (this.totalBytes <= this.budgetBytes) return [];
    const byAge = [...this.chunks.values()].sort((a, b) => a.lastUsed - b.lastUsed);
    const out: string[] = [];
    for (const c of byAge) {
      if (this.totalBytes <= this.budgetBytes) break;
      if (visible.has(c.file) || margin.has(c.file)) continue;
      this.remove(gl, c);
      out.push(c.file);
    }
    return out;
  }

  /** Forgets every chunk; with a lost context there is nothing to delete. */
  clear(gl: WebGL2RenderingContext | null): string[] {
    const files = [...this.chunks.keys()];
    if (gl) for (const c of this.chunks.values()) c.delete(gl);
    this.chunks.clear();
    this.totalBytes = 0;
    return files;
  }

  private remove(gl: WebGL2RenderingContext, c: StoredChunk): void {
    c.delete(gl);
    this.chunks.delete(c.file);
    this.totalBytes -= c.bytes;
  }
}
