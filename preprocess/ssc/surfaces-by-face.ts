// Which surfaces lie in a face's area, so that a tilted surface later laid over that area can
// be kept above each of them where they overlap (the cube stays a partition at every z): the
// surfaces whose upper face is the face, or a face merged into it since. A replaced face's
// surfaces all lie under its re-emitted area, so only that is kept.
import RBush from 'rbush';
import { trianglesOverlap } from '../geom/triangles-overlap.js';
import type { Surfaces } from './surfaces.js';

interface Item {
  minX: number;
  minY: number;
  maxX: number;
  maxY: number;
  /** The surface triangle. */
  t: number;
  /** Its highest z. */
  z: number;
}

/**
 * Per face, its surfaces in a spatial index: a large face (nlcd_zion's biggest holds about
 * 14,000) is looked up once per removal along its boundary, and scanning its whole list each
 * time took minutes.
 */
export class SurfacesByFace {
  private readonly trees = new Map<number, RBush<Item>>();
  private readonly sizes = new Map<RBush<Item>, number>();
  /** Surfaces up to this z no later transition reaches (the latest `zForget`): left out of merged trees. */
  private forgotten = -Infinity;

  constructor(private readonly out: Surfaces) {}

  /** Surface triangle `tri` now lies in `face`'s area. */
  add(face: number, tri: number): void {
    let tree = this.trees.get(face);
    if (!tree) this.trees.set(face, (tree = new RBush<Item>()));
    this.sizes.set(tree, (this.sizes.get(tree) ?? 0) + 1);
    const { v, xs, ys } = this.out;
    const a = v[3 * tri]!, b = v[3 * tri + 1]!, c = v[3 * tri + 2]!;
    tree.insert({
      minX: Math.min(xs[a]!, xs[b]!, xs[c]!), minY: Math.min(ys[a]!, ys[b]!, ys[c]!),
      maxX: Math.max(xs[a]!, xs[b]!, xs[c]!), maxY: Math.max(ys[a]!, ys[b]!, ys[c]!),
      t: tri, z: this.maxZ(tri),
    });
  }

  /** `from`'s area joins `to`'s (a merge). */
  hand(from: number, to: number): void {
    const a = this.trees.get(from);
    this.trees.delete(from);
    if (!a) return;
    const b = this.trees.get(to);
    if (!b) {
      this.trees.set(to, a);
      return;
    }
    // The smaller tree into the larger: a face that grows by many merges costs n log n in all.
    const [large, small] = this.sizes.get(a)! > this.sizes.get(b)! ? [a, b] : [b, a];
    const kept = small.all().filter((item) => item.z > this.forgotten);
    large.load(kept);
    this.sizes.set(large, this.sizes.get(large)! + kept.length);
    this.sizes.delete(small);
    this.trees.set(to, large);
  }

  /** The face ends, its area drawn afresh (a split or a re-emit). */
  drop(face: number): void {
    const tree = this.trees.get(face);
    if (tree) this.sizes.delete(tree);
    this.trees.delete(face);
  }

  private maxZ(t: number): number {
    const z = this.out.z;
    return Math.max(z[3 * t]!, z[3 * t + 1]!, z[3 * t + 2]!);
  }

  private coords(v: ArrayLike<number>, i: number, into: Float64Array): Float64Array {
    for (let k = 0; k < 3; k++) {
      into[2 * k] = this.out.xs[v[i + k]!]!;
      into[2 * k + 1] = this.out.ys[v[i + k]!]!;
    }
    return into;
  }

  /**
   * Per vertex of `tris` (the face's area triangulated), the lowest z it may take: `gap` above
   * every surface of the face's area reaching above `zFrom` that overlaps one of its triangles.
   * The surfaces no later transition can reach (none above `zForget`) are forgotten.
   */
  lowestZ(face: number, tris: ArrayLike<number>, zFrom: number, gap: number, zForget: number): Map<number, number> {
    return this.waitsAbove(tris, this.overlapping(face, tris, zFrom, gap, zForget), gap);
  }

  /**
   * The corner rule for `pairs` (from `overlapping`): every corner of a triangle of `tris` that
   * overlaps a surface `gap` above that surface's highest point. Always enough, often more than
   * needed: a long triangle's far corner waits for a small surface at its other end.
   */
  waitsAbove(tris: ArrayLike<number>, pairs: readonly (readonly [number, number])[], gap: number): Map<number, number> {
    const lowest = new Map<number, number>();
    for (const [i, t] of pairs) {
      const top = this.maxZ(t) + gap;
      for (let k = 0; k < 3; k++) {
        const w = tris[i + k]!;
        lowest.set(w, Math.max(lowest.get(w) ?? -Infinity, top));
      }
    }
    return lowest;
  }

  /**
   * The pairs [i, t]: triangle i (offset into `tris`) overlaps surface t of the face's area,
   * which reaches above `zFrom - gap` (forgetting those below `zForget`, as `lowestZ` does).
   */
  overlapping(face: number, tris: ArrayLike<number>, zFrom: number, gap: number, zForget: number): [number, number][] {
    const pairs: [number, number][] = [];
    this.forgotten = Math.max(this.forgotten, zForget - gap);
    const tree = this.trees.get(face);
    if (!tree) return pairs;
    const { v } = this.out;
    const a = new Float64Array(6), b = new Float64Array(6);
    for (let i = 0; i + 2 < tris.length; i += 3) {
      this.coords(tris, i, a);
      const box = { minX: Math.min(a[0]!, a[2]!, a[4]!), minY: Math.min(a[1]!, a[3]!, a[5]!), maxX: Math.max(a[0]!, a[2]!, a[4]!), maxY: Math.max(a[1]!, a[3]!, a[5]!) };
      for (const { t, z } of tree.search(box)) {
        if (z + gap > zFrom && trianglesOverlap(a, this.coords(v, 3 * t, b))) pairs.push([i, t]);
      }
    }
    return pairs;
  }
}
