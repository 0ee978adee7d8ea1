// A ring that crosses itself (a bow-tie) is named as such, before the checks between
// features: its reversed loop would otherwise lie on a neighbour's side and be taken for an
// overlap with that neighbour.
import type { Refusal } from './refusal.js';
import { crossingPoint, forEachNearPair, segmentsConflict } from './segment-conflict.js';
import type { Ring } from './topology-types.js';

export function checkRingSelfCrossings(rings: Ring[], xs: Float64Array, ys: Float64Array, refusal: Refusal): void {
  let n = 0;
  for (const r of rings) n += r.ids.length;
  const from = new Int32Array(n), to = new Int32Array(n), ringOf = new Int32Array(n);
  let s = 0;
  rings.forEach((r, ri) => {
    const m = r.ids.length;
    for (let i = 0; i < m; i++, s++) {
      from[s] = r.ids[i]!;
      to[s] = r.ids[(i + 1) % m]!;
      ringOf[s] = ri;
    }
  });
  const named = new Set<number>();
  forEachNearPair(from, to, xs, ys, (i, j) => {
    const ri = ringOf[i]!;
    if (ringOf[j] !== ri || named.has(ri)) return;
    if (!segmentsConflict(from[i]!, to[i]!, from[j]!, to[j]!, xs, ys)) return;
    named.add(ri);
    const [x, y] = crossingPoint(from[i]!, to[i]!, from[j]!, to[j]!, xs, ys);
    const r = rings[ri]!;
    refusal.note('selfIntersection', `is self-intersecting: its ${r.outer ? 'outer ring' : 'hole'} crosses itself`, r.face, x, y);
  });
}
