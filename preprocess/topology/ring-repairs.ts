// The safe repairs of input rings, each counted: points closer than the precision merged,
// T-junctions inserted, repeated points and zero-width spikes dropped, and rings turned to the
// orientation of their role. What cannot be repaired is refused.
import KDBush from 'kdbush';
import { orient } from '../geom/predicates.js';
import { ringArea2 } from '../geom/ring.js';
import type { Refusal } from './refusal.js';
import type { Ring, TopologyRepairs } from './topology-types.js';

/**
 * Merges points closer than `precision`, puts vertices lying on another ring's segment into
 * that segment, and cleans what that leaves. The ids keep their coordinates; rings are new
 * where they changed.
 */
export function repairRings(rawRings: Ring[], xs: Float64Array, ys: Float64Array, precision: number, repairs: TopologyRepairs): Ring[] {
  const nv = xs.length;
  const index = new KDBush(nv, 64, Float64Array);
  for (let v = 0; v < nv; v++) index.add(xs[v]!, ys[v]!);
  index.finish();
  // Tolerances compare with a hair of slack so that neighbours exactly one grid step apart count.
  const tol = precision * (1 + 1e-9);
  // Points closer than the precision are one point (the first one met in the input).
  const alias = mergeNearPoints(rawRings, index, xs, ys, tol, repairs);
  // T-junctions: a vertex lying on another ring's segment is inserted into that segment.
  const rings = insertTJunctions(rawRings, index, alias, xs, ys, tol, repairs);
  for (const r of rings) r.ids = cleanRing(r.ids, repairs);
  return rings;
}

/**
 * Turns outer rings counterclockwise and holes clockwise. A ring of fewer than 3 points or no
 * area is refused, unless `sliver` takes it (a sliver the snapping collapsed); both are
 * returned, to be left out.
 */
export function orientRings(rings: Ring[], xs: Float64Array, ys: Float64Array, repairs: TopologyRepairs, refusal: Refusal, sliver: (r: Ring) => boolean = () => false): Ring[] {
  const collapsed: Ring[] = [];
  for (const r of rings) {
    const distinct = new Set(r.ids).size;
    const a2 = distinct < 3 ? 0 : ringArea2(r.ids, xs, ys);
    if (a2 === 0) collapsed.push(r);
    if (a2 === 0 && sliver(r)) continue;
    if (distinct < 3) {
      refusal.note('ring', `has a ${r.outer ? 'ring' : 'hole'} with fewer than 3 distinct points`, r.face, xs[r.ids[0]!], ys[r.ids[0]!]);
      continue;
    }
    if (a2 === 0) {
      refusal.note('ring', `has a ${r.outer ? 'ring' : 'hole'} of zero area`, r.face, xs[r.ids[0]!], ys[r.ids[0]!]);
      continue;
    }
    if ((a2 > 0) !== r.outer) {
      r.ids.reverse();
      repairs.reorientedRings++;
    }
  }
  return collapsed;
}

/**
 * Inserts every vertex that lies on a segment (within the precision) into that segment; but a
 * vertex of another ring of the segment's own face (its hole, its outer ring, another of its
 * parts) only when exactly on it: pulled onto the segment from near by, it would fold the ring
 * onto that ring (an outer ring passing 0.09 mm from a vertex of its hole is a valid polygon,
 * not an overlap). A vertex of the same ring is inserted: that is how a zero-width spike or a
 * fold of the ring narrower than the precision closes up (cleanRing), where leaving it would
 * have the snapping make the ring cross itself.
 */
function insertTJunctions(rings: Ring[], index: KDBush, alias: Int32Array, xs: Float64Array, ys: Float64Array, tol: number, repairs: TopologyRepairs): Ring[] {
  const tol2 = tol * tol;
  const out: Ring[] = [];
  const own = new OwnVertices(rings, xs.length);
  for (let ri = 0; ri < rings.length; ri++) {
    const r = rings[ri]!;
    const ids = r.ids;
    const n = ids.length;
    let result: number[] | null = null;
    for (let i = 0; i < n; i++) {
      const a = ids[i]!, b = ids[(i + 1) % n]!;
      const ax = xs[a]!, ay = ys[a]!, bx = xs[b]!, by = ys[b]!;
      const found = index.range(Math.min(ax, bx) - tol, Math.min(ay, by) - tol, Math.max(ax, bx) + tol, Math.max(ay, by) + tol);
      let inserts: { v: number; t: number }[] | null = null;
      if (found.length > 2) {
        const dx = bx - ax, dy = by - ay;
        const len2 = dx * dx + dy * dy;
        for (const v of found) {
          if (v === a || v === b || alias[v] !== v) continue;
          const px = xs[v]! - ax, py = ys[v]! - ay;
          const t = (px * dx + py * dy) / len2;
          if (t <= 0 || t >= 1) continue;
          // Within the precision of an end point it is that end point (merged before), not a T.
          if (px * px + py * py <= tol2) continue;
          const qx = xs[v]! - bx, qy = ys[v]! - by;
          if (qx * qx + qy * qy <= tol2) continue;
          const o = orient(ax, ay, bx, by, xs[v]!, ys[v]!);
          if (o !== 0) {
            // o is twice the triangle area: distance to the line is o / |ab|.
            if (tol === 0 || (o * o) / len2 > tol2) continue;
            if (own.folds(a, b, v)) continue;
          }
          (inserts ??= []).push({ v, t });
        }
      }
      if (inserts) {
        if (!result) result = Array.from(ids.subarray(0, i + 1));
        inserts.sort((p, q) => p.t - q.t || p.v - q.v);
        for (const ins of inserts) result.push(ins.v);
        repairs.tJunctions += inserts.length;
        if (i + 1 < n) result.push(b);
      } else if (result && i + 1 < n) {
        result.push(b);
      }
    }
    out.push(result ? { ...r, ids: Int32Array.from(result) } : r);
  }
  return out;
}

