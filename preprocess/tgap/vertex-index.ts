// The vertices that can block a simplification, in an R-tree. Vertices die all the time
// (removed by simplification or by a merge): they stay in the tree and are skipped, and the
// tree is rebuilt when the dead outnumber the living.
import RBush from 'rbush';

interface Item {
  minX: number;
  minY: number;
  maxX: number;
  maxY: number;
  v: number;
}

export class VertexIndex {
  private tree = new RBush<Item>(16);
  private count = 0;

  constructor(private readonly store: { xs: Float64Array; ys: Float64Array; alive: Uint8Array; size: number }) {}

  load(ids: Iterable<number>): void {
    const items: Item[] = [];
    for (const v of ids) items.push(this.item(v));
    this.tree.load(items);
    this.count += items.length;
  }

  insert(v: number): void {
    this.tree.insert(this.item(v));
    this.count++;
  }

  /** Calls `fn` for every living vertex in the box; stops early when fn returns true. */
  some(minX: number, minY: number, maxX: number, maxY: number, fn: (v: number) => boolean): boolean {
    const alive = this.store.alive;
    for (const it of this.tree.search({ minX, minY, maxX, maxY })) {
      if (alive[it.v] && fn(it.v)) return true;
    }
    return false;
  }

  /** Rebuilds from the living vertices when most entries are dead. */
  compact(aliveCount: number): void {
    if (this.count < 1024 || aliveCount * 2 > this.count) return;
    const ids: number[] = [];
    const { alive, size } = this.store;
    for (let v = 0; v < size; v++) if (alive[v]) ids.push(v);
    this.tree.clear();
    this.count = 0;
    this.load(ids);
  }

  private item(v: number): Item {
    const x = this.store.xs[v]!, y = this.store.ys[v]!;
    return { minX: x, minY: y, maxX: x, maxY: y, v };
  }
}
