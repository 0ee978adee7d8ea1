// A centreline graph as polylines: a path runs between ends, ports and points where three or
// more pieces meet; a loop with none of those (a ring road) is one closed path. Then points
// that lie on the straight line between their neighbours (within a tolerance far below the
// area's width) are dropped: a straight strip's axis has a point per triangle.
import { pointSegmentDistance } from '../../format/point-segment.js';
import type { AxisGraph } from './axis-graph.js';

/** Node sequences of the graph's paths, in node order (a closed path repeats its first node). */
export function tracePaths(g: AxisGraph): number[][] {
  const used = new Set<number>();
  const key = (a: number, b: number): number => Math.min(a, b) * g.size + Math.max(a, b);
  const paths: number[][] = [];
  const walk = (from: number, to: number): number[] => {
    const path = [from];
    let prev = from, cur = to;
    for (;;) {
      used.add(key(prev, cur));
      path.push(cur);
      if (isEnd(g, cur)) return path;
      const next = g.adj[cur]!.find((m) => !used.has(key(cur, m)));
      if (next === undefined) return path;
      prev = cur;
      cur = next;
    }
  };
  for (let n = 0; n < g.size; n++) {
    if (!isEnd(g, n)) continue;
    for (const m of g.adj[n]!) if (!used.has(key(n, m))) paths.push(walk(n, m));
  }
  for (let n = 0; n < g.size; n++) {
    for (const m of g.adj[n]!) if (!used.has(key(n, m))) paths.push(walk(n, m));
  }
  return paths;
}

function isEnd(g: AxisGraph, n: number): boolean {
  const d = g.degree(n);
  return d > 0 && (d !== 2 || g.port[n]!);
}

/**
 * Douglas-Peucker on a node path: keeps its ends and every point farther than `tol` from the
 * chord that would replace it. Returns flat x, y pairs.
 */
export function simplifyPath(g: AxisGraph, path: number[], tol: number): Float64Array {
  const keep = new Uint8Array(path.length);
  keep[0] = 1;
  keep[path.length - 1] = 1;
  const stack: [number, number][] = [[0, path.length - 1]];
  while (stack.length > 0) {
    const [i, j] = stack.pop()!;
    let worst = -1, worstD = tol;
    for (let k = i + 1; k < j; k++) {
      const d = distToSegment(g, path[k]!, path[i]!, path[j]!);
      if (d > worstD) {
        worstD = d;
        worst = k;
      }
    }
    if (worst < 0) continue;
    keep[worst] = 1;
    stack.push([i, worst], [worst, j]);
  }
  const out: number[] = [];
  path.forEach((n, k) => {
    const x = g.xs[n]!, y = g.ys[n]!;
    // A port that is also an axis point adds a piece of no length.
    if (keep[k] && !(out.length > 0 && out[out.length - 2] === x && out[out.length - 1] === y)) out.push(x, y);
  });
  return Float64Array.from(out);
}

function distToSegment(g: AxisGraph, p: number, a: number, b: number): number {
  return pointSegmentDistance(g.xs[p]!, g.ys[p]!, g.xs[a]!, g.ys[a]!, g.xs[b]!, g.ys[b]!);
}

