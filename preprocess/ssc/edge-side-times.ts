// Since when each vertex of a tGAP edge has had the face it now has on one of its sides: a
// smooth merge's front may leave a vertex of the boundary the loser shares with the winner only
// once the winner lies beside it. A new version of an edge (its chain simplified, or joined with
// another when a merge removed the boundary between them) keeps its parents' faces, so its
// vertices keep their parents' times; only that side's face changing (a merge, a split, a
// re-emit) or an edge made afresh starts a new time.
import { phaseZ, type TgapEdge } from '../../format/tgap-model.js';

export const enum Side {
  Left = 0,
  Right = 1,
}

export class EdgeSideTimes {
  /** Per edge and side, the latest change of the face on it since the edge was made (its birth when made afresh). */
  private readonly own: Float64Array;
  /**
   * Per edge and side, the z until which a face held back in a cascade (surfaces.ts) still
   * shows there, though the tGAP has merged it into the face on that side.
   */
  private readonly held: Float64Array;
  /** Per edge, side and whether holds count, its parents' vertices' times (parents no longer change). */
  private readonly inherited = new Map<number, Map<number, number>>();

  constructor(private readonly edges: readonly TgapEdge[]) {
    this.own = new Float64Array(2 * edges.length);
    this.held = new Float64Array(2 * edges.length).fill(-Infinity);
    edges.forEach((e, i) => {
      if (e.parents.length === 0 && e.stepLow > 0) this.own.fill(phaseZ(e.stepLow, 0), 2 * i, 2 * i + 2);
    });
  }

  /** The face on edge e's `side` changed at z. */
  relabel(e: number, side: Side, z: number): void {
    this.own[2 * e + side] = Math.max(this.own[2 * e + side]!, z);
  }

  /** The face on edge e's `side` is held back until z: the face the tGAP has there lies beside it from then on. */
  hold(e: number, side: Side, z: number): void {
    this.held[2 * e + side] = Math.max(this.held[2 * e + side]!, z);
  }

  /**
   * Per vertex of edge e, since when the face on its `side` has been there; with `holds` false,
   * since when a face held back there has been (what shows there before the hold ends).
   */
  vertexTimes(e: number, side: Side, holds = true): Map<number, number> {
    const base = this.parentTimes(e, side, holds);
    const own = holds ? Math.max(this.own[2 * e + side]!, this.held[2 * e + side]!) : this.own[2 * e + side]!;
    const out = new Map<number, number>();
    for (const v of this.edges[e]!.verts) out.set(v, Math.max(base.get(v) ?? own, own));
    return out;
  }

  /**
   * Per vertex of edge e's parents (those simplification removed from e too), since when the
   * face on e's `side` has been beside it.
   */
  parentTimes(e: number, side: Side, holds = true): Map<number, number> {
    const key = 2 * (2 * e + side) + (holds ? 1 : 0);
    let m = this.inherited.get(key);
    if (m) return m;
    m = new Map();
    const edge = this.edges[e]!;
    for (const p of edge.parents) {
      // A parent used reversed has its sides swapped.
      const times = p >= 0 ? this.vertexTimes(p, side, holds) : this.vertexTimes(-p - 1, side === Side.Left ? Side.Right : Side.Left, holds);
      for (const [v, t] of times) m.set(v, Math.max(m.get(v) ?? -Infinity, t));
    }
    this.inherited.set(key, m);
    return m;
  }
}
