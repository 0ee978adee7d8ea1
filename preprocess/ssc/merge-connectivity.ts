// No spurious multi-parts (issue 11): during a smooth merge, every part of the loser's area that
// the winner has already taken must be attached to the winner through the boundary they share.
// Exact, on the triangles themselves: with z linear over a triangle, the part of it below a
// slice is convex and, when not empty, holds a corner below the slice. So the taken parts are
// connected exactly as the corners below the slice are, joined within each triangle, and a
// part touches the shared boundary exactly when one of its corners lies on it.
import type { Tgap } from '../../format/tgap-model.js';
import { mergeTriangles, sharedBoundaries } from './merge-surface.js';
import type { MergeTransition, Surfaces } from './surfaces.js';

/** Triangles with per-corner z: vertex ids and z, 3 per triangle. */
export interface ZTriangles {
  v: ArrayLike<number>;
  z: ArrayLike<number>;
}

/**
 * The parts of the triangles' area below the slice at `zs` (z < zs) that touch no vertex of
 * `shared`: each one an island of the winner's gain, apart from the winner.
 */
export function detachedParts(tris: ZTriangles, shared: ReadonlySet<number>, zs: number): number {
  const parent = new Map<number, number>();
  const find = (a: number): number => {
    let r = a;
    while (parent.get(r)! !== r) r = parent.get(r)!;
    while (a !== r) {
      const next = parent.get(a)!;
      parent.set(a, r);
      a = next;
    }
    return r;
  };
  for (let i = 0; i + 2 < tris.v.length; i += 3) {
    let first = -1;
    for (let j = i; j < i + 3; j++) {
      if (!(tris.z[j]! < zs)) continue;
      const v = tris.v[j]!;
      if (!parent.has(v)) parent.set(v, v);
      if (first < 0) first = v;
      else parent.set(find(v), find(first));
    }
  }
  const attached = new Set<number>();
  for (const v of parent.keys()) if (shared.has(v)) attached.add(find(v));
  const roots = new Set<number>();
  for (const v of parent.keys()) roots.add(find(v));
  let detached = 0;
  for (const r of roots) if (!attached.has(r)) detached++;
  return detached;
}

/** Slices strictly inside a transition: `n` evenly spaced z between zStart and zMerge. */
export function samplesInside(zStart: number, zMerge: number, n: number): number[] {
  return Array.from({ length: n }, (_, i) => zStart + ((zMerge - zStart) * (i + 1)) / (n + 1));
}

/** One tilted merge's connectivity over its transition. */
export interface MergeConnectivity {
  transition: MergeTransition;
  /** Indices of the merge's triangles in the surfaces. */
  triangles: number[];
  /** Per sampled z, the detached parts of the winner's gain (0 everywhere: no violation). */
  detached: number[];
}

/**
 * Every tilted merge of `transitions` sliced at `samples` z inside its transition. The shared
 * boundary is the tGAP's, just before the merge.
 */
export function mergeConnectivity(t: Tgap, s: Surfaces, transitions: readonly MergeTransition[], samples = 8): MergeConnectivity[] {
  const tilted = transitions.filter((m) => m.tilted);
  const tris = mergeTriangles(s, tilted, t);
  const heldIn = new Map(transitions.filter((m) => m.held).map((m) => [m.loser, m.into]));
  const shared = sharedBoundaries(t, tilted, tris, s, heldIn);
  return tilted.map((m, k) => {
    const mine = tris[k]!;
    if (mine.length === 0) throw new Error(`merge of face ${m.loser} into ${m.into} (step ${m.step}) is marked tilted but has no triangles between z ${m.zStart} and ${m.zMerge}`);
    const v = new Int32Array(3 * mine.length), z = new Float64Array(3 * mine.length);
    mine.forEach((i, n) => {
      v.set(s.v.subarray(3 * i, 3 * i + 3), 3 * n);
      z.set(s.z.subarray(3 * i, 3 * i + 3), 3 * n);
    });
    const detached = samplesInside(m.zStart, m.zMerge, samples).map((zs) => detachedParts({ v, z }, shared[k]!, zs));
    return { transition: m, triangles: mine, detached };
  });
}

/** A merge violates when its gain is apart from the winner at any sampled z. */
export const violates = (c: MergeConnectivity): boolean => c.detached.some((n) => n > 0);
