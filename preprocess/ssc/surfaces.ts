// The Space-Scale Cube's surfaces from a tGAP: the tGAP is replayed step by step and every
// change of a point's face becomes a horizontal triangle between the old face (lower) and the
// new one (upper), at the z of the step's phase (docs/FORMAT.md):
// - the floor (z = 0): every input face, nothing below;
// - a merge: the loser's area (and, when the winner is replaced by a new face, the winner's);
//   with `smooth`, tilted instead: rising from the boundary the loser shares with the winner,
//   from the loser's last change to the merge (smooth-merge.ts);
// - a split: the triangles the split gave each receiving face;
// - simplification: each removed vertex's triangle, between the faces on either side.
import { orient } from '../geom/predicates.js';
import { EventKind, faceEndZ, LAST_REMOVAL_PHASE, phaseZ, REEMIT_PHASE, resolveFace, resolveFaceAt, type Tgap } from '../../format/tgap-model.js';
import { smoothMergeZ } from './smooth-merge.js';
import { triangulateFace, type FaceEdge, type TriangulateStats } from './triangulate-face.js';

export class Surfaces {
  count = 0;
  /** tGAP vertex ids, 3 per triangle, counterclockwise. */
  v = new Int32Array(3 * 1024);
  /** z of each vertex of each triangle (3 per triangle): equal on a horizontal one. */
  z = new Float64Array(3 * 1024);
  /** The triangle's lowest z: from there on it can be seen (chunk boxes, culling). */
  zMin = new Float64Array(1024);
  upper = new Int32Array(1024);
  lower = new Int32Array(1024);
  /** z from which newer surfaces cover the triangle (its upper face ended). */
  zEnd = new Float64Array(1024);
  /**
   * Horizontal triangles with the same z, upper and lower face form a piece, and so do a
   * tilted merge's triangles: only within a piece can they share vertices (a vertex carries z
   * and both faces).
   */
  piece = new Int32Array(1024);
  pieces = 0;
  private readonly pieceIds = new Map<string, number>();
  private lastFlat = false;

  /** A horizontal triangle at z. */
  add(a: number, b: number, c: number, z: number, upper: number, lower: number): void {
    const i = this.count;
    const same = i > 0 && this.lastFlat && this.zMin[i - 1] === z && this.upper[i - 1] === upper && this.lower[i - 1] === lower;
    this.push(a, b, c, z, z, z, upper, lower, same ? null : `${z} ${upper} ${lower}`);
    this.lastFlat = true;
  }

  /** A tilted triangle of the piece named `key` (each vertex with one z throughout the piece). */
  addTilted(a: number, b: number, c: number, za: number, zb: number, zc: number, upper: number, lower: number, key: string): void {
    this.push(a, b, c, za, zb, zc, upper, lower, key);
    this.lastFlat = false;
  }

  /** key null: the previous triangle's piece. */
  private push(a: number, b: number, c: number, za: number, zb: number, zc: number, upper: number, lower: number, key: string | null): void {
    if (this.count === this.zMin.length) this.grow();
    const i = this.count++;
    if (key === null) {
      this.piece[i] = this.piece[i - 1]!;
    } else {
      let id = this.pieceIds.get(key);
      if (id === undefined) this.pieceIds.set(key, (id = this.pieces++));
      this.piece[i] = id;
    }
    this.v[3 * i] = a;
    this.v[3 * i + 1] = b;
    this.v[3 * i + 2] = c;
    this.z[3 * i] = za;
    this.z[3 * i + 1] = zb;
    this.z[3 * i + 2] = zc;
    this.zMin[i] = Math.min(za, zb, zc);
    this.upper[i] = upper;
    this.lower[i] = lower;
  }

