// After a merge or a split a node may be left with just two edges that bound the same two
// faces: it no longer separates anything, so the two edges are joined into one.
import { EMPTY_U8, type PlanarState } from './planar-state.js';

/** Joins the two edges at node v where only they remain; returns the new edge, or -1 when v stays a node. */
export function dissolveNode(st: PlanarState, v: number): number {
  const list = st.nodeEdges.get(v);
  if (!list || list.length !== 2 || list[0] === list[1]) return -1;
  const e1 = list[0]!, e2 = list[1]!;
  const a = st.edges[e1]!, b = st.edges[e2]!;
  const aEnds = a.end === v; // a runs into v
  const bStarts = b.start === v; // b runs out of v
  const [al, ar] = st.sides(e1);
  const [bl, br] = st.sides(e2);
  const left = aEnds ? al : ar, right = aEnds ? ar : al;
  const bLeft = bStarts ? bl : br, bRight = bStarts ? br : bl;
  if (left !== bLeft || right !== bRight) return -1; // not one boundary: keep the node
  const av = aEnds ? a.verts : a.verts.slice().reverse();
  const bv = bStarts ? b.verts : b.verts.slice().reverse();
  const verts = new Int32Array(av.length + bv.length - 1);
  verts.set(av);
  verts.set(bv.subarray(1), av.length);
  // A parent run backwards is stored as -(id + 1), so the cube can follow the vertex order.
  const parents = Int32Array.of(aEnds ? e1 : -(e1 + 1), bStarts ? e2 : -(e2 + 1));
  st.endEdge(e1);
  st.endEdge(e2);
  return st.addEdge(verts[0]!, verts[verts.length - 1]!, left, right, verts, parents, new Int32Array(0), EMPTY_U8);
}

/** Dissolves each of the nodes (in the given order); returns the edges made by joining. */
export function dissolveNodes(st: PlanarState, nodes: Iterable<number>): number[] {
  const joined: number[] = [];
  for (const v of nodes) {
    const e = dissolveNode(st, v);
    if (e >= 0) joined.push(e);
  }
  return joined;
}
