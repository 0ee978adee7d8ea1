// The first step from polygons to a partition: coordinates are snapped to the precision grid
// and every distinct point gets one id, so that neighbours share their points by id.
import { PointHash } from '../geom/point-hash.js';
import type { InputFeature } from '../io/read-input.js';
import type { Ring, TopologyRepairs } from './topology-types.js';

export interface SnappedRings {
  /** Every ring of every feature (face = feature index + 1), as point ids, repeated points dropped. */
  rings: Ring[];
  /** Coordinates of the points by id. */
  xs: Float64Array;
  ys: Float64Array;
}

/** `skip(face, part)`: a polygon left out (a sliver narrower than the precision, slivers.ts). */
export function snapPoints(features: readonly InputFeature[], precision: number, repairs: TopologyRepairs, skip: (face: number, part: number) => boolean = () => false): SnappedRings {
  let total = 0;
  for (const f of features) for (const p of f.polygons) for (const r of p) total += r.length >> 1;
  const hash = new PointHash(total);
  const snap = gridSnapper(precision);
  const rings: Ring[] = [];
  features.forEach((f, fi) => {
    const face = fi + 1;
    f.polygons.forEach((poly, part) => {
      if (skip(face, part)) return;
      poly.forEach((r, ri) => {
        const ids: number[] = [];
        for (let i = 0; i < r.length; i += 2) {
          const x = snap(r[i]!), y = snap(r[i + 1]!);
          if (x !== r[i] || y !== r[i + 1]) repairs.snappedPoints++;
          const id = hash.id(x, y);
          if (ids.length > 0 && ids[ids.length - 1] === id) {
            repairs.duplicatePoints++;
            continue;
          }
          ids.push(id);
        }
        while (ids.length > 1 && ids[0] === ids[ids.length - 1]) {
          ids.pop();
          repairs.duplicatePoints++;
        }
        rings.push({ face, outer: ri === 0, ids: Int32Array.from(ids), part, ring: ri });
      });
    });
  });
  const nv = hash.size;
  return { rings, xs: hash.xs.subarray(0, nv), ys: hash.ys.subarray(0, nv) };
}

/** Rounds a coordinate to the grid of size p (p <= 0: no grid). */
export function gridSnapper(p: number): (v: number) => number {
  // Grids of a power of ten round through the decimal text, so values already on the grid stay
  // bit-identical (181477.123 stays 181477.123, not 181477.12300000002).
  const decimals = p > 0 ? Math.round(-Math.log10(p)) : 0;
  const decimalGrid = p > 0 && decimals >= 0 && decimals <= 15 && Math.abs(10 ** -decimals - p) < p * 1e-9;
  return (v: number): number => {
    if (p <= 0) return v;
    if (decimalGrid) return Number(v.toFixed(decimals));
    return Math.round(v / p) * p;
  };
}
