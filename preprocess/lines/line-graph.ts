// The network of lines as a graph: a line is a node, a join between two lines an edge. A join
// point belongs to exactly two lines (a port and the anchor that took it up), while a
// junction lies inside one line, so a line whose removal would split its network is a cut
// vertex (articulation point) of this graph, not a bridge edge.
import type { LineObject } from './collapse-lines.js';

/** Neighbours of every line through its joins, both ways, each once, in increasing order. */
export function joinAdjacency(lines: readonly Pick<LineObject, 'joins'>[]): number[][] {
  const sets = lines.map(() => new Set<number>());
  lines.forEach((l, i) => {
    for (const j of l.joins) {
      if (j.line < 0 || j.line === i) continue;
      if (j.line >= lines.length) throw new Error(`line ${i}: a join names line ${j.line}, but there are ${lines.length} lines`);
      sets[i]!.add(j.line);
      sets[j.line]!.add(i);
    }
  });
  return sets.map((s) => [...s].sort((a, b) => a - b));
}

/**
 * Lines among the alive ones whose removal would split their connected piece (Tarjan's
 * articulation points, with an explicit stack: a long road is a deep path).
 */
export function cutLines(adj: readonly (readonly number[])[], alive: ArrayLike<number>): Uint8Array {
  const n = adj.length;
  const disc = new Int32Array(n).fill(-1);
  const low = new Int32Array(n);
  const parent = new Int32Array(n).fill(-1);
  const next = new Int32Array(n);
  const cut = new Uint8Array(n);
  let time = 0;
  const stack: number[] = [];
  for (let root = 0; root < n; root++) {
    if (!alive[root] || disc[root]! >= 0) continue;
    let rootChildren = 0;
    disc[root] = low[root] = time++;
    stack.push(root);
    while (stack.length > 0) {
      const v = stack[stack.length - 1]!;
      const nv = adj[v]!;
      if (next[v]! < nv.length) {
        const w = nv[next[v]!++]!;
        if (!alive[w]) continue;
        if (disc[w]! < 0) {
          parent[w] = v;
          disc[w] = low[w] = time++;
          stack.push(w);
          if (v === root) rootChildren++;
        } else if (w !== parent[v]) {
          low[v] = Math.min(low[v]!, disc[w]!);
        }
        continue;
      }
      stack.pop();
      const p = parent[v]!;
      if (p < 0) continue;
      low[p] = Math.min(low[p]!, low[v]!);
      if (p !== root && low[v]! >= disc[p]!) cut[p] = 1;
    }
    if (rootChildren > 1) cut[root] = 1;
  }
  return cut;
}

/** Connected piece of every alive line (numbered from 0 in order of their lowest line), -1 for the others. */
export function lineGraphComponents(adj: readonly (readonly number[])[], alive: ArrayLike<number>): Int32Array {
  const comp = new Int32Array(adj.length).fill(-1);
  let n = 0;
  for (let i = 0; i < adj.length; i++) {
    if (!alive[i] || comp[i]! >= 0) continue;
    comp[i] = n;
    const stack = [i];
    while (stack.length > 0) {
      for (const w of adj[stack.pop()!]!) {
        if (!alive[w] || comp[w]! >= 0) continue;
        comp[w] = n;
        stack.push(w);
      }
    }
    n++;
  }
  return comp;
}