  private grow(): void {
    const n = this.zMin.length * 2;
    const v = new Int32Array(3 * n);
    v.set(this.v);
    this.v = v;
    const z = new Float64Array(3 * n);
    z.set(this.z);
    this.z = z;
    for (const k of ['zMin', 'zEnd'] as const) {
      const a = new Float64Array(n);
      a.set(this[k]);
      this[k] = a;
    }
    for (const k of ['upper', 'lower', 'piece'] as const) {
      const a = new Int32Array(n);
      a.set(this[k]);
      this[k] = a;
    }
  }
}

export interface SurfaceStats extends TriangulateStats {
  floor: number;
  merge: number;
  split: number;
  simplify: number;
  reemit: number;
  /** Merges drawn tilted (smooth), of `merge`'s triangles' events. */
  tiltedMerges: number;
}

export interface SurfaceOptions {
  /** Smooth merges: the loser's area tilted over its transition (docs/FORMAT.md, "Smooth cube"). */
  smooth?: boolean;
}

/**
 * A merge's transition: from zStart, the last change of the loser, of its boundary or the
 * winner's creation, to zMerge, the merge's z (zStart = zMerge: no room, drawn horizontal).
 */
export interface MergeTransition {
  step: number;
  loser: number;
  into: number;
  zStart: number;
  zMerge: number;
  /** Drawn tilted (with --smooth, room in z and a vertex off the shared boundary). */
  tilted: boolean;
}

