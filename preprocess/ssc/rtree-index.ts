// The chunk index: an R-tree packed bottom-up from the chunks in the order of their plan (the
// split's, chunking.ts: neighbours in the split are neighbours here), 16 children a node; subtrees
// that would make a file too large go to sub-index files of their own.
import { encodeSubIndex, type Box3, type ChunkLeaf, type IndexNode, type InnerNode } from '../../format/cube-index.js';

export const FANOUT = 16;

function union(boxes: Box3[]): Box3 {
  const b: Box3 = [Infinity, Infinity, Infinity, -Infinity, -Infinity, -Infinity];
  for (const c of boxes) {
    for (let i = 0; i < 3; i++) {
      b[i] = Math.min(b[i]!, c[i]!);
      b[i + 3] = Math.max(b[i + 3]!, c[i + 3]!);
    }
  }
  return b;
}

/** The tree over the leaves (in their given order); the root is always an inner node. */
export function packTree(leaves: ChunkLeaf[]): InnerNode {
  let level: IndexNode[] = leaves;
  do {
    const next: InnerNode[] = [];
    for (let i = 0; i < level.length; i += FANOUT) {
      const children = level.slice(i, i + FANOUT);
      next.push({ bbox: union(children.map((c) => c.bbox)), children });
    }
    level = next;
  } while (level.length > 1);
  return level[0] as InnerNode;
}

export interface SubIndexFile {
  name: string;
  json: string;
}

const countChunks = (n: IndexNode): number => ('file' in n ? 1 : 'ref' in n ? n.chunks : n.children.reduce((a, c) => a + countChunks(c), 0));

/** `child` written to a sub-index file of its own (added to `files`): the reference that takes its place. */
function moveOut(child: InnerNode, files: SubIndexFile[], name: (json: string) => string): IndexNode {
  const json = encodeSubIndex(child);
  const file = name(json);
  files.push({ name: file, json });
  return { bbox: child.bbox, ref: file, chunks: countChunks(child) };
}

/**
 * Moves subtrees out to sub-index files, bottom-up: wherever a node written inline would exceed
 * `maxBytes` of JSON, its largest inline children go to files of their own until it fits.
 * `name(json)` gives a content-hashed file name.
 */
export function splitTree(root: InnerNode, maxBytes: number, name: (json: string) => string): { root: InnerNode; files: SubIndexFile[] } {
  const files: SubIndexFile[] = [];
  const visit = (n: InnerNode): InnerNode => {
    const inner: InnerNode = { bbox: n.bbox, children: n.children.map((c) => ('children' in c ? visit(c) : c)) };
    for (;;) {
      if (JSON.stringify(inner).length <= maxBytes) return inner;
      let biggest = -1, biggestLen = 0;
      inner.children.forEach((c, i) => {
        if (!('children' in c)) return;
        const len = JSON.stringify(c).length;
        if (len > biggestLen) {
          biggest = i;
          biggestLen = len;
        }
      });
      if (biggest < 0) return inner;
      inner.children[biggest] = moveOut(inner.children[biggest] as InnerNode, files, name);
    }
  };
  return { root: visit(root), files };
}

/**
 * The root's inline inner children moved out to sub-index files too (`split` as splitTree gave
 * it): index.json then holds only the root's boxes. For a cube with floor chunks, whose first
 * map at the floor needs the floor's tree alone (docs/FORMAT.md, "index.json", has the figures).
 */
export function rootOutOfLine(split: { root: InnerNode; files: SubIndexFile[] }, name: (json: string) => string): { root: InnerNode; files: SubIndexFile[] } {
  const files = [...split.files];
  const children = split.root.children.map((c) => ('children' in c ? moveOut(c, files, name) : c));
  return { root: { bbox: split.root.bbox, children }, files };
}
