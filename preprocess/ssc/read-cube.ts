// Reading a cube directory the way the map does: index.json, sub-index files on demand, and
// chunks and line chunks checked against the index's SHA-256 before they are decoded.
import { createHash } from 'node:crypto';
import { promises as fs } from 'node:fs';
import path from 'node:path';
import type { DecodedChunk } from '../../format/chunk.js';
import { decodeSurfaceFile } from '../../format/surface-file.js';
import { decodeFacePage } from '../../format/face-page.js';
import { expectedDigest, parseIndex, parseSubIndex, type ChunkLeaf, type CubeIndex, type InnerNode, type LineChunkLeaf } from '../../format/cube-index.js';
import { EVERYWHERE, queryIndex, queryLineChunks, type QueryBox } from '../../format/index-query.js';
import { decodeLineChunk, type LineChunkData } from '../../format/line-chunk.js';
import { InputError } from '../io/errors.js';

export class CubeReader {
  private readonly subs = new Map<string, InnerNode>();
  /** Sub-index files read so far. */
  subIndexFiles = 0;

  private constructor(readonly dir: string, readonly index: CubeIndex) {}

  static async open(dir: string): Promise<CubeReader> {
    const file = path.join(dir, 'index.json');
    let text: string;
    try {
      text = await fs.readFile(file, 'utf8');
    } catch (err) {
      throw new InputError(`cannot read the cube's index: ${(err as Error).message}`, { file });
    }
    try {
      return new CubeReader(dir, parseIndex(JSON.parse(text)));
    } catch (err) {
      throw new InputError(`is not a valid cube index: ${(err as Error).message}`, { file });
    }
  }

  /**
   * The chunks whose boxes meet the query, reading sub-index files as the query reaches them:
   * in the cube's tree, or in `root` (the floor chunks' tree).
   */
  async query(q: QueryBox, root: InnerNode = this.index.root): Promise<ChunkLeaf[]> {
    for (;;) {
      const r = queryIndex(root, q, (ref) => this.subs.get(ref));
      if (r.missing.length === 0) return r.leaves;
      for (const ref of r.missing) await this.loadSub(ref);
    }
  }

  /** Every sub-index file of the cube's tree (or of `root`, the floor chunks'), so that queries run without reading anything; returns every chunk. */
  loadAll(root: InnerNode = this.index.root): Promise<ChunkLeaf[]> {
    return this.query(EVERYWHERE, root);
  }

  /** The node of a sub-index file read so far. */
  loadedSub(ref: string): InnerNode | undefined {
    return this.subs.get(ref);
  }

  /** Synchronous query over what is loaded (after loadAll of the same tree). */
  queryLoaded(q: QueryBox, root: InnerNode = this.index.root): ChunkLeaf[] {
    return queryIndex(root, q, (ref) => this.subs.get(ref)).leaves;
  }

  private async loadSub(ref: string): Promise<void> {
    const file = path.join(this.dir, ref);
    let json: unknown;
    try {
      json = JSON.parse(await fs.readFile(file, 'utf8'));
    } catch (err) {
      throw new InputError(`cannot read sub-index: ${(err as Error).message}`, { file });
    }
    try {
      this.subs.set(ref, parseSubIndex(json, ref));
    } catch (err) {
      throw new InputError(`is not a valid sub-index: ${(err as Error).message}`, { file });
    }
    this.subIndexFiles++;
  }

  async chunk(leaf: ChunkLeaf): Promise<DecodedChunk> {
    return this.checkedFile(leaf, 'chunk', decodeSurfaceFile);
  }

  /**
   * Each face's end as a step, by face id: its stepHigh (at or just above the z where it ends),
   * Infinity for a face alive to the top of the cube; from the face pages.
   */
  async faceEnds(): Promise<Float64Array> {
    const meta = this.index.meta;
    const ends = new Float64Array(meta.faces.count).fill(Infinity);
    for (const p of meta.faces.pages) {
      const page = await this.decodedFile(p.file, 'face page', (bytes) => decodeFacePage(Uint8Array.from(bytes).buffer));
      for (let i = 0; i < page.count && page.first + i < ends.length; i++) {
        if (page.stepHigh[i]! <= meta.steps) ends[page.first + i] = page.stepHigh[i]!;
      }
    }
    return ends;
  }

  /** The line chunks whose boxes meet the query (none in a cube without lines). */
  lineChunks(q: QueryBox): LineChunkLeaf[] {
    return queryLineChunks(this.index.lines ?? [], q);
  }

  async lineChunk(leaf: LineChunkLeaf): Promise<LineChunkData> {
    return this.checkedFile(leaf, 'line chunk', decodeLineChunk);
  }

  /** A file of the index read, checked against the index's size and its SHA-256 against its name (or the index's), and decoded. */
  private checkedFile<T>(leaf: { file: string; bytes: number; sha256?: string | undefined }, kind: string, decode: (bytes: Uint8Array, name: string) => T | Promise<T>): Promise<T> {
    return this.decodedFile(leaf.file, kind, decode, (bytes, file) => {
      if (bytes.length !== leaf.bytes) throw new InputError(`is ${bytes.length} bytes; the index says ${leaf.bytes} (truncated or replaced)`, { file });
      const sha = createHash('sha256').update(bytes).digest('hex');
      if (!sha.startsWith(expectedDigest(leaf))) throw new InputError(`is corrupt: its SHA-256 does not match ${leaf.sha256 ? 'the index' : 'its name'}`, { file });
    });
  }

  /** A file of the cube read, checked by `check` where given, and decoded; every failure names the file. */
  private async decodedFile<T>(name: string, kind: string, decode: (bytes: Uint8Array, name: string) => T | Promise<T>, check?: (bytes: Buffer, file: string) => void): Promise<T> {
    const file = path.join(this.dir, name);
    let bytes: Buffer;
    try {
      bytes = await fs.readFile(file);
    } catch (err) {
      throw new InputError(`cannot read ${kind}: ${(err as Error).message}`, { file });
    }
    check?.(bytes, file);
    try {
      return await decode(new Uint8Array(bytes.buffer, bytes.byteOffset, bytes.byteLength), name);
    } catch (err) {
      throw new InputError(`is not a valid ${kind}: ${(err as Error).message}`, { file });
    }
  }
}
