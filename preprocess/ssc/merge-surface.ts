// A merge's surface in a built set of surfaces (issue 11's checks): the triangles over which the
// winner takes the loser's area during the merge's transition, and the loser's boundary with
// the winner as the tGAP has it just before the merge. Found from the surfaces and the tGAP
// alone, so the checks hold whichever way the build shapes the transition.
import { resolveFace, type Tgap } from '../../format/tgap-model.js';
import type { MergeTransition, Surfaces } from './surfaces.js';

/**
 * Per transition, the indices of its triangles in `s`: lower face the loser, upper the winner,
 * inside [zStart, zMerge] and above zStart somewhere (a simplification of their common boundary
 * may lie flat at zStart itself: it is what bounds the start, not part of the merge).
 */
export function mergeTriangles(s: Surfaces, transitions: readonly MergeTransition[]): number[][] {
  const byLoser = new Map<number, number[]>();
  transitions.forEach((m, i) => {
    if (byLoser.has(m.loser)) throw new Error(`face ${m.loser} loses two merges (transitions ${byLoser.get(m.loser)![0]} and ${i})`);
    byLoser.set(m.loser, [i]);
  });
  const out = transitions.map((): number[] => []);
  for (let i = 0; i < s.count; i++) {
    const m = byLoser.get(s.lower[i]!)?.[0];
    if (m === undefined) continue;
    const { into, zStart, zMerge } = transitions[m]!;
    if (s.upper[i] !== into) continue;
    const z0 = s.z[3 * i]!, z1 = s.z[3 * i + 1]!, z2 = s.z[3 * i + 2]!;
    const lo = Math.min(z0, z1, z2), hi = Math.max(z0, z1, z2);
    if (lo >= zStart && hi > zStart && hi <= zMerge) out[m]!.push(i);
  }
  return out;
}

/** Per transition, the vertices of the edges between loser and winner in the state before the merge. */
export function sharedBoundaries(t: Tgap, transitions: readonly MergeTransition[], tris: readonly number[][], s: Surfaces): Set<number>[] {
  // The edges (of any state) through each vertex.
  const edgesAt = new Map<number, number[]>();
  t.edges.forEach((e, i) => {
    for (const v of e.verts) {
      let l = edgesAt.get(v);
      if (!l) edgesAt.set(v, (l = []));
      if (l[l.length - 1] !== i) l.push(i);
    }
  });
  return transitions.map((m, k) => {
    const state = m.step - 1;
    const shared = new Set<number>();
    const tried = new Set<number>();
    for (const i of tris[k]!) {
      for (let j = 0; j < 3; j++) {
        for (const e of edgesAt.get(s.v[3 * i + j]!) ?? []) {
          if (tried.has(e)) continue;
          tried.add(e);
          const edge = t.edges[e]!;
          if (edge.stepLow > state || edge.stepHigh <= state) continue;
          const l = resolveFace(t.faces, edge.left, state), r = resolveFace(t.faces, edge.right, state);
          if ((l === m.loser && r === m.into) || (l === m.into && r === m.loser)) for (const v of edge.verts) shared.add(v);
        }
      }
    }
    return shared;
  });
}
