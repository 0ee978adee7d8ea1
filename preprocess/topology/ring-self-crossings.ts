// A ring that crosses itself (a bow-tie) is named as such, before the checks between
// features: its reversed loop would otherwise lie on a neighbour's side and be taken for an
// overlap with that neighbour.
import type { Refusal } from './refusal.js';
import { crossingPoint, segmentsConflict } from './segment-conflict.js';
import type { Ring } from './topology-types.js';

export function checkRingSelfCrossings(rings: Ring[], xs: Float64Array, ys: Float64Array, refusal: Refusal): void {
  for (const r of rings) {
    const crossing = ringCrossing(r.ids, xs, ys);
    if (crossing) refusal.note('selfIntersection', `is self-intersecting: its ${r.outer ? 'outer ring' : 'hole'} crosses itself`, r.face, crossing[0], crossing[1]);
  }
}

/**
 * The first place where two segments of a ring conflict, or null: a sweep along x over the
 * segments sorted by their left end, each compared with those whose x range meets its own
 * (an R-tree per ring costs more than it saves on the small rings of real data).
 */
function ringCrossing(ids: Int32Array, xs: Float64Array, ys: Float64Array): [number, number] | null {
  const n = ids.length;
  const x0 = new Float64Array(n), x1 = new Float64Array(n), y0 = new Float64Array(n), y1 = new Float64Array(n);
  for (let i = 0; i < n; i++) {
    const a = ids[i]!, b = ids[(i + 1) % n]!;
    x0[i] = Math.min(xs[a]!, xs[b]!); x1[i] = Math.max(xs[a]!, xs[b]!);
    y0[i] = Math.min(ys[a]!, ys[b]!); y1[i] = Math.max(ys[a]!, ys[b]!);
  }
  // Small rings (most of real data) skip the sort: in ring order, every pair is compared.
  const order = n <= 32 ? null : Int32Array.from({ length: n }, (_, i) => i).sort((p, q) => x0[p]! - x0[q]! || p - q);
  for (let k = 0; k < n; k++) {
    const i = order ? order[k]! : k;
    for (let m = k + 1; m < n; m++) {
      const j = order ? order[m]! : m;
      if (order && x0[j]! > x1[i]!) break;
      if (x0[j]! > x1[i]! || x1[j]! < x0[i]! || y0[j]! > y1[i]! || y1[j]! < y0[i]!) continue;
      const a = ids[i]!, b = ids[(i + 1) % n]!, c = ids[j]!, d = ids[(j + 1) % n]!;
      if (segmentsConflict(a, b, c, d, xs, ys)) return crossingPoint(a, b, c, d, xs, ys);
    }
  }
  return null;
}
