// The line's way into a port, straightened. Near a port the chordal axis bends: the triangle at
// a gate joins the port to its neighbours' midpoints, which lie off the axis by up to half a
// width. Within `reach` along the line from the port, the farthest point the port sees without
// crossing the boundary is joined to it directly and the bend between goes.
import type { AxisGraph } from './axis-graph.js';

/** `sees(a, b)`: whether the straight piece between nodes a and b stays inside the area. */
export function straightenApproaches(g: AxisGraph, sees: (a: number, b: number) => boolean, reach: number): void {
  for (let p = 0; p < g.size; p++) {
    if (!g.port[p] || g.degree(p) !== 1) continue;
    // Along the line up to the first point where it branches, ends or passes another port.
    const path = [p];
    let prev = -1, cur = p, length = 0;
    for (;;) {
      const next = g.adj[cur]!.find((m) => m !== prev);
      if (next === undefined) break;
      length += g.dist(cur, next);
      if (length > reach) break;
      path.push(next);
      if (g.degree(next) !== 2 || g.port[next]) break;
      prev = cur;
      cur = next;
    }
    for (let k = path.length - 1; k >= 2; k--) {
      if (!sees(p, path[k]!)) continue;
      for (let i = 0; i < k; i++) g.unlink(path[i]!, path[i + 1]!);
      g.link(p, path[k]!);
      break;
    }
  }
}
