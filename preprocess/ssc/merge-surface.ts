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
  return transitions.map(({ first, end, loser, into, carries, shownAs, takers }) => {
    if (!(first >= 0 && first <= end && end <= s.count)) throw new Error(`merge of ${loser} into ${into}: triangles ${first}..${end} not in the surfaces (${s.count})`);
    // A loser given to a face held back in the winner (shownAs) is taken by that face, and
    // pieces of it by `takers`.
    const winner = shownAs !== undefined ? new Set([shownAs]) : replaced ? winnerIds(replaced, into) : new Set([into]);
    for (const f of takers ?? []) winner.add(f);
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

/**
 * Per transition, the vertices of the edges between loser and winner in the state before the
 * merge. In a cube's faces (`tgap` of buildSurfaces) a face held back is still there, so the
 * edges beside it are its own: the loser's side includes the held faces its ramp carries on
 * (`carries`), and the winner's the faces held back in it that take the loser (`shownAs`) or
 * pieces of it (`takers`), with the faces those were held back in (`heldIn`: loser -> winner of
 * each held merge): an edge made after a taker's merge bears the face it merged into, though the
 * taker still shows beside it.
 * With the vertices that simplification removed from the edge's earlier versions: a smooth cube
 * may leave a removal out (a sliver handed back), and its corner is still on the boundary.
 */
export function sharedBoundaries(t: Tgap, transitions: readonly MergeTransition[], tris: readonly number[][], s: Surfaces, heldIn: ReadonlyMap<number, number> = new Map()): Set<number>[] {
  // The edges (of any state) through each vertex.
  const edgesAt = new Map<number, number[]>();
  t.edges.forEach((e, i) => {
    for (const v of e.verts) {
      let l = edgesAt.get(v);
      if (!l) edgesAt.set(v, (l = []));
      if (l[l.length - 1] !== i) l.push(i);
    }
  });
  /** Edge e's vertices, and those its earlier versions lost to simplification, into `out` (not kept per edge: sets along a chain of hundreds of versions would grow with its square). */
  const withAncestors = (e: number, out: Set<number>): void => {
    for (const v of t.edges[e]!.verts) out.add(v);
    const seen = new Set<number>();
    const todo = [e];
    while (todo.length > 0) {
      const i = todo.pop()!;
      if (seen.has(i)) continue;
      seen.add(i);
      const edge = t.edges[i]!;
      for (const v of edge.removed) out.add(v);
      for (const p of edge.parents) todo.push(p >= 0 ? p : -p - 1);
    }
  };
  return transitions.map((m, k) => {
    const state = m.step - 1;
    const winning = new Set([m.into]);
    for (const f of [...(m.shownAs !== undefined ? [m.shownAs] : []), ...(m.takers ?? [])]) {
      for (let g: number | undefined = f; g !== undefined && g !== m.into && !winning.has(g); g = heldIn.get(g)) winning.add(g);
    }
    const losing = (f: number): boolean => f === m.loser || (m.carries?.includes(f) ?? false);
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
          const other = losing(l) ? r : losing(r) ? l : -1;
          if (winning.has(other)) withAncestors(e, shared);
        }
      }
    }
    return shared;
  });
}
