// The chunks on the GPU, within a memory budget: when over it, the least recently drawn chunks
// that the view does not need (on screen or in its prefetch margin) leave. Chunks the view needs
// stay even beyond the budget: evicting them would only fetch them again at once, forever.
import type { ChunkPayload } from '../source/worker-protocol.js';
import { GpuChunk } from './gpu-chunk.js';

export class ChunkStore {
  private readonly chunks = new Map<string, GpuChunk>();
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

  get(file: string): GpuChunk | undefined {
    return this.chunks.get(file);
  }

  values(): IterableIterator<GpuChunk> {
    return this.chunks.values();
  }

  add(gl: WebGL2RenderingContext, payload: ChunkPayload, frame: number): GpuChunk {
    const old = this.chunks.get(payload.file);
    if (old) this.remove(gl, old);
    const c = new GpuChunk(gl, payload);
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

  private remove(gl: WebGL2RenderingContext, c: GpuChunk): void {
    c.delete(gl);
    this.chunks.delete(c.file);
    this.totalBytes -= c.bytes;
  }
}
