// The chunks a view needs: R-tree leaves whose box meets the view's ground box and the z range
// of its slicing surface (docs/FORMAT.md: z0 <= zMax and z1 > zMin), and the line chunks by the
// same rule. Sub-index files not yet loaded are reported, so the caller can fetch them and ask
// again. Pure and synchronous.
import { isExternal, isLeaf, type Box3, type ChunkLeaf, type IndexNode, type InnerNode, type LineChunkLeaf } from './cube-index.js';

export interface QueryBox {
  /** Ground box x0, y0, x1, y1. */
  ground: [number, number, number, number];
  zMin: number;
  zMax: number;
}

export interface QueryResult {
  leaves: ChunkLeaf[];
  /** Sub-index files (refs) the query reached but that are not loaded. */
  missing: string[];
  /** Nodes visited (for measuring). */
  visited: number;
}

/** A query every box meets: the whole ground, every z. */
export const EVERYWHERE: QueryBox = { ground: [-Infinity, -Infinity, Infinity, Infinity], zMin: -Infinity, zMax: Infinity };

export function boxMeets(b: Box3, q: QueryBox): boolean {
  return b[0] <= q.ground[2] && b[3] >= q.ground[0] && b[1] <= q.ground[3] && b[4] >= q.ground[1] && b[2] <= q.zMax && b[5] > q.zMin;
}

export function queryIndex(root: InnerNode, q: QueryBox, loaded: (ref: string) => InnerNode | undefined): QueryResult {
  const leaves: ChunkLeaf[] = [];
  const missing: string[] = [];
  let visited = 0;
  const stack: IndexNode[] = [root];
  while (stack.length > 0) {
    const n = stack.pop()!;
    visited++;
    if (!boxMeets(n.bbox, q)) continue;
    if (isLeaf(n)) leaves.push(n);
    else if (isExternal(n)) {
      const sub = loaded(n.ref);
      if (sub) stack.push(sub);
      else missing.push(n.ref);
    } else {
      for (const c of n.children) stack.push(c);
    }
  }
  return { leaves, missing, visited };
}

/**
 * A priority for fetching: 0 for a box under the view centre at the view's z, growing with the
 * ground distance (in view half-diagonals) and the z distance (in units of zScale).
 */
export function chunkPriority(b: Box3, cx: number, cy: number, z: number, halfDiagonal: number, zScale: number): number {
  const dx = Math.max(b[0] - cx, 0, cx - b[3]);
  const dy = Math.max(b[1] - cy, 0, cy - b[4]);
  const dz = Math.max(b[2] - z, 0, z - b[5]);
  return Math.hypot(dx, dy) / Math.max(halfDiagonal, 1e-9) + dz / Math.max(zScale, 1e-9);
}

/** chunkPriority for a view with ground box `box`, its centre and base z and its z range: nearest first. */
export function viewPriority(b: Box3, box: readonly [number, number, number, number], v: { centerX: number; centerY: number; z: number; zMin: number; zMax: number }): number {
  const halfDiag = Math.hypot(box[2] - box[0], box[3] - box[1]) / 2;
  return chunkPriority(b, v.centerX, v.centerY, v.z, halfDiag, Math.max(1, v.zMax - v.zMin));
}

/** The line chunks a view needs: those whose box meets the view's, by the chunks' rule. */
export function queryLineChunks(lines: readonly LineChunkLeaf[], q: QueryBox): LineChunkLeaf[] {
  return lines.filter((l) => boxMeets(l.bbox, q));
}