export function buildSurfaces(t: Tgap, opts: SurfaceOptions = {}): { surfaces: Surfaces; stats: SurfaceStats; transitions: MergeTransition[] } {
  const steps = t.meta.steps;
  const zTop = steps + 1;
  const out = new Surfaces();
  const stats: SurfaceStats = { earcut: 0, fallback: 0, failed: 0, floor: 0, merge: 0, split: 0, simplify: 0, reemit: 0, tiltedMerges: 0 };
  const { xs, ys, faces, edges } = t;
  // Edges by the state they start and end in.
  const born: number[][] = Array.from({ length: steps + 2 }, () => []);
  const died: number[][] = Array.from({ length: steps + 2 }, () => []);
  edges.forEach((e, i) => {
    born[e.stepLow]!.push(i);
    if (e.stepHigh <= steps) died[e.stepHigh]!.push(i);
  });
  const faceEdges = new Map<number, Set<number>>();
  const attach = (e: number, s: number): void => {
    const edge = edges[e]!;
    for (const f of [resolveFace(faces, edge.left, s), resolveFace(faces, edge.right, s)]) {
      if (f === 0) continue;
      let set = faceEdges.get(f);
      if (!set) faceEdges.set(f, (set = new Set()));
      set.add(e);
    }
  };
  // What bounds a smooth merge's start (MergeTransition): per face, the z of its creation and of
  // the last change of its area (no other surface may lie in the loser's area during the
  // transition); per edge, the z of its birth or of the last change of a face on its sides (a
  // boundary the loser came to share with the winner when a neighbour merged into the winner:
  // the winner's side must be the winner's, the neighbour's transition over, so that what the
  // winner gains stays attached to it).
  const createdZ = new Float64Array(faces.length);
  const areaChange = new Float64Array(faces.length);
  const sideChange = Float64Array.from(edges, (e) => (e.stepLow > 0 ? phaseZ(e.stepLow, 0) : 0));
  const touch = (f: number, z: number): void => {
    if (f > 0) areaChange[f] = Math.max(areaChange[f]!, z);
  };
  /** The faces on f's edges changed at z (f merged, split or was replaced). */
  const relabel = (f: number, z: number): void => {
    for (const e of faceEdges.get(f) ?? []) sideChange[e] = Math.max(sideChange[e]!, z);
  };
  /** The loser's edges shared with the winner at state s. */
  const sharedEdges = (loser: number, into: number, s: number): number[] => {
    const out: number[] = [];
    for (const e of faceEdges.get(loser) ?? []) {
      const edge = edges[e]!;
      const l = resolveFace(faces, edge.left, s);
      const r = resolveFace(faces, edge.right, s);
      if ((l === loser && r === into) || (l === into && r === loser)) out.push(e);
    }
    return out;
  };
  const tris: number[] = [];
  /** Triangulates face f's area at state s into `tris`; returns the triangle count. */
  const triangulate = (f: number, s: number): number => {
    tris.length = 0;
    const set = faceEdges.get(f);
    if (!set) return 0;
    const fe: FaceEdge[] = [];
    for (const e of [...set].sort((a, b) => a - b)) {
      const edge = edges[e]!;
      const l = resolveFace(faces, edge.left, s);
      const r = resolveFace(faces, edge.right, s);
      if (l === f && r === f) continue;
      fe.push({ verts: edge.verts, forward: l === f });
    }
    return triangulateFace(fe, xs, ys, tris, stats);
  };
  /** Triangulates face f's current area and adds it at z with the given upper and lower faces. */
  const emitFace = (f: number, s: number, z: number, upper: number, lower: number): number => {
    const n = triangulate(f, s);
    for (let i = 0; i < tris.length; i += 3) out.add(tris[i]!, tris[i + 1]!, tris[i + 2]!, z, upper, lower);
    return n;
  };
  /**
   * The loser's area (state s) tilted from its boundary with the winner (zStart) to zMerge, or
   * flat at zMerge when it cannot tilt; returns whether it tilted.
   */
  const emitSmoothMerge = (loser: number, into: number, s: number, sharedWithInto: number[], zStart: number, zMerge: number, key: string): boolean => {
    stats.merge += triangulate(loser, s);
    const shared = new Set<number>();
    for (const e of sharedWithInto) for (const v of edges[e]!.verts) shared.add(v);
    const z = smoothMergeZ(tris, xs, ys, shared, zStart, zMerge);
    const zOf = (v: number): number => z?.get(v) ?? zMerge;
    for (let i = 0; i < tris.length; i += 3) {
      const a = tris[i]!, b = tris[i + 1]!, c = tris[i + 2]!;
      if (z) out.addTilted(a, b, c, zOf(a), zOf(b), zOf(c), into, loser, key);
      else out.add(a, b, c, zMerge, into, loser);
    }
    if (z) stats.tiltedMerges++;
    return z !== null;
  };
  const transitions: MergeTransition[] = [];

  for (const e of born[0]!) if (edges[e]!.stepHigh > 0) attach(e, 0);
  for (let f = 1; f < faces.length; f++) {
    if (faces[f]!.stepLow === 0 && faces[f]!.stepHigh > 0) stats.floor += emitFace(f, 0, 0, f, 0);
  }
  let ev = 0;
  for (let k = 1; k <= steps; k++) {
    const z0 = phaseZ(k, 0);
    // Phase 0: the areas that change face in this step, as they were in state k - 1.
    const handOn: [number, number][] = []; // [face, into]: faces whose edges go to another face
    const reemits: [number, number][] = [];
    for (; ev < t.events.length && t.events[ev]!.step === k; ev++) {
      const e = t.events[ev]!;
      if (e.kind === EventKind.Merge) {
        const shared = sharedEdges(e.loser, e.into, k - 1);
        let zStart = Math.max(areaChange[e.loser]!, createdZ[e.into]!);
        for (const se of shared) zStart = Math.max(zStart, sideChange[se]!);
        let tilted = false;
        if (opts.smooth) tilted = emitSmoothMerge(e.loser, e.into, k - 1, shared, zStart, z0, `m${ev}`);
        else stats.merge += emitFace(e.loser, k - 1, z0, e.into, e.loser);
        transitions.push({ step: k, loser: e.loser, into: e.into, zStart, zMerge: z0, tilted });
        // The winner grows; the loser's neighbours now border the winner.
        touch(e.into, z0);
        relabel(e.loser, z0);
        handOn.push([e.loser, e.into]);
      } else if (e.kind === EventKind.Split) {
        const tv = e.tris!, tf = e.triFaces!;
        for (let i = 0; i < tf.length; i++) {
          out.add(tv[3 * i]!, tv[3 * i + 1]!, tv[3 * i + 2]!, z0, tf[i]!, e.loser);
          touch(tf[i]!, z0);
        }
        stats.split += tf.length;
        relabel(e.loser, z0);
        faceEdges.delete(e.loser);
      } else {
        const zRe = phaseZ(k, REEMIT_PHASE);
        relabel(e.loser, zRe);
        createdZ[e.into] = zRe;
        touch(e.into, zRe);
        handOn.push([e.loser, e.into]);
        reemits.push([e.loser, e.into]);
      }
    }
    // The edges that end here leave their faces (as they were before the step) ...
    for (const e of died[k]!) {
      const edge = edges[e]!;
      for (const f of [resolveFace(faces, edge.left, k - 1), resolveFace(faces, edge.right, k - 1)]) faceEdges.get(f)?.delete(e);
    }
    // ... merged and replaced faces hand their edges on ...
    for (const [f, into] of handOn) {
      const set = faceEdges.get(f);
      faceEdges.delete(f);
      if (!set) continue;
      let target = faceEdges.get(into);
      if (!target) faceEdges.set(into, (target = new Set()));
      for (const e of set) target.add(e);
    }
    // ... and the new edges join theirs.
    for (const e of born[k]!) if (edges[e]!.stepHigh > k) attach(e, k);
    // Simplification: replay each new version's removals on its parent's chain.
    for (const e of born[k]!) {
      const edge = edges[e]!;
      if (edge.removed.length === 0) continue;
      const p = edge.parents[0]!;
      const parent = edges[p >= 0 ? p : -p - 1]!;
      const chain = p >= 0 ? Array.from(parent.verts) : Array.from(parent.verts).reverse();
      const n = chain.length;
      const pos = new Map<number, number>();
      for (let i = 1; i < n - 1; i++) pos.set(chain[i]!, i);
      const prev = Int32Array.from({ length: n }, (_, i) => i - 1);
      const next = Int32Array.from({ length: n }, (_, i) => i + 1);
      // The faces as they are while lines are simplified (before any replacement at the step's end).
      const left = resolveFaceAt(faces, edge.left, k, LAST_REMOVAL_PHASE);
      const right = resolveFaceAt(faces, edge.right, k, LAST_REMOVAL_PHASE);
      for (let r = 0; r < edge.removed.length; r++) {
        const i = pos.get(edge.removed[r]!);
        if (i === undefined) throw new Error(`edge ${e}: removed vertex ${edge.removed[r]} is not in its parent chain`);
        const a = chain[prev[i]!]!, v = chain[i]!, b = chain[next[i]!]!;
        next[prev[i]!] = next[i]!;
        prev[next[i]!] = prev[i]!;
        const o = orient(xs[a]!, ys[a]!, xs[b]!, ys[b]!, xs[v]!, ys[v]!);
        if (o === 0) continue;
        // v left of the new chord: the triangle passes from the right face to the left one.
        const z = phaseZ(k, edge.removedPhase[r]!);
        if (o > 0) out.add(a, b, v, z, left, right);
        else out.add(a, v, b, z, right, left);
        touch(left, z);
        touch(right, z);
        stats.simplify++;
      }
    }
    // Replaced faces: their whole area, as it is at the end of the step, drawn again.
    for (const [f, g] of reemits) stats.reemit += emitFace(g, k, phaseZ(k, REEMIT_PHASE), g, f);
  }
  // Each triangle matters until its upper face ends; after that newer surfaces cover it.
  for (let i = 0; i < out.count; i++) {
    const u = out.upper[i]!;
    out.zEnd[i] = u > 0 ? Math.min(zTop, faceEndZ(faces[u]!, steps)) : zTop;
  }
  return { surfaces: out, stats, transitions };
}
