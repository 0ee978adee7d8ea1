// Open-addressing hash from exact (x, y) pairs to dense ids: the vertex dictionary of a
// planar partition, without a string key per point.

export class PointHash {
  xs: Float64Array;
  ys: Float64Array;
  size = 0;
  private table: Int32Array;
  private mask: number;
  private readonly f64 = new Float64Array(2);
  private readonly u32 = new Uint32Array(this.f64.buffer);

  constructor(expected = 1024) {
    let cap = 16;
    while (cap < expected * 2) cap <<= 1;
    this.table = new Int32Array(cap).fill(-1);
    this.mask = cap - 1;
    this.xs = new Float64Array(Math.max(16, expected));
    this.ys = new Float64Array(Math.max(16, expected));
  }

  private hash(x: number, y: number): number {
    this.f64[0] = x === 0 ? 0 : x; // -0 and 0 are one point
    this.f64[1] = y === 0 ? 0 : y;
    const u = this.u32;
    let h = Math.imul(u[0]! ^ 0x9e3779b9, 0x85ebca6b) ^ u[1]!;
    h = Math.imul(h ^ (h >>> 13), 0xc2b2ae35) ^ u[2]!;
    h = Math.imul(h ^ (h >>> 16), 0x85ebca6b) ^ u[3]!;
    h ^= h >>> 15;
    return h >>> 0;
  }

  /** The id of (x, y), adding it when new. */
  id(x: number, y: number): number {
    let i = this.hash(x, y) & this.mask;
    for (;;) {
      const v = this.table[i]!;
      if (v < 0) break;
      if (this.xs[v] === x && this.ys[v] === y) return v;
      i = (i + 1) & this.mask;
    }
    const id = this.size++;
    if (id >= this.xs.length) this.growArrays();
    this.xs[id] = x;
    this.ys[id] = y;
    this.table[i] = id;
    if (this.size * 2 > this.table.length) this.rehash();
    return id;
  }

  private growArrays(): void {
    const n = this.xs.length * 2;
    const xs = new Float64Array(n);
    xs.set(this.xs);
    const ys = new Float64Array(n);
    ys.set(this.ys);
    this.xs = xs;
    this.ys = ys;
  }

  private rehash(): void {
    const cap = this.table.length * 2;
    this.table = new Int32Array(cap).fill(-1);
    this.mask = cap - 1;
    for (let v = 0; v < this.size; v++) {
      let i = this.hash(this.xs[v]!, this.ys[v]!) & this.mask;
      while (this.table[i]! >= 0) i = (i + 1) & this.mask;
      this.table[i] = v;
    }
  }
}
