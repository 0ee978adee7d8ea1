// Which surfaces lie in a face's area, so that a tilted surface later laid over that area can
// be kept above each of them where they overlap (the cube stays a partition at every z): the
// surfaces whose upper face is the face, or a face merged into it since. A replaced face's
// surfaces all lie under its re-emitted area, so only that is kept.
import Flatbush from 'flatbush';
import { trianglesOverlap } from '../geom/triangles-overlap.js';
import type { Surfaces } from './surfaces.js';

/** Below this many candidates the triangles are compared one by one. */
const INDEX_FROM = 32;

export class SurfacesByFace {
  private readonly lists = new Map<number, number[]>();
  /** Per face, the highest z of the surfaces in its area. */
  private readonly tops = new Map<number, number>();

  constructor(private readonly out: Surfaces) {}

  /** Surface triangle `tri` now lies in `face`'s area. */
  add(face: number, tri: number): void {
    let l = this.lists.get(face);
    if (!l) this.lists.set(face, (l = []));
    l.push(tri);
    this.tops.set(face, Math.max(this.tops.get(face) ?? -Infinity, this.maxZ(tri)));
  }

  /** How many surfaces lie in `face`'s area (as far as they are still kept). */
  count(face: number): number {
    return this.lists.get(face)?.length ?? 0;
  }

  /** The highest z of any surface in `face`'s area (-Infinity: none above the floor). */
  top(face: number): number {
    return this.tops.get(face) ?? -Infinity;
  }

  /** `from`'s area joins `to`'s (a merge). */
  hand(from: number, to: number): void {
    const a = this.lists.get(from);
    this.lists.delete(from);
    this.tops.set(to, Math.max(this.top(to), this.top(from)));
    this.tops.delete(from);
    if (!a) return;
    const b = this.lists.get(to);
    if (!b) {
      this.lists.set(to, a);
      return;
    }
    // The shorter list into the longer: a face that grows by many merges costs n log n in all.
    const [long, short] = a.length > b.length ? [a, b] : [b, a];
    for (const t of short) long.push(t);
    this.lists.set(to, long);
  }

  /** The face ends, its area drawn afresh (a split or a re-emit). */
  drop(face: number): void {
    this.lists.delete(face);
    this.tops.delete(face);
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
    const lowest = new Map<number, number>();
    const all = this.lists.get(face);
    if (!all) return lowest;
    const kept = all.filter((t) => this.maxZ(t) + gap > zForget);
    this.lists.set(face, kept);
    const near = kept.filter((t) => this.maxZ(t) + gap > zFrom);
    if (near.length === 0) return lowest;
    const { v } = this.out;
    const a = new Float64Array(6), b = new Float64Array(6);
    const box = (c: Float64Array): [number, number, number, number] => [Math.min(c[0]!, c[2]!, c[4]!), Math.min(c[1]!, c[3]!, c[5]!), Math.max(c[0]!, c[2]!, c[4]!), Math.max(c[1]!, c[3]!, c[5]!)];
    let index: Flatbush | undefined;
    if (near.length >= INDEX_FROM) {
      index = new Flatbush(near.length);
      for (const t of near) index.add(...box(this.coords(v, 3 * t, b)));
      index.finish();
    }
    for (let i = 0; i + 2 < tris.length; i += 3) {
      this.coords(tris, i, a);
      const candidates = index ? index.search(...box(a)).map((k) => near[k]!) : near;
      let top = -Infinity;
      for (const t of candidates) {
        const zt = this.maxZ(t);
        if (zt > top && trianglesOverlap(a, this.coords(v, 3 * t, b))) top = zt;
      }
      if (top === -Infinity) continue;
      for (let k = 0; k < 3; k++) {
        const w = tris[i + k]!;
        lowest.set(w, Math.max(lowest.get(w) ?? -Infinity, top + gap));
      }
    }
    return lowest;
  }
}
