// Where two areas of a network join: the point halfway along the boundary they share. Both
// areas must get the same point to the last bit, whichever way round each walks the chain, so
// it is computed in one canonical order: an open chain from its lexicographically smaller end
// (x, then y); a closed one from its smallest vertex towards the smaller of that vertex's
// neighbours.
import type { Point } from './centreline.js';

/** Halfway along the chain through the flat x, y pairs (a closed chain repeats its first point last). */
export function chainMidpoint(coords: ArrayLike<number>): Point {
  const n = coords.length / 2;
  if (n < 2) throw new Error(`a chain needs two points, got ${n}`);
  const pts = canonical(coords);
  let total = 0;
  const len: number[] = [];
  for (let i = 0; i + 1 < pts.length; i++) {
    const l = Math.hypot(pts[i + 1]![0] - pts[i]![0], pts[i + 1]![1] - pts[i]![1]);
    len.push(l);
    total += l;
  }
  let half = total / 2;
  for (let i = 0; i < len.length; i++) {
    const l = len[i]!;
    if (half <= l && l > 0) {
      const t = half / l;
      const [ax, ay] = pts[i]!, [bx, by] = pts[i + 1]!;
      return t === 1 ? { x: bx, y: by } : { x: ax + (bx - ax) * t, y: ay + (by - ay) * t };
    }
    half -= l;
  }
  const [x, y] = pts[pts.length - 1]!;
  return { x, y };
}

const less = (a: readonly [number, number], b: readonly [number, number]): boolean => a[0] < b[0] || (a[0] === b[0] && a[1] < b[1]);

function canonical(coords: ArrayLike<number>): [number, number][] {
  const pts: [number, number][] = [];
  for (let i = 0; i < coords.length; i += 2) pts.push([coords[i]!, coords[i + 1]!]);
  const first = pts[0]!, last = pts[pts.length - 1]!;
  if (first[0] !== last[0] || first[1] !== last[1]) return less(last, first) ? pts.reverse() : pts;
  const ring = pts.slice(0, -1);
  const m = ring.length;
  let s = 0;
  for (let i = 1; i < m; i++) if (less(ring[i]!, ring[s]!)) s = i;
  const forward = less(ring[(s + 1) % m]!, ring[(s + m - 1) % m]!);
  const out: [number, number][] = [];
  for (let k = 0; k <= m; k++) out.push(ring[(((forward ? s + k : s - k) % m) + m) % m]!);
  return out;
}