/** Union of points within `tol` of each other, each replaced by the lowest id of its group. */
function mergeNearPoints(rings: Ring[], index: KDBush, xs: Float64Array, ys: Float64Array, tol: number, repairs: TopologyRepairs): Int32Array {
  const nv = xs.length;
  const alias = new Int32Array(nv);
  for (let v = 0; v < nv; v++) alias[v] = v;
  if (tol <= 0) return alias;
  const find = (v: number): number => {
    while (alias[v] !== v) {
      alias[v] = alias[alias[v]!]!;
      v = alias[v]!;
    }
    return v;
  };
  let merged = false;
  for (let v = 0; v < nv; v++) {
    for (const w of index.within(xs[v]!, ys[v]!, tol)) {
      if (w === v) continue;
      const a = find(v), b = find(w);
      if (a === b) continue;
      if (a < b) alias[b] = a;
      else alias[a] = b;
      merged = true;
    }
  }
  if (!merged) return alias;
  for (let v = 0; v < nv; v++) alias[v] = find(v);
  for (const r of rings) {
    for (let i = 0; i < r.ids.length; i++) {
      const v = r.ids[i]!;
      if (alias[v] !== v) {
        r.ids[i] = alias[v]!;
        repairs.mergedPoints++;
      }
    }
  }
  return alias;
}

/** Drops repeated points and zero-width spikes (a, b, a) that merging can leave in a ring. */
export function cleanRing(ids: Int32Array, repairs: TopologyRepairs): Int32Array {
  const out: number[] = [];
  let changed = false;
  for (const v of ids) {
    if (out.length > 0 && out[out.length - 1] === v) {
      repairs.duplicatePoints++;
      changed = true;
      continue;
    }
    if (out.length >= 2 && out[out.length - 2] === v) {
      out.pop();
      repairs.spikes++;
      changed = true;
      continue;
    }
    out.push(v);
  }
  // The same across the ring's closing point.
  for (;;) {
    const n = out.length;
    if (n >= 2 && out[0] === out[n - 1]) {
      out.pop();
      repairs.duplicatePoints++;
      changed = true;
    } else if (n >= 3 && out[1] === out[n - 1]) {
      out.shift();
      out.pop();
      repairs.spikes++;
      changed = true;
    } else if (n >= 3 && out[0] === out[n - 2]) {
      out.pop();
      out.pop();
      repairs.spikes++;
      changed = true;
    } else break;
  }
  return changed ? Int32Array.from(out) : ids;
}

/**
 * Which rings each vertex is on (built when first asked): tells whether a vertex near a segment
 * is on another ring of the face the segment bounds, where moving it onto the segment folds
 * one ring onto the other.
 */
class OwnVertices {
  private start: Int32Array | null = null;
  /** Per vertex, its (ring, position) pairs: ring indices and positions interleaved. */
  private list: Int32Array | null = null;

  constructor(private readonly rings: readonly Ring[], private readonly nv: number) {}

  /** True when v is on another ring of a face whose ring has the segment a-b. */
  folds(a: number, b: number, v: number): boolean {
    const { rings } = this;
    const { start, list } = this.build();
    for (let i = start[a]!; i < start[a + 1]!; i += 2) {
      const ri = list[i]!, p = list[i + 1]!;
      const ids = rings[ri]!.ids;
      const n = ids.length;
      if (ids[(p + 1) % n] !== b && ids[(p + n - 1) % n] !== b) continue;
      // Ring ri has the segment a-b.
      for (let k = start[v]!; k < start[v + 1]!; k += 2) {
        const rj = list[k]!;
        if (rj !== ri && rings[rj]!.face === rings[ri]!.face) return true;
      }
    }
    return false;
  }

  private build(): { start: Int32Array; list: Int32Array } {
    if (this.start && this.list) return { start: this.start, list: this.list };
    const start = new Int32Array(this.nv + 1);
    for (const r of this.rings) for (const v of r.ids) start[v + 1]! += 2;
    for (let v = 0; v < this.nv; v++) start[v + 1]! += start[v]!;
    const fill = start.slice(0, this.nv);
    const list = new Int32Array(start[this.nv]!);
    this.rings.forEach((r, ri) => {
      r.ids.forEach((v, p) => {
        list[fill[v]!++] = ri;
        list[fill[v]!++] = p;
      });
    });
    this.start = start;
    this.list = list;
    return { start, list };
  }
}
