// A face of the tGAP at a state: the edges around it then, with the faces across them. The
// tGAP stores edge versions with the faces they had when made; a face's area at state s also
// takes the edges of the faces merged into it (or replaced by it) before s.
import { resolveFace, type Tgap } from '../../format/tgap-model.js';

export interface FaceSide {
  edge: number;
  /** True when the face lies left of the edge (from its first vertex to its last). */
  forward: boolean;
  /** The face across the edge at that state. */
  other: number;
}

export class FaceHistory {
  /** Faces merged into (or replaced by) each face. */
  private readonly children: number[][];
  /** Edge versions with each face on a side, as made. */
  private readonly edgesOf: number[][];

  constructor(private readonly tgap: Tgap) {
    const nf = tgap.faces.length;
    this.children = Array.from({ length: nf }, () => []);
    tgap.faces.forEach((f, i) => {
      if (i > 0 && f.mergedInto > 0) this.children[f.mergedInto]!.push(i);
    });
    this.edgesOf = Array.from({ length: nf }, () => []);
    tgap.edges.forEach((e, i) => {
      if (e.left > 0) this.edgesOf[e.left]!.push(i);
      if (e.right > 0 && e.right !== e.left) this.edgesOf[e.right]!.push(i);
    });
  }

  /** Face f and the faces whose area it holds at state s. */
  heldBy(f: number, s: number): number[] {
    const out: number[] = [];
    const stack = [f];
    while (stack.length > 0) {
      const g = stack.pop()!;
      if (resolveFace(this.tgap.faces, g, s) === f) out.push(g);
      stack.push(...this.children[g]!);
    }
    return out.sort((a, b) => a - b);
  }

  /** The edges around face f at state s (in id order), with the faces across. */
  boundaryAt(f: number, s: number): FaceSide[] {
    const { tgap } = this;
    const seen = new Set<number>();
    const out: FaceSide[] = [];
    for (const g of this.heldBy(f, s)) {
      for (const e of this.edgesOf[g]!) {
        if (seen.has(e)) continue;
        seen.add(e);
        const edge = tgap.edges[e]!;
        if (edge.stepLow > s || edge.stepHigh <= s) continue;
        const l = resolveFace(tgap.faces, edge.left, s), r = resolveFace(tgap.faces, edge.right, s);
        if (l === r) continue;
        if (l === f) out.push({ edge: e, forward: true, other: r });
        else if (r === f) out.push({ edge: e, forward: false, other: l });
      }
    }
    return out.sort((a, b) => a.edge - b.edge);
  }
}
