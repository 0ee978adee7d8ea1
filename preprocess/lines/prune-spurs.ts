// Spurs of a chordal axis: every corner and bulge of an area sends a short branch from the
// axis to the boundary. A branch from a free end (a leaf that is not a port) to the point
// where it leaves the rest of the line is pruned when it is shorter than the area is wide at
// that point: it runs into a corner or a bulge, not along a way of its own (in topographic
// data a side road is a face of its own, and where one is not, it is longer than its road is
// wide). Shortest relative to the width first, so that of two corner spurs at a dead end both
// go and the line ends between them.
import type { AxisGraph } from './axis-graph.js';

interface Spur {
  /** From the leaf to the node before the junction. */
  nodes: number[];
  junction: number;
  ratio: number;
}

/** Prunes spurs in place; `widthAt(node)` is the area's width at a node. Returns how many went. */
export function pruneSpurs(g: AxisGraph, widthAt: (node: number) => number): number {
  let pruned = 0;
  for (;;) {
    const spurs: Spur[] = [];
    for (let n = 0; n < g.size; n++) {
      if (g.degree(n) !== 1 || g.port[n]) continue;
      const s = spurFrom(g, n);
      if (s) {
        s.ratio /= widthAt(s.junction);
        if (s.ratio < 1) spurs.push(s);
      }
    }
    if (spurs.length === 0) return pruned;
    spurs.sort((a, b) => a.ratio - b.ratio || a.nodes[0]! - b.nodes[0]!);
    for (const s of spurs) {
      // Of the spurs at one junction all may go as long as one branch stays: at a dead end both
      // corner spurs go and the line ends at the junction.
      if (g.degree(s.junction) < 2) continue;
      const path = [...s.nodes, s.junction];
      for (let i = 0; i + 1 < path.length; i++) g.unlink(path[i]!, path[i + 1]!);
      pruned++;
    }
  }
}

/** The branch from leaf n to the first node where three or more pieces meet (null: none, a bare path). */
function spurFrom(g: AxisGraph, leaf: number): Spur | null {
  const nodes = [leaf];
  let prev = -1, cur = leaf, length = 0;
  for (;;) {
    const next = g.adj[cur]!.find((m) => m !== prev);
    if (next === undefined) return null;
    length += g.dist(cur, next);
    const d = g.degree(next);
    if (d >= 3) return { nodes, junction: next, ratio: length };
    if (d === 1 || next === leaf) return null;
    nodes.push(next);
    prev = cur;
    cur = next;
  }
}
