// Dense local numbers for the vertices of one face, and their coordinates moved near the
// origin (triangulators work best on small numbers; national grids are in the millions).
export class LocalVertices {
  readonly ids: number[] = [];
  private readonly local = new Map<number, number>();

  /** The local number of global vertex v, given on first sight. */
  of(v: number): number {
    let i = this.local.get(v);
    if (i === undefined) {
      i = this.ids.length;
      this.local.set(v, i);
      this.ids.push(v);
    }
    return i;
  }

  /** x, y pairs of the vertices so far, relative to their lower-left corner. */
  coords(xs: Float64Array, ys: Float64Array): Float64Array {
    let x0 = Infinity, y0 = Infinity;
    for (const v of this.ids) {
      x0 = Math.min(x0, xs[v]!);
      y0 = Math.min(y0, ys[v]!);
    }
    const out = new Float64Array(this.ids.length * 2);
    this.ids.forEach((v, i) => {
      out[2 * i] = xs[v]! - x0;
      out[2 * i + 1] = ys[v]! - y0;
    });
    return out;
  }
}
