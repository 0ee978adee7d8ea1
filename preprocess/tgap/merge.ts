// Merging: the loser's area and edges go to its most compatible neighbour, the winner.
import type { PlanarState } from './planar-state.js';
import { dissolveNodes } from './dissolve-node.js';

export interface MergeTarget {
  /** The winner: the neighbour with the highest shared boundary length x class compatibility (-1: none). */
  best: number;
  /** How many neighbours f has (outside the domain not counted). */
  count: number;
}

/**
 * The neighbour face f merges into: the highest shared boundary length times the
 * compatibility of the two classes, the lower id on a tie (so the result is reproducible).
 */
export function mostCompatibleNeighbour(st: PlanarState, f: number, compat: readonly ArrayLike<number>[]): MergeTarget {
  const shared = new Map<number, number>();
  for (const e of st.faceEdges[f]!) {
    const [l, r] = st.sides(e);
    const o = l === f ? r : l;
    if (o > 0) shared.set(o, (shared.get(o) ?? 0) + st.edgeLength[e]!);
  }
  const cf = st.faces[f]!.classIndex;
  let best = -1, bestScore = -1;
  for (const [o, len] of shared) {
    const score = len * compat[cf]![st.faces[o]!.classIndex]!;
    if (score > bestScore || (score === bestScore && o < best)) {
      best = o;
      bestScore = score;
    }
  }
  return { best, count: shared.size };
}

/**
 * Merges face L into W in the current step: their shared edges end, L's area and its other
 * edges go to W, and nodes left between two edges of one boundary are dissolved. Returns the
 * edges whose lines now bound W and may need simplifying: the joined ones, then L's others.
 * W = 0, the outside, takes a face with no other neighbour: all its edges end, and it leaves
 * the map.
 */
export function mergeFace(st: PlanarState, L: number, W: number): number[] {
  // What the cube drew for L now counts as drawn for W (see reemit).
  if (W > 0) st.faceCost[W]! += st.faceVerts[L]!;
  const removed: number[] = [];
  const kept: number[] = [];
  for (const e of st.faceEdges[L]!) {
    const [l, r] = st.sides(e);
    (l === W || r === W ? removed : kept).push(e);
  }
  // Sets iterate in insertion order, which depends on history: sort for a fixed order.
  removed.sort((p, q) => p - q);
  kept.sort((p, q) => p - q);
  const nodes = new Set<number>();
  for (const e of removed) {
    nodes.add(st.edges[e]!.start);
    nodes.add(st.edges[e]!.end);
    st.endEdge(e);
  }
  if (W > 0) st.faceArea2[W]! += st.faceArea2[L]!;
  st.endFace(L, W);
  const joined = dissolveNodes(st, [...nodes].sort((p, q) => p - q));
  return [...joined, ...kept];
}
