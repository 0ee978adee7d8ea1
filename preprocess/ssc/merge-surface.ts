// A merge's surface in a built set of surfaces (issue 11's checks): the triangles over which the
// winner takes the loser's area during the merge's transition, and the loser's boundary with
// the winner as the tGAP has it just before the merge. Found from the surfaces and the tGAP
// alone, so the checks hold whichever way the build shapes the transition.
import { replacedFaces, resolveFace, type Tgap } from '../../format/tgap-model.js';
import type { MergeTransition, Surfaces } from './surfaces.js';

/**
 * Per transition, the indices of its triangles in `s` (the build states which they are: a
 * simplification of the loser's boundary with the winner has the same faces, and may now lie
 * inside the transition's z range, but it is an event of its own).
 */
export function mergeTriangles(s: Surfaces, transitions: readonly MergeTransition[], t?: Pick<Tgap, 'faces'>): number[][] {
  const replaced = t ? replacedFaces(t.faces) : undefined;
  return transitions.map(({ first, end, loser, into, carries, shownAs }) => {
    if (!(first >= 0 && first <= end && end <= s.count)) throw new Error(`merge of ${loser} into ${into}: triangles ${first}..${end} not in the surfaces (${s.count})`);
    // A loser given to a face held back in the winner (shownAs) is taken by that face.
    const winner = shownAs !== undefined ? new Set([shownAs]) : replaced ? winnerIds(replaced, into) : new Set([into]);
    const out: number[] = [];
    for (let i = first; i < end; i++) {
      if ((s.lower[i] !== loser && !carries?.includes(s.lower[i]!)) || !winner.has(s.upper[i]!)) throw new Error(`merge of ${loser} into ${into}: triangle ${i} is between ${s.lower[i]} and ${s.upper[i]}`);
      out.push(i);
    }
    return out;
  });
}

/**
 * The winner's ids: `into` and the faces it replaced by re-emits (same class and attributes),
 * for the part a smooth merge has taken before the winner's re-emit shows the id it had then.
 */
export function winnerIds(replaced: ReadonlyMap<number, number>, into: number): Set<number> {
  const ids = new Set([into]);
  for (let g = replaced.get(into); g !== undefined && !ids.has(g); g = replaced.get(g)) ids.add(g);
  return ids;
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
