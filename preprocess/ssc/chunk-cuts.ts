// Where a set of triangles, sorted along one axis, may be cut in two for the chunk split, and
// the boxes the two sides of each cut would have.
import type { Box6 } from './view-hit-chance.js';

/** Each triangle's ground box and z range, by triangle index. */
export interface TriangleBoxes {
  x0: Float64Array;
  y0: Float64Array;
  x1: Float64Array;
  y1: Float64Array;
  /** The z the triangle appears at, and the z it is covered from. */
  z0: Float64Array;
  z1: Float64Array;
}

/** A cut before position `at` of the sorted list, meant to leave `kl` chunks' worth on its left. */
export interface CandidateCut {
  at: number;
  kl: number;
}

/** A set of triangles, list[lo .. hi), sorted along one axis, to be split into k chunks. */
export interface SortedRange {
  list: Uint32Array;
  key: (i: number) => number;
  lo: number;
  hi: number;
  k: number;
  /** Bytes of the triangles in the range. */
  bytes: number;
}

/**
 * Candidate cuts: at each whole number of chunks' worth of bytes (at most 15 of them), moved
 * to where the key changes when that is near (a set of equal keys, say every triangle
 * appearing at z = 0, is then not cut through).
 */
export function candidateCuts(r: SortedRange, cost: Float64Array): CandidateCut[] {
  const { list, key, lo, hi, k, bytes } = r;
  const js: number[] = [];
  const step = Math.max(1, Math.floor((k - 1) / 15));
  for (let j = 1; j < k; j += step) js.push(j);
  if (js[js.length - 1] !== k - 1) js.push(k - 1);
  const cuts: CandidateCut[] = [];
  let acc = 0, at = lo;
  const cum: number[] = [];
  for (const j of js) {
    const want = (bytes * j) / k;
    while (at < hi - 1 && acc + cost[list[at]!]! / 2 < want) acc += cost[list[at++]!]!;
    cum.push(at);
  }
  const slack = Math.max(1, Math.floor((hi - lo) / (8 * k)));
  js.forEach((j, ji) => {
    let c = Math.max(lo + 1, cum[ji]!);
    // Look a little either way for a change of key.
    const kc = key(list[c - 1]!);
    if (key(list[c]!) === kc) {
      let f = c, b = c;
      while (f < Math.min(hi - 1, c + slack) && key(list[f]!) === kc) f++;
      while (b > Math.max(lo + 1, c - slack) && key(list[b - 1]!) === key(list[b]!)) b--;
      if (key(list[f - 1]!) !== key(list[f]!)) c = f;
      else if (key(list[b - 1]!) !== key(list[b]!)) c = b;
    }
    cuts.push({ at: c, kl: j });
  });
  return cuts;
}

/** The box and bytes left of each cut and the box right of it: one pass forward, one backward. */
export function sideBoxes(
  r: SortedRange, cuts: CandidateCut[], boxes: TriangleBoxes, cost: Float64Array,
): { leftBox: Box6[]; rightBox: Box6[]; leftBytes: number[] } {
  const { list, lo, hi } = r;
  const order = cuts.map((_, i) => i).sort((p, q) => cuts[p]!.at - cuts[q]!.at);
  const leftBox: Box6[] = [], rightBox: Box6[] = [], leftBytes: number[] = [];
  {
    const grow = new BoxGrower(boxes);
    let sum = 0;
    let kk = lo;
    for (const ci of order) {
      for (; kk < cuts[ci]!.at; kk++) {
        const i = list[kk]!;
        grow.add(i);
        sum += cost[i]!;
      }
      leftBox[ci] = grow.box();
      leftBytes[ci] = sum;
    }
  }
  {
    const grow = new BoxGrower(boxes);
    let kk = hi - 1;
    for (let oi = order.length - 1; oi >= 0; oi--) {
      const ci = order[oi]!;
      for (; kk >= cuts[ci]!.at; kk--) grow.add(list[kk]!);
      rightBox[ci] = grow.box();
    }
  }
  return { leftBox, rightBox, leftBytes };
}

/** The box around the triangles added so far (empty: inverted infinities). */
class BoxGrower {
  private x0 = Infinity;
  private y0 = Infinity;
  private x1 = -Infinity;
  private y1 = -Infinity;
  private z0 = Infinity;
  private z1 = -Infinity;

  constructor(private readonly b: TriangleBoxes) {}

  add(i: number): void {
    const b = this.b;
    if (b.x0[i]! < this.x0) this.x0 = b.x0[i]!;
    if (b.x1[i]! > this.x1) this.x1 = b.x1[i]!;
    if (b.y0[i]! < this.y0) this.y0 = b.y0[i]!;
    if (b.y1[i]! > this.y1) this.y1 = b.y1[i]!;
    if (b.z0[i]! < this.z0) this.z0 = b.z0[i]!;
    if (b.z1[i]! > this.z1) this.z1 = b.z1[i]!;
  }

  box(): Box6 {
    return [this.x0, this.y0, this.x1, this.y1, this.z0, this.z1];
  }
}
