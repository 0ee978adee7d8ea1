// Exact duplicate polygons: two features with the same rings (whatever their start point or
// direction). They are refused naming both, or the later one is dropped (--drop-duplicates).
import type { InputFeature } from '../io/read-input.js';

/** Pairs [earlier, later] of feature positions whose polygons are the same; each later one once. */
export function findDuplicateFeatures(features: readonly InputFeature[]): [number, number][] {
  // Candidates share their point count and bounding box; only those are compared in full.
  const bySignature = new Map<string, number[]>();
  features.forEach((f, i) => {
    if (f.polygons.length === 0) return;
    const sig = signature(f);
    const list = bySignature.get(sig);
    if (list) list.push(i);
    else bySignature.set(sig, [i]);
  });
  const pairs: [number, number][] = [];
  for (const list of bySignature.values()) {
    if (list.length < 2) continue;
    const canon = new Map<string, number>();
    for (const i of list) {
      const key = canonical(features[i]!);
      const first = canon.get(key);
      if (first === undefined) canon.set(key, i);
      else pairs.push([first, i]);
    }
  }
  return pairs.sort((p, q) => p[1] - q[1]);
}

function signature(f: InputFeature): string {
  let n = 0, x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  for (const p of f.polygons) {
    for (const r of p) {
      n += r.length;
      for (let i = 0; i < r.length; i += 2) {
        x0 = Math.min(x0, r[i]!); x1 = Math.max(x1, r[i]!);
        y0 = Math.min(y0, r[i + 1]!); y1 = Math.max(y1, r[i + 1]!);
      }
    }
  }
  return `${n}|${x0}|${y0}|${x1}|${y1}`;
}

/** The polygons as text, each ring from its least point and in its lesser direction, polygons sorted. */
function canonical(f: InputFeature): string {
  return f.polygons.map((p) => p.map(canonicalRing).join(';')).sort().join('/');
}

function canonicalRing(r: Float64Array): string {
  const n = r.length >> 1;
  const less = (i: number, j: number): boolean => r[2 * i]! < r[2 * j]! || (r[2 * i] === r[2 * j] && r[2 * i + 1]! < r[2 * j + 1]!);
  let s = 0;
  for (let i = 1; i < n; i++) if (less(i, s)) s = i;
  const walk = (step: number): number[] => {
    const out: number[] = [];
    for (let k = 0; k < n; k++) {
      const i = (((s + step * k) % n) + n) % n;
      out.push(r[2 * i]!, r[2 * i + 1]!);
    }
    return out;
  };
  const fwd = walk(1).join(','), back = walk(-1).join(',');
  return fwd < back ? fwd : back;
}
