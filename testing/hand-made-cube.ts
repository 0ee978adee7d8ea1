// Small cubes made by hand for the map's source tests: real chunk files (format/chunk.ts),
// index leaves that name their files freely and carry their true SHA-256 (index version 1, which
// the readers still read; `namedLeaf` makes a leaf as the build writes it now), a valid
// index.json, and a fake-fetch answer that serves the files under a base URL.
import { createHash } from 'node:crypto';
import { encodeChunk } from '../format/chunk-encode.js';
import { encodeIndex, encodeSubIndex, hashedName, type Box3, type ChunkLeaf, type CubeIndexJson, type IndexNode, type InnerNode } from '../format/cube-index.js';
import { body, status, type Answer } from './fake-fetch.js';

export const sha256 = (bytes: Uint8Array): string => createHash('sha256').update(bytes).digest('hex');

/**
 * A unit square of two triangles: [0, 2, 1] faces down (clockwise seen from above), [0, 2, 3]
 * faces up. `n` shifts the origin so that every chunk's bytes (and hash) differ.
 */
export function squareChunk(n = 0): Uint8Array {
  return encodeChunk({
    originX: 1000 + n,
    originY: 2000,
    box: new Float32Array([0, 0, 0, 1, 1, 10]),
    positions: new Float32Array([0, 0, 0, 1, 0, 0, 1, 1, 10, 0, 1, 10]),
    upper: new Uint32Array([5, 5, 5, 5]),
    lower: new Uint32Array([0, 0, 0, 0]),
    upperClass: new Uint16Array([1, 1, 1, 1]),
    lowerClass: new Uint16Array([0xffff, 0xffff, 0xffff, 0xffff]),
    indices: new Uint16Array([0, 2, 1, 0, 2, 3]),
  });
}

/** The index leaf (version 1: any name, the whole SHA-256) for a chunk file with these bytes. */
export function leafFor(file: string, bbox: Box3, bytes: Uint8Array): ChunkLeaf {
  return { bbox, file, bytes: bytes.byteLength, triangles: 2, sha256: sha256(bytes) };
}

/** The index leaf as the build writes it (version 2): the file named by its SHA-256, no digest beside. */
export function namedLeaf(bbox: Box3, bytes: Uint8Array): ChunkLeaf {
  return { bbox, file: hashedName('c', sha256(bytes), 'bin'), bytes: bytes.byteLength, triangles: 2 };
}

/** The box around some nodes' boxes. */
export function boxAround(nodes: IndexNode[]): Box3 {
  const b: Box3 = [Infinity, Infinity, Infinity, -Infinity, -Infinity, -Infinity];
  for (const n of nodes) {
    for (let i = 0; i < 3; i++) {
      b[i] = Math.min(b[i]!, n.bbox[i]!);
      b[i + 3] = Math.max(b[i + 3]!, n.bbox[i + 3]!);
    }
  }
  return b;
}

/** The bytes of an index.json over this tree (and floor chunks), with the least metadata the schema allows. */
export function indexFile(root: InnerNode, floor?: CubeIndexJson['floor']): Uint8Array {
  const index: CubeIndexJson = {
    format: 'ssc-index',
    version: 1,
    meta: {
      name: 'hand-made',
      extent: [root.bbox[0], root.bbox[1], root.bbox[3], root.bbox[4]],
      zMax: root.bbox[5],
      steps: root.bbox[5],
      baseScale: 1000,
      baseFaces: 10,
      scaleTable: [[0, 10], [root.bbox[5], 1]],
      style: { classes: { land: { color: '#88aa66' } } },
      faces: { count: 0, pageSize: 1, pages: [] },
      attributes: { count: 0, pageSize: 1, pages: [] },
    },
    root,
    ...(floor ? { floor } : {}),
  };
  return encodeIndex(index);
}

export const subIndexFile = (node: InnerNode): Uint8Array => new TextEncoder().encode(encodeSubIndex(node));

/** One chunk of the cube: its file name and box; its bytes are squareChunk(i) for the i-th. */
export interface ChunkSpec {
  file: string;
  bbox: Box3;
}

export interface HandMadeCube {
  leaves: Map<string, ChunkLeaf>;
  /** File name to bytes: index.json and every chunk. */
  files: Map<string, Uint8Array>;
}

/**
 * A cube whose index.json lists these chunks directly under its root, and `floor.chunks` as
 * floor chunks below `floor.top` (docs/FORMAT.md, "Floor chunks"). With `subIndex`, the root
 * refers to a sub-index file of that name, which lists the chunks, as the build writes a cube
 * with floor chunks; with `floor.subIndex`, the floor's root likewise (a floor too large for
 * index.json).
 */
export function handMadeCube(chunks: ChunkSpec[], floor?: { top: number; chunks: ChunkSpec[]; subIndex?: string }, subIndex?: string): HandMadeCube {
  const files = new Map<string, Uint8Array>();
  const leaves = new Map<string, ChunkLeaf>();
  const add = (specs: ChunkSpec[]): ChunkLeaf[] =>
    specs.map((c) => {
      const bytes = squareChunk(files.size);
      files.set(c.file, bytes);
      const leaf = leafFor(c.file, c.bbox, bytes);
      leaves.set(c.file, leaf);
      return leaf;
    });
  const children = add(chunks);
  const floorLeaves = add(floor?.chunks ?? []);
  // A tree whose leaves move to a sub-index file of that name, when given.
  const tree = (leaves: ChunkLeaf[], sub?: string): InnerNode => {
    const node: InnerNode = { bbox: boxAround(leaves), children: leaves };
    if (!sub) return node;
    files.set(sub, subIndexFile(node));
    return { bbox: node.bbox, children: [{ bbox: node.bbox, ref: sub, chunks: leaves.length }] };
  };
  const floorRoot = floor ? { top: floor.top, root: tree(floorLeaves, floor.subIndex) } : undefined;
  files.set('index.json', indexFile(tree(children, subIndex), floorRoot));
  return { leaves, files };
}

/**
 * A cube with a sub-index: its root holds c-a.bin (x 0..10) and refers to i-b.json (x 10..20),
 * which holds c-b.bin.
 */
export function twoLevelCube(): HandMadeCube {
  const aBytes = squareChunk(0), bBytes = squareChunk(1);
  const a = leafFor('c-a.bin', [0, 0, 0, 10, 10, 100], aBytes);
  const b = leafFor('c-b.bin', [10, 0, 0, 20, 10, 100], bBytes);
  const sub: InnerNode = { bbox: b.bbox, children: [b] };
  const root: InnerNode = { bbox: boxAround([a, b]), children: [a, { bbox: sub.bbox, ref: 'i-b.json', chunks: 1 }] };
  const files = new Map([['index.json', indexFile(root)], ['i-b.json', subIndexFile(sub)], [a.file, aBytes], [b.file, bBytes]]);
  return { leaves: new Map([[a.file, a], [b.file, b]]), files };
}

/** Answers requests under `base` with the files, whatever the query string (404 for any other). */
export function serveFiles(base: string, files: Map<string, Uint8Array>): (url: string) => Answer {
  return (url) => {
    const bytes = url.startsWith(base) ? files.get(url.slice(base.length).split('?')[0]!) : undefined;
    return bytes ? body(bytes) : status(404);
  };
}
