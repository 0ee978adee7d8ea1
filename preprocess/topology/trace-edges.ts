// Edges of the partition: nodes are the vertices where other than two segments meet, and an
// edge is the chain of segments from one node to the next, with one face on either side.
import type { HalfEdges } from './half-edges.js';
import type { TopoEdge } from './topology-types.js';

export function traceEdges(he: HalfEdges, nv: number): { edges: TopoEdge[]; nodeCount: number } {
  const { from: fromAll, to: toAll, face: faceAll, twin, count: nh, out: outAll } = he;
  const degree = new Int32Array(nv);
  for (let h = 0; h < nh; h++) degree[fromAll[h]!]!++;
  const isNode = new Uint8Array(nv);
  let nodeCount = 0;
  for (let v = 0; v < nv; v++) {
    if (degree[v]! > 0 && degree[v] !== 2) {
      isNode[v] = 1;
      nodeCount++;
    }
  }
  const edges: TopoEdge[] = [];
  const visited = new Uint8Array(nh);
  const nextAlong = (h: number): number => {
    // At a vertex of degree 2 the chain continues on the outgoing half-edge that is not the way back.
    const v = toAll[h]!;
    const s = outAll.start[v]!;
    const g = outAll.list[s]!;
    return g === twin[h] ? outAll.list[s + 1]! : g;
  };
  const trace = (h0: number): void => {
    const verts: number[] = [fromAll[h0]!];
    let h = h0;
    for (;;) {
      visited[h] = 1;
      visited[twin[h]!] = 1;
      const v = toAll[h]!;
      verts.push(v);
      if (isNode[v] || v === fromAll[h0]) break;
      h = nextAlong(h);
    }
    edges.push({ start: verts[0]!, end: verts[verts.length - 1]!, left: faceAll[h0]!, right: faceAll[twin[h0]!]!, verts: Int32Array.from(verts) });
  };
  for (let h = 0; h < nh; h++) if (!visited[h] && isNode[fromAll[h]!]) trace(h);
  // Rings without any node (an island, or a face inside one other face): one loop edge each,
  // starting at its first vertex, which becomes a node.
  for (let h = 0; h < nh; h++) {
    if (visited[h]) continue;
    isNode[fromAll[h]!] = 1;
    nodeCount++;
    trace(faceAll[h] === 0 ? twin[h]! : h);
  }
  return { edges, nodeCount };
}
