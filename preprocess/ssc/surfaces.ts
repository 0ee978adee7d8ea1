// The Space-Scale Cube's surfaces from a tGAP: the tGAP is replayed step by step and every
// change of a point's face becomes a horizontal triangle between the old face (lower) and the
// new one (upper), at the z of the step's phase (docs/FORMAT.md):
// - the floor (z = 0): every input face, nothing below;
// - a merge: the loser's area (and, when the winner is replaced by a new face, the winner's);
//   with `smooth`, tilted instead: a front rising from the boundary the loser shares with the
//   winner, up to a zoom level before the merge, above the older surfaces (smooth-merge.ts);
// - a split: the triangles the split gave each receiving face; with `smooth`, tilted per
//   receiving face as a merge of that part into it;
// - simplification: each removed vertex's triangle, between the faces on either side; with
//   `smooth`, tilted from the removed corner up to the removal. A smooth cube leaves out the
//   re-emits of faces that end soon after (late-reemits.ts) and those a merge held back may
//   cross (hold-line.ts); a face held back keeps showing until its winner's line brings its
//   class back, handed on by a split to the part whose face's line does (followSplit).
import { snapNewVertices } from '../geom/snap-new-vertices.js';
import { planeDeficit } from '../geom/plane-deficit.js';
import { orient } from '../geom/predicates.js';
import { crossesRightOf } from '../../format/face-rings.js';
import { scaleAtZ, zAtScale, type ScaleInfo } from '../../format/scale.js';
import { EventKind, faceEndZ, faceStartZ, LAST_REMOVAL_PHASE, phaseZ, REEMIT_PHASE, replacedFaces, resolveFace, resolveFaceAt, scaleInfoOf, type Tgap, type TgapEvent } from '../../format/tgap-model.js';
import { smoothMergeZ } from './smooth-merge.js';
import { EdgeSideTimes, Side } from './edge-side-times.js';
import { edgeKey, splitChords } from './split-chords.js';
import { skipLateReemits } from './late-reemits.js';
import { holdLimitZ, reemitBefore, reemitsHeldAcross, returnOnLine } from './hold-line.js';
import { removalHeights } from './removal-heights.js';
import { SurfacesByFace } from './surfaces-by-face.js';
import { triangulateFace, type FaceEdge, type TriangulateStats } from './triangulate-face.js';
import { ZoomTime } from './zoom-time.js';
import { AreaIndex } from './area-index.js';
import { meshPieces } from './mesh-pieces.js';

export class Surfaces {
  count = 0;
  /**
   * Vertex coordinates by id: the tGAP's, and after them the few a smooth cube adds (chord
   * midpoints, split-chords.ts).
   */
  xs: Float64Array;
  ys: Float64Array;
  vertexCount: number;
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

  constructor(xs: Float64Array = new Float64Array(0), ys: Float64Array = new Float64Array(0)) {
    this.xs = xs;
    this.ys = ys;
    this.vertexCount = xs.length;
  }

  /** The centre of the triangle with corners a, b, c (vertex ids). */
  centre(a: number, b: number, c: number): [number, number] {
    return [(this.xs[a]! + this.xs[b]! + this.xs[c]!) / 3, (this.ys[a]! + this.ys[b]! + this.ys[c]!) / 3];
  }

  /** The vertex ids of triangles first..end (not included) whose upper face is `face`. */
  trianglesOf(first: number, end: number, face: number): number[] {
    const out: number[] = [];
    for (let i = first; i < end; i++) if (this.upper[i] === face) out.push(this.v[3 * i]!, this.v[3 * i + 1]!, this.v[3 * i + 2]!);
    return out;
  }

  /** A new vertex at (x, y); returns its id. */
  addVertex(x: number, y: number): number {
    if (this.vertexCount === this.xs.length) {
      // Copied on the first one: the tGAP's own arrays are not ours to grow.
      const n = Math.max(16, this.xs.length + (this.xs.length >> 3));
      for (const k of ['xs', 'ys'] as const) {
        const a = new Float64Array(n);
        a.set(this[k]);
        this[k] = a;
      }
    }
    this.xs[this.vertexCount] = x;
    this.ys[this.vertexCount] = y;
    return this.vertexCount++;
  }

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
  /** Simplification triangles drawn tilted (smooth), of `simplify`. */
  tiltedRemovals: number;
  /** A split's parts given to one neighbour drawn tilted (smooth). */
  tiltedSplits: number;
  /** Triangles added by splitting chords between shared-boundary vertices (smooth merges). */
  chordSplits: number;
  /** Merges held back (a cascade that would send the loser's area back to its class). */
  heldMerges: number;
  /** Removals left out of a smooth cube: a sliver handed to a face that soon merges back into its giver. */
  skippedRemovals: number;
  /** Faces triangulated without their slivers' notches, which no longer fit. */
  notchFallbacks: number;
  /** Slivers left out (givesBack) that a re-emit of their giver does not take along: drawn for the face that holds them then (with the giver's new id, maybe). */
  sliversHandedOn: number;
  /** The same slivers that such a face and the giver's new id do not hold between them: they go on showing the giver. */
  sliversLeftShowing: number;
  /** Parts of splits given to a face held back in their receiving face, which shows beside them. */
  splitPartsToHeld: number;
  /** Pieces of a loser's (or split part's) area that the winner lay beside nowhere, given to a face held back in it. */
  piecesToHeld: number;
  /** Faces held back in a split face that stay, held back in the face a part goes to (its line brings their class back). */
  splitFollows: number;
  /** Removals' triangles given likewise to a face held back in their upper face. */
  removalsToHeld: number;
  /** Merges whose loser goes likewise to a face held back in the winner. */
  mergesToHeld: number;
  /** Vertices added at the centre of ramp triangles whose corners all wait at one z. */
  apexes: number;
}

/** What made a run of surface triangles (bench/explain-frames.ts attributes a frame's changes to it). */
export type OriginKind = 'floor' | 'merge' | 'split' | 'simplify' | 'reemit';

/**
 * Triangles first..end (not including end) of the surfaces came from one event of `step`:
 * a merge, one receiving face's part of a split,
 * the removals of one edge version, a re-emit, or one face's floor. `face`: the loser (the
 * lower face of a removal), `into`: the winner (the upper face).
 */
export interface SurfaceOrigin {
  kind: OriginKind;
  step: number;
  face: number;
  into: number;
  first: number;
  end: number;
}

/** A removal left out (givesBack): its triangle, the vertex removed, and the face it would have gone to. */
interface Sliver {
  tri: number[];
  v: number;
  face: number;
}

export interface SurfaceOptions {
  /** Smooth merges: the loser's area tilted over its transition (docs/FORMAT.md, "Smooth cube"). */
  smooth?: boolean;
  /** The chunks' coarsest grid: the points the surfaces make go onto it where they can (snap-new-vertices.ts; 0: none). */
  snapStep?: number;
}

/**
 * How far a smooth merge may reach back: at most this factor in scale before the merge (one
 * zoom level, the map's default zoom step). Measured at 1280x720: x2.83 took Otterlo's worst
 * frame from 0.942% to 0.902% (nlcd_zion's stayed 0.290%; x4: 1.024%), but left 4 of
 * bgt_otterlo_400m's 337 merges with raster pixels apart from the winner at 4x (e2e
 * pipeline-cube allows 3; exactly, all attached), so it stays one zoom level.
 */
export const MAX_TRANSITION_RATIO = 2;

/**
 * How far a tilted surface stays above an older one it overlaps, in steps: a 32nd of a step
 * still differs in float32 up to about 2^17 steps, so the two never tie in depth.
 */
export const SURFACE_GAP = 1 / 32;

/**
 * How long a merge may be held back (a cascade that would send its area back to its class): its
 * loser may stay until at most this factor in scale after its own merge (three zoom levels).
 * Measured on bgt_otterlo_1800m (bench:explain, sliced at 1280x720), holding along the winner's
 * whole line: x4 left 84 pixels of flicker, x8 30, x16 30; the worst frame 0.453%, 0.447%, 0.439%.
 */
export const MAX_HOLD_RATIO = 8;

/** Rounds of holding up a ramp where it would dip under an older surface, before the corner rule. */
const EXACT_ROUNDS = 6;

/** Where a merge's (or a split part's) transition starts, and where its ramp triangles end in the surfaces. */
interface Ramp {
  zStart: number;
  end: number;
  /** The earliest z its front could leave the shared boundary (zMerge: none), before any wait above older surfaces. */
  zFront: number;
  /** Faces held back in the winner that took pieces of the area the winner lies beside nowhere (emitTilted). */
  takers?: number[];
}

/** A removed vertex's triangle (counterclockwise), passing from `lower` to `upper` at its phase. */
interface Removal {
  tri: number[];
  v: number;
  upper: number;
  lower: number;
  edge: number;
  /** The upper face's side of the edge. */
  side: Side;
  phase: number;
}

/** A face whose merge was held back (a cascade): its area, and its transition (that of the merge that carries it on). */
interface Held {
  face: number;
  area: AreaIndex;
  transition: MergeTransition;
  /** The z until which it shows (the end of the face of its winner's line that carries it on: returnOnLine), as far as known when it was last held. */
  until: number;
}

/**
 * A merge's transition: from zStart, the last z at which the loser is whole (half a gap below
 * its tilted surface's lowest vertex, above every older surface there), to zMerge, the merge's
 * z, from which it is gone (zStart = zMerge: no room, drawn horizontal).
 */
export interface MergeTransition {
  step: number;
  loser: number;
  into: number;
  zStart: number;
  zMerge: number;
  /**
   * What bounded zStart: the earliest start allowed (reachBackZ), and the
   * earliest z at which the front could leave the shared boundary (the winner beside it).
   */
  zFoot: number;
  zFront: number;
  /** Drawn tilted (with --smooth, room in z and a vertex off the shared boundary). */
  tilted: boolean;
  /**
   * Held back (a smooth cube's cascade that would send the loser's area back to its class): the
   * loser stays until a merge or split further along its winner's line (hold-line.ts), whose ramp
   * (zStart to zMerge) carries its area on; it has no ramp of its own (first = end).
   */
  held?: boolean;
  /** The faces held back in the loser's area whose areas this merge's ramp carries on (their lower face under it). */
  carries?: number[];
  /**
   * The face held back in the winner that takes the loser's area, when it shows along all of
   * their shared boundary (its ramp's upper face; its area then moves on with that face's).
   */
  shownAs?: number;
  /** Faces held back in the winner that took the pieces of the loser's area beside which only they lay (as shownAs takes all of it). */
  takers?: number[];
  /**
   * Its ramp's triangles in the surfaces: from `first` up to (not including) `end`; their upper
   * face is the winner (`shownAs` when set; the winner's id at the merge, also where the ramp
   * lies below a re-emit of the winner).
   */
  first: number;
  end: number;
}

/**
 * A smooth split (a smooth cube's only): from zStart, where the first of its parts starts to go
 * to a neighbour, to zSplit, the split's z, where the face has closed.
 */
export interface SplitTransition {
  step: number;
  loser: number;
  zStart: number;
  zSplit: number;
  /** The faces held back in the split face's area that its parts carry on (their lower face under them). */
  carries?: number[];
}

/**
 * The earliest z of a transition ending at z: one zoom level before, and within the first two
 * levels half way (in scale) back to the base scale, so that their transitions do not all start
 * at the floor (where the map starts, every one of them would be moving at once). It grows with
 * z, and z only grows as the tGAP is replayed, so older surfaces below it are never needed again.
 */
export function reachBackZ(info: ScaleInfo, z: number): number {
  const scale = scaleAtZ(info, z);
  return zAtScale(info, scale / Math.min(MAX_TRANSITION_RATIO, Math.sqrt(scale / info.baseScale)));
}

/**
 * The surfaces of the cube built from tGAP `input`, and the tGAP they name faces of: with
 * `smooth`, `input` without the re-emits of faces that end soon after (late-reemits.ts) and of
 * those a hold may cross (hold-line.ts), whose faces are the ones to write beside the surfaces.
 */
export function buildSurfaces(input: Tgap, opts: SurfaceOptions = {}): { surfaces: Surfaces; stats: SurfaceStats; transitions: MergeTransition[]; splits: SplitTransition[]; origins: SurfaceOrigin[]; tgap: Tgap } {
  // The scale of every step: skipping re-emits keeps the tGAP's meta.
  const scaleInfo = scaleInfoOf(input);
  const t = opts.smooth ? skipLateReemits(input, (z) => reachBackZ(scaleInfo, z), reemitsHeldAcross(input, scaleInfo, MAX_HOLD_RATIO)).tgap : input;
  const steps = t.meta.steps;
  const zTop = steps + 1;
  const out = new Surfaces(t.xs, t.ys);
  const snapStep = opts.snapStep ?? 0;
  const stats: SurfaceStats = { earcut: 0, fallback: 0, failed: 0, floor: 0, merge: 0, split: 0, simplify: 0, reemit: 0, tiltedMerges: 0, tiltedRemovals: 0, tiltedSplits: 0, chordSplits: 0, heldMerges: 0, skippedRemovals: 0, notchFallbacks: 0, sliversHandedOn: 0, sliversLeftShowing: 0, splitPartsToHeld: 0, splitFollows: 0, piecesToHeld: 0, removalsToHeld: 0, mergesToHeld: 0, apexes: 0 };
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
  // What bounds a smooth merge's start besides the older surfaces in the loser's area
  // (SurfacesByFace): per face, the z of its re-emit (the winner's id must be the one shown
  // beside the loser); per edge, the z of its birth or of the last change of a face on its sides
  // (a boundary the loser came to share with the winner when a neighbour merged into the winner:
  // the winner's side must be the winner's, the neighbour's transition over, so that what the
  // winner gains stays attached to it).
  const sides = new EdgeSideTimes(edges);
  /**
   * f's side of its edges changed at z (f merged, split or was replaced; `at` resolves an edge's
   * faces as f had them); with `hold`, f still shows there until z (its merge held back).
   */
  const relabel = (f: number, z: number, at: (face: number) => number, hold = false): void => {
    for (const e of faceEdges.get(f) ?? []) {
      const edge = edges[e]!;
      for (const side of [Side.Left, Side.Right]) {
        if (at(side === Side.Left ? edge.left : edge.right) !== f) continue;
        if (hold) sides.hold(e, side, z);
        else sides.relabel(e, side, z);
      }
    }
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
  /** The face each re-emitted face replaced (a sliver's lower face may have been re-emitted: givesBack). */
  const replaced = opts.smooth ? replacedFaces(faces) : undefined;
  const reachBack = (z: number): number => reachBackZ(scaleInfo, z);
  /** The lowest z a surface given at z may start from: no further back than reachBackZ, and above the floor. */
  const footOf = (z: number): number => Math.max(SURFACE_GAP, reachBack(z));
  /** Fronts advance evenly in zoom, not in z (zoom-time.ts), and by the share of the area passed (evenArea). */
  const time = new ZoomTime(scaleInfo);
  const byFace = opts.smooth ? new SurfacesByFace(out) : undefined;
  /** Surfaces from `from` up to the last one added lie in `face`'s area (smooth cubes only). */
  const lieIn = (face: number, from: number): void => {
    if (byFace) for (let i = from; i < out.count; i++) byFace.add(face, i);
  };
  /**
   * Per face, the slivers it gained and never shows (givesBack): the vertex each removal took
   * off a segment of its boundary, by the segment (edgeKey). Put back, they keep the slivers
   * out of the face's area: its ramp then covers only what it shows.
   */
  const notches = new Map<number, Map<string, number>>();
  /** Edge e's chain, with face f's notches put back. */
  const chainFor = (e: number, f: number): ArrayLike<number> => {
    const verts = edges[e]!.verts;
    const m = notches.get(f);
    if (!m) return verts;
    const chain = Array.from(verts);
    let changed = false;
    for (let i = 0; i + 1 < chain.length; i++) {
      const v = m.get(edgeKey(chain[i]!, chain[i + 1]!));
      if (v === undefined || chain.includes(v)) continue;
      // Look at the new segment chain[i]-v again: an earlier notch may lie on it.
      chain.splice(i + 1, 0, v);
      changed = true;
      i--;
    }
    return changed ? chain : verts;
  };
  /** Triangulates face f's area at state s into `tris`; returns the triangle count. */
  const triangulate = (f: number, s: number): number => {
    tris.length = 0;
    const set = faceEdges.get(f);
    if (!set) return 0;
    const fe: FaceEdge[] = [];
    const plain: FaceEdge[] = [];
    for (const e of [...set].sort((a, b) => a - b)) {
      const edge = edges[e]!;
      const l = resolveFace(faces, edge.left, s);
      const r = resolveFace(faces, edge.right, s);
      if (l === f && r === f) continue;
      fe.push({ verts: chainFor(e, f), forward: l === f });
      plain.push({ verts: edge.verts, forward: l === f });
    }
    // A notch that no longer fits (a boundary of the face has since been simplified across it):
    // the face's area as the tGAP has it, the sliver's lower face then named approximately.
    if (notches.has(f) && triangulateNotched(fe, tris)) return tris.length / 3;
    return triangulateFace(plain, xs, ys, tris, stats);
  };
  /**
   * Triangulates an outline with notches into `into`; false (nothing added, a notch fallback
   * counted) when the notches no longer fit. Counted only if it holds: a failed try is not a
   * failed triangulation.
   */
  const triangulateNotched = (outline: FaceEdge[], into: number[]): boolean => {
    const trial: TriangulateStats = { earcut: 0, fallback: 0, failed: 0 };
    const before = into.length;
    try {
      triangulateFace(outline, xs, ys, into, trial);
    } catch {
      into.length = before;
      stats.notchFallbacks++;
      return false;
    }
    stats.earcut += trial.earcut;
    stats.fallback += trial.fallback;
    stats.failed += trial.failed;
    return true;
  };
  /**
   * A split's part (`area`, triangles of the split face f) without f's slivers (givesBack): where
   * one's chord is a side of the part's outline, the outline goes round its notch, and the part
   * is triangulated again. The part as it is when it has no such side, or when that fails.
   */
  const withoutSlivers = (f: number, area: number[]): number[] => {
    const m = notches.get(f);
    if (!m) return area;
    const directed = new Set<string>();
    for (let i = 0; i < area.length; i += 3) for (let j = 0; j < 3; j++) directed.add(`${area[i + j]}>${area[i + (j + 1) % 3]}`);
    const outline: FaceEdge[] = [];
    let notched = false;
    for (let i = 0; i < area.length; i += 3) {
      for (let j = 0; j < 3; j++) {
        const p = area[i + j]!, q = area[i + (j + 1) % 3]!;
        if (directed.has(`${q}>${p}`)) continue; // inside the part
        const v = m.get(edgeKey(p, q));
        notched ||= v !== undefined;
        outline.push({ verts: v === undefined ? [p, q] : [p, v, q], forward: true });
      }
    }
    if (!notched) return area;
    const out: number[] = [];
    return triangulateNotched(outline, out) ? out : area;
  };
  /** Triangulates face f's current area and adds it at z with the given upper and lower faces. */
  const emitFace = (f: number, s: number, z: number, upper: number, lower: number): number => {
    const n = triangulate(f, s);
    for (let i = 0; i < tris.length; i += 3) out.add(tris[i]!, tris[i + 1]!, tris[i + 2]!, z, upper, lower);
    return n;
  };
  /**
   * The loser's area (state s) tilted: a front leaves the boundary shared with the winner, no
   * earlier than zFoot, and waits above the older surfaces still in the loser's area
   * (smooth-merge.ts); or flat at zMerge when it cannot tilt. Returns its Ramp.
   */
  const emitSmoothMerge = (byFace: SurfacesByFace, loser: number, into: number, s: number, sharedWithInto: number[], zFoot: number, zMerge: number, key: string, lowerOf?: (a: number, b: number, c: number) => number): Ramp => {
    triangulate(loser, s);
    // The winner may have been re-emitted during the transition: the ramp names its id at the
    // merge throughout (the same class and attributes as the ids before).
    const ramp = emitTilted(byFace, tris, loser, into, s, sharedWithInto, zFoot, zMerge, key, 'merge', into, lowerOf);
    if (ramp.zStart < zMerge) stats.tiltedMerges++;
    return ramp;
  };
  /**
   * The ramp with waits only where needed: solved without, then each triangle whose plane comes
   * within `SURFACE_GAP` of an older surface where they overlap (planeDeficit, exact) has its
   * corners held up by the shortfall, and the front is run again; a triangle that this would
   * lift past zMerge at a corner has its corners held above every older surface around them instead
   * (`aboveAll`: those waits, flat only there, not over the whole ramp). null when that does not
   * settle within EXACT_ROUNDS (or the ramp cannot tilt).
   */
  const exactRamp = (own: number[], pairs: readonly [number, number][], zMerge: number, solve: (waits: ReadonlyMap<number, number>) => Map<number, number> | null, aboveAll: () => ReadonlyMap<number, number>): Map<number, number> | null => {
    const waits = new Map<number, number>();
    let above: ReadonlyMap<number, number> | undefined;
    const a = new Float64Array(6), b = new Float64Array(6), za = new Float64Array(3), zb = new Float64Array(3);
    for (let round = 0; round < EXACT_ROUNDS; round++) {
      const z = solve(waits);
      if (!z || pairs.length === 0) return z;
      let short = 0;
      for (const [i, t] of pairs) {
        for (let k = 0; k < 3; k++) {
          const w = own[i + k]!, u = out.v[3 * t + k]!;
          a[2 * k] = out.xs[w]!; a[2 * k + 1] = out.ys[w]!; za[k] = z.get(w) ?? zMerge;
          b[2 * k] = out.xs[u]!; b[2 * k + 1] = out.ys[u]!; zb[k] = out.z[3 * t + k]!;
        }
        const deficit = planeDeficit(a, za, b, zb, SURFACE_GAP);
        if (!(deficit > 0)) continue;
        short++;
        // A margin on top, so that rounding does not leave it a hair short again. Where that
        // would lift a corner past zMerge, the corners wait above everything older around them instead.
        const lift = Math.max(za[0]!, za[1]!, za[2]!) + deficit + SURFACE_GAP / 8 > zMerge;
        if (lift) above ??= aboveAll();
        for (let k = 0; k < 3; k++) {
          const w = own[i + k]!;
          waits.set(w, Math.max(waits.get(w) ?? -Infinity, lift ? above!.get(w) ?? -Infinity : za[k]! + deficit + SURFACE_GAP / 8));
        }
      }
      if (short === 0) return z;
    }
    return null;
  };
  /** Which side of edge e face f has at state s. */
  const sideOf = (e: number, f: number, s: number): Side => (resolveFace(faces, edges[e]!.left, s) === f ? Side.Left : Side.Right);
  /**
   * Part of the loser's area (`area`, triangles of state s) given to `into` at zMerge, tilted as
   * a smooth merge is (a front from their shared boundary); or flat at zMerge when it cannot
   * tilt. Its upper face is `taker`: into (its id at zMerge, below a re-emit too), or a face held
   * back in into that shows where the part lies (`holds` false then: a vertex may start once that
   * face lies beside it). Returns where its transition starts (zMerge: flat) and where its ramp's
   * triangles end.
   */
  const emitTilted = (
    byFace: SurfacesByFace, area: number[], loser: number, into: number, s: number, sharedWithInto: number[], zFoot: number, zMerge: number, key: string, kind: 'merge' | 'split',
    taker = into, lowerOf: (a: number, b: number, c: number) => number = () => loser, holds = true,
    upperOf?: (a: number, b: number, c: number) => number | undefined,
  ): Ramp => {
    // A vertex of the shared boundary may start once the winner lies beside it, and only where
    // the ramp's upper face (`taker`: the winner, or the face held back in it that takes the
    // area) shows beside it, not only another face held back in the winner: what the winner
    // takes stays attached to what shows of it.
    const shared = sharedTimes(sharedWithInto, loser, into, s, holds);
    if (!held.has(into)) return emitRamp(byFace, area, loser, shared.times, shared.segments, zFoot, zMerge, key, kind, taker, lowerOf, upperOf);
    const beside = facesBeside(sharedWithInto, loser, into, s);
    for (const [v, fs] of beside) if (!fs.has(taker)) shared.times.set(v, Math.max(shared.times.get(v) ?? zMerge, zMerge));
    // A piece of the area (connected) that the winner lies beside nowhere before zMerge goes to
    // the face shown beside most of its boundary (held back in the winner), from when that face
    // lay there; else its ramp could not leave the boundary and would lie flat.
    let own: Map<number, number> | undefined;
    const pieceFace = new Map<number, number>();
    for (const piece of meshPieces(area)) {
      if (piece.some((v) => (shared.times.get(v) ?? Infinity) < zMerge)) continue;
      const count = new Map<number, number>();
      for (const v of piece) for (const f of beside.get(v) ?? []) if (f !== taker) count.set(f, (count.get(f) ?? 0) + 1);
      let h = -1, most = 0;
      for (const [f, n] of count) if (n > most || (n === most && f < h)) [h, most] = [f, n];
      own ??= sharedTimes(sharedWithInto, loser, into, s, false).times;
      // With no held face beside it, the winner's, from the times without the holds.
      const keep = h < 0;
      for (const v of piece) {
        const z = own.get(v);
        if (z !== undefined && (keep || beside.get(v)?.has(h))) shared.times.set(v, z);
        if (!keep) pieceFace.set(v, h);
      }
      if (!keep) stats.piecesToHeld++;
    }
    // The pieces' own areas, for a triangle of new vertices only (the middle of a triangle whose
    // three sides are chords).
    const pieceAreas = new Map<number, AreaIndex>();
    for (let i = 0; i < area.length; i += 3) {
      const f = pieceFace.get(area[i]!);
      if (f === undefined) continue;
      const tri = [area[i]!, area[i + 1]!, area[i + 2]!];
      const a = pieceAreas.get(f);
      if (a) a.add(tri, out.xs, out.ys);
      else pieceAreas.set(f, new AreaIndex(tri, out.xs, out.ys));
    }
    const first = out.count;
    const ramp = emitRamp(byFace, area, loser, shared.times, shared.segments, zFoot, zMerge, key, kind, taker, lowerOf, (a, b, c) => {
      const f = upperOf?.(a, b, c) ?? pieceFace.get(a) ?? pieceFace.get(b) ?? pieceFace.get(c);
      if (f !== undefined || pieceAreas.size === 0) return f;
      const [x, y] = out.centre(a, b, c);
      for (const [g, pa] of pieceAreas) if (pa.contains(x, y)) return g;
      return undefined;
    });
    // What a face held back in the winner took (the taker's part, or pieces) joins its area and
    // moves on with it.
    const takers: number[] = [];
    for (const h of held.get(into)!) {
      const l = out.trianglesOf(first, ramp.end, h.face);
      if (l.length === 0) continue;
      h.area.add(l, out.xs, out.ys);
      if (pieceAreas.has(h.face)) takers.push(h.face);
    }
    return takers.length > 0 ? { ...ramp, takers: takers.sort((p, q) => p - q) } : ramp;
  };
  /**
   * Per vertex of the loser's boundary with `into` (edges `sharedWithInto`, state s, with the
   * loser's notches), the faces shown just beside its segments on into's side: into itself, or
   * a face held back in it (innermost first).
   */
  const facesBeside = (sharedWithInto: number[], loser: number, into: number, s: number): Map<number, Set<number>> => {
    const inInto = held.get(into) ?? [];
    const out = new Map<number, Set<number>>();
    for (const e of sharedWithInto) {
      const toward = sideOf(e, into, s) === Side.Left ? 1 : -1;
      const verts = chainFor(e, loser);
      for (let i = 0; i + 1 < verts.length; i++) {
        const p = verts[i]!, q = verts[i + 1]!;
        const [x, y] = besidePoint(p, q, toward);
        const f = inInto.find((h) => h.area.contains(x, y))?.face ?? into;
        for (const v of [p, q]) {
          let set = out.get(v);
          if (!set) out.set(v, (set = new Set()));
          set.add(f);
        }
      }
    }
    return out;
  };
  /** The point a millionth of segment p-q's length off its middle, on its left (`toward` 1) or right (-1). */
  const besidePoint = (p: number, q: number, toward: 1 | -1): [number, number] => {
    const dx = xs[q]! - xs[p]!, dy = ys[q]! - ys[p]!;
    // Left of p -> q is (-dy, dx).
    return [(xs[p]! + xs[q]!) / 2 - toward * dy * 1e-6, (ys[p]! + ys[q]!) / 2 + toward * dx * 1e-6];
  };
  /**
   * Per vertex of the loser's boundary with `into` (edges `sharedWithInto`, state s, with the
   * loser's notches), the z from which its front may leave it; and that boundary's segments.
   */
  const sharedTimes = (sharedWithInto: number[], loser: number, into: number, s: number, holds: boolean): { times: Map<number, number>; segments: Set<string> } => {
    const shared = new Map<number, number>();
    const segments = new Set<string>();
    for (const e of sharedWithInto) {
      const times = sides.vertexTimes(e, sideOf(e, into, s), holds);
      const verts = chainFor(e, loser);
      /** The time of the nearest vertex of the edge itself from i, going by `step`. */
      const near = (i: number, step: number): number => {
        for (let j = i; j >= 0 && j < verts.length; j += step) {
          const z = times.get(verts[j]!);
          if (z !== undefined) return z;
        }
        return -Infinity;
      };
      for (let i = 0; i < verts.length; i++) {
        // A notch's vertex lies beside the winner since the edge's vertices either side of it do, at the latest.
        const z = times.get(verts[i]!) ?? Math.max(near(i, -1), near(i, 1));
        shared.set(verts[i]!, Math.max(shared.get(verts[i]!) ?? -Infinity, z + SURFACE_GAP));
      }
      // With the notches, and without (if they no longer fit, the triangulation has the plain chain).
      for (const chain of [verts, edges[e]!.verts]) for (let i = 0; i + 1 < chain.length; i++) segments.add(edgeKey(chain[i]!, chain[i + 1]!));
    }
    return { times: shared, segments };
  };
  /** emitTilted's ramp, from the shared boundary's times. */
  const emitRamp = (
    byFace: SurfacesByFace, area: number[], loser: number, shared: ReadonlyMap<number, number>, segments: ReadonlySet<string>, zFoot: number, zMerge: number, key: string, kind: 'merge' | 'split',
    upper: number, lowerOf: (a: number, b: number, c: number) => number, upperOf?: (a: number, b: number, c: number) => number | undefined,
  ): Ramp => {
    const firstNew = out.vertexCount;
    const own = splitChords(area, out.xs, out.ys, (v) => shared.has(v), (a, b) => segments.has(edgeKey(a, b)), (x, y) => out.addVertex(x, y));
    snapNewVertices(own, out.xs, out.ys, firstNew, out.vertexCount, snapStep);
    stats[kind] += own.length / 3;
    stats.chordSplits += (own.length - area.length) / 3;
    const pairs = byFace.overlapping(loser, own, zFoot, SURFACE_GAP, reachBack(zMerge));
    const solve = (waits: ReadonlyMap<number, number>): Map<number, number> | null => smoothMergeZ(own, out.xs, out.ys, shared, { zFoot, zMerge, lowest: waits, time, evenArea: true });
    const aboveAll = (): ReadonlyMap<number, number> => byFace.waitsAbove(own, pairs, SURFACE_GAP);
    const z = exactRamp(own, pairs, zMerge, solve, aboveAll) ?? solve(aboveAll());
    /** The apexes added to triangles that would lie flat below zMerge (below), and their z. */
    const apexes = new Map<number, number>();
    const zOf = (v: number): number => apexes.get(v) ?? z?.get(v) ?? zMerge;
    let zLow = zMerge;
    const emitOne = (a: number, b: number, c: number, lower: number, up: number): void => {
      const za = zOf(a), zb = zOf(b), zc = zOf(c);
      zLow = Math.min(zLow, za, zb, zc);
      out.addTilted(a, b, c, za, zb, zc, up, lower, `${key}${lower === loser ? '' : `/${lower}`}${up === upper ? '' : `^${up}`}`);
    };
    for (let i = 0; i < own.length; i += 3) {
      const a = own[i]!, b = own[i + 1]!, c = own[i + 2]!;
      const lower = lowerOf(a, b, c);
      // A face held back in the loser that stays (a split hands it on) is also the upper face
      // over its own area: lower and upper are then one face, so blending toward the lower face
      // changes nothing there.
      const up = upperOf?.(a, b, c) ?? upper;
      if (!z) {
        out.add(a, b, c, zMerge, up, lower);
        continue;
      }
      const za = zOf(a);
      if (za === zOf(b) && za === zOf(c) && za < zMerge && faces[lower]!.classIndex !== faces[up]!.classIndex) {
        // All three corners wait at one z (above an older surface): flat, its area would change
        // class at once. An apex at its centre, half way to zMerge, makes it recede from its
        // sides to the centre instead; above the corners, it stays above what they wait for.
        const m = out.addVertex(...out.centre(a, b, c));
        snapNewVertices([a, b, m, b, c, m, c, a, m], out.xs, out.ys, m, m + 1, snapStep);
        apexes.set(m, za + (zMerge - za) / 2);
        stats.apexes++;
        emitOne(a, b, m, lower, up);
        emitOne(b, c, m, lower, up);
        emitOne(c, a, m, lower, up);
      } else {
        emitOne(a, b, c, lower, up);
      }
    }
    const end = out.count;
    let zFront = Infinity;
    for (const t of shared.values()) zFront = Math.min(zFront, Math.max(t, zFoot));
    return { zStart: z ? zLow - SURFACE_GAP / 2 : zMerge, end, zFront: Math.min(zFront, zMerge) };
  };
  /**
   * Where a smooth removal's corner starts to recede: the triangle (a, v, b) tilts from its
   * corner v (the receding vertex) up to its chord, at the removal's z or before it when later
   * removals of the step overlap it (removal-heights.ts), so the upper face takes
   * it from the corner, beside which it lies. No further back than reachBackZ, nor before
   * the upper face lay beside the corner (its side of the parent chain; a face held back there
   * counts from its own time: that side shows it until the corner recedes), and above every
   * older surface in the losing face's area. A re-emit of the upper face does not hold it: the
   * triangle names the new id before it (the same face).
   */
  const smoothRemovalStart = (byFace: SurfacesByFace, tri: number[], lower: number, z: number, line?: { edge: number; side: Side }): number => {
    const zCap = reachBack(z);
    let start = footOf(z);
    // After the removals before it on its line (a sliver handed on has none).
    if (line) {
      const times = sides.parentTimes(line.edge, line.side, false);
      for (const w of tri) start = Math.max(start, (times.get(w) ?? z) + SURFACE_GAP);
    }
    // Above the older surfaces it overlaps in the losing face's area.
    for (const w of byFace.lowestZ(lower, tri, start, SURFACE_GAP, zCap).values()) start = Math.max(start, w);
    return Math.min(start, z);
  };
  /**
   * Points that say where a sliver (a removal's triangle, corner v) lies: its centre, the corner,
   * the middles of its sides at v, and just inside the middle of the chord, where a triangle on
   * the chord may hold only a thin strip of it. Flat [x, y, ...].
   */
  const sliverProbes = (tri: readonly number[], v: number): number[] => {
    const [a, b] = tri.filter((w) => w !== v) as [number, number];
    const mx = (xs[a]! + xs[b]!) / 2, my = (ys[a]! + ys[b]!) / 2;
    return [
      (xs[a]! + xs[b]! + xs[v]!) / 3, (ys[a]! + ys[b]! + ys[v]!) / 3, xs[v]!, ys[v]!,
      (xs[a]! + xs[v]!) / 2, (ys[a]! + ys[v]!) / 2, (xs[b]! + xs[v]!) / 2, (ys[b]! + ys[v]!) / 2,
      mx + (xs[v]! - mx) * 1e-6, my + (ys[v]! - my) * 1e-6,
    ];
  };
  /**
   * A removal that hands `lower`'s triangle to `upper` at z, when `upper` then merges into
   * `lower` within reach of z, or is split with the sliver going to `lower`: in a smooth cube
   * the sliver stays `lower`'s, as `upper`'s ramp soon takes its area to `lower` anyway. Drawn,
   * it would change twice (lower, upper, lower), and the ramp would have to wait above it where
   * it starts, on the shared boundary.
   */
  const givesBack = (upper: number, lower: number, z: number, tri: readonly number[], v: number): boolean => {
    const f = faces[upper]!;
    if (!(f.endPhase === 0 && f.stepHigh <= steps && reachBack(phaseZ(f.stepHigh, 0)) <= z)) return false;
    // `lower`, or `lower` under the id a re-emit gave it meanwhile.
    const isLower = (g0: number): boolean => {
      for (let g: number | undefined = g0; g !== undefined; g = replaced!.get(g)) if (g === lower) return true;
      return false;
    };
    if (f.mergedInto > 0) return isLower(f.mergedInto);
    // A split: the sliver (sliverProbes) lies in the split's triangles that go to `lower`, so
    // that its part can leave the sliver out.
    const split = splitOf.get(upper);
    if (!split) return false;
    const probes = sliverProbes(tri, v);
    const tv = split.tris!, tf = split.triFaces!;
    const toLower: number[] = [], toOthers: number[] = [];
    for (let i = 0; i < tf.length; i++) (isLower(tf[i]!) ? toLower : toOthers).push(tv[3 * i]!, tv[3 * i + 1]!, tv[3 * i + 2]!);
    const lowerArea = new AreaIndex(toLower, xs, ys), otherArea = new AreaIndex(toOthers, xs, ys);
    for (let p = 0; p < probes.length; p += 2) {
      if (!lowerArea.contains(probes[p]!, probes[p + 1]!) || otherArea.contains(probes[p]!, probes[p + 1]!)) return false;
    }
    return true;
  };
  /**
   * Per face, the slivers left its own (givesBack) while the face that had them in the tGAP
   * is still there: a re-emit of the face draws them again under its new id, as it draws the
   * rest of its area (the tGAP's area no longer holds them).
   */
  const slivers = new Map<number, Sliver[]>();
  /**
   * Whether (x, y) lies in face f as its edges bound it now (even-odd over their segments; an
   * edge with f on both sides bounds nothing).
   */
  const insideFace = (f: number, x: number, y: number, k: number): boolean => {
    let inside = false;
    for (const e of faceEdges.get(f) ?? []) {
      const edge = edges[e]!;
      if (resolveFace(faces, edge.left, k) === resolveFace(faces, edge.right, k)) continue;
      const verts = edge.verts;
      for (let i = 0; i + 1 < verts.length; i++) {
        if (crossesRightOf(xs[verts[i]!]!, ys[verts[i]!]!, xs[verts[i + 1]!]!, ys[verts[i + 1]!]!, x, y)) inside = !inside;
      }
    }
    return inside;
  };
  /** Whether a and b follow each other on one of face f's edges (a sliver's chord is still its boundary). */
  const onBoundary = (f: number, a: number, b: number): boolean => {
    for (const e of faceEdges.get(f) ?? []) {
      const verts = edges[e]!.verts;
      for (let i = 0; i + 1 < verts.length; i++) if (edgeKey(verts[i]!, verts[i + 1]!) === edgeKey(a, b)) return true;
    }
    return false;
  };
  const transitions: MergeTransition[] = [];
  const splits: SplitTransition[] = [];
  const origins: SurfaceOrigin[] = [];
  /** The triangles from `first` to the last one added came from this event. */
  const origin = (kind: OriginKind, step: number, face: number, into: number, first: number): void => {
    if (out.count > first) origins.push({ kind, step, face, into, first, end: out.count });
  };

  /**
   * Cascades that would send an area back to its class (smooth cubes): a loser of class A whose
   * winner, of another class, has a line (its merges and re-emits, in turn) that comes back to A
   * within MAX_HOLD_RATIO: a face of it merges into a face of class A, or is split with some of
   * the loser's area going to faces of class A (hold-line.ts). Its area would show A, then other
   * classes, then A again (flicker); instead the loser stays until that face's ramp carries its
   * area on, so that its pixels keep class A throughout.
   * Per face, the faces held back in its area; per face held back, the merge that carried it on.
   */
  const held = new Map<number, Held[]>();
  const splitOf = new Map(t.events.filter((e) => e.kind === EventKind.Split).map((e) => [e.loser, e]));
  const carried = new Map<number, { step: number; into: number }>();
  /** Triangle i of a split's triangulation as [x0, y0, x1, y1, x2, y2]. */
  const splitTriangle = (split: TgapEvent, i: number): number[] => [0, 1, 2].flatMap((j) => [xs[split.tris![3 * i + j]!]!, ys[split.tris![3 * i + j]!]!]);
  /**
   * Whether a split gives some of `area` to a face of class cl: one of its triangles for such a
   * face overlaps the area (a road's split triangles span the road, and a run of them cut as
   * one may cross a small area with neither its centre nor a corner in it).
   */
  const givesBackTo = (split: TgapEvent, area: AreaIndex, cl: number): boolean => {
    const tf = split.triFaces!;
    for (let i = 0; i < tf.length; i++) if (faces[tf[i]!]!.classIndex === cl && area.overlaps(splitTriangle(split, i))) return true;
    return false;
  };
  /**
   * Where a split may hand on the hold of a face of class cl held back since zFirst in `area`:
   * to the face, not of class cl, that takes most of the area whose own line brings cl back
   * (returnOnLine: a merge into a face of class cl, or a split giving some of the area to cl)
   * within MAX_HOLD_RATIO of zFirst, with no re-emit on the way; and until when.
   * That part of the area would show cl, the part's class, then cl again.
   */
  const followSplit = (split: TgapEvent, area: AreaIndex, cl: number, zFirst: number): { into: number; until: number } | undefined => {
    const tv = split.tris!, tf = split.triFaces!;
    /** Per face taking some of the area, its triangles there. */
    const over = new Map<number, number[]>();
    for (let i = 0; i < tf.length; i++) {
      if (faces[tf[i]!]!.classIndex === cl || !area.overlaps(splitTriangle(split, i))) continue;
      let l = over.get(tf[i]!);
      if (!l) over.set(tf[i]!, (l = []));
      l.push(tv[3 * i]!, tv[3 * i + 1]!, tv[3 * i + 2]!);
    }
    const zLast = holdLimitZ(scaleInfo, zFirst, MAX_HOLD_RATIO);
    for (const [into, taken] of [...over].sort((p, q) => q[1].length - p[1].length || p[0] - q[0])) {
      const end = returnOnLine(faces, into, cl, steps, zLast);
      if (end < 0 || reemitBefore(faces, into, end)) continue;
      // A split at the end must give some of the area back to cl, as for any hold: of the area
      // itself, or of the triangles it would hold in `into` (the part's own, often wider).
      const last = splitOf.get(end);
      if (faces[end]!.mergedInto > 0 || (last && (givesBackTo(last, area, cl) || givesBackTo(last, new AreaIndex(taken, xs, ys), cl)))) return { into, until: phaseZ(faces[end]!.stepHigh, 0) };
    }
    return undefined;
  };
  /**
   * The z up to which the loser's merge into `into` at step k is held back (undefined: not
   * held); `loserArea` gives the loser's area, triangulated only when a split needs it.
   */
  const holdUntil = (loser: number, into: number, k: number, loserArea: () => AreaIndex): number | undefined => {
    const cl = faces[loser]!.classIndex;
    const z0 = phaseZ(k, 0);
    // Faces held in the loser that wait for a later step down the winner's line keep it waiting
    // with them (their area lies in its area).
    let until = -Infinity;
    for (const h of held.get(loser) ?? []) until = Math.max(until, h.until);
    if (until > z0) return until;
    const winnerClass = faces[into]!.classIndex;
    if (winnerClass === cl) return undefined;
    // Held back no longer than MAX_HOLD_RATIO in scale, for the loser and the faces held in it
    // (but those of the winner's class, which then show what the tGAP shows).
    let zFirst = z0;
    for (const h of held.get(loser) ?? []) if (faces[h.face]!.classIndex !== cl && faces[h.face]!.classIndex !== winnerClass) zFirst = Math.min(zFirst, h.transition.zMerge);
    const end = returnOnLine(faces, into, cl, steps, holdLimitZ(scaleInfo, zFirst, MAX_HOLD_RATIO));
    if (end < 0) return undefined;
    const zOn = phaseZ(faces[end]!.stepHigh, 0);
    if (faces[end]!.mergedInto > 0) return zOn;
    // Split: part of what it gives away over the loser's area goes to faces of the loser's
    // class, or the split can hand the hold on to a part whose face's line brings it back.
    const split = splitOf.get(end);
    if (!split) return undefined;
    if (givesBackTo(split, loserArea(), cl)) return zOn;
    return !reemitBefore(faces, into, end) && followSplit(split, loserArea(), cl, zFirst) ? zOn : undefined;
  };
  /** Under a ramp over the loser's area lies the loser, or a face held back in it (undefined: none held). */
  const lowerUnder = (loser: number): ((a: number, b: number, c: number) => number) | undefined => {
    const inLoser = held.get(loser);
    if (!inLoser) return undefined;
    return (a, b, c) => {
      const [x, y] = out.centre(a, b, c);
      return inLoser.find((h) => h.area.contains(x, y))?.face ?? loser;
    };
  };
  /**
   * The face held back in `into` that shows beside segments p-q (vertex pairs) on their left
   * (`toward` 1) or right (-1), if exactly one held face shows beside any of them (the others
   * may show `into` itself): what `into` gains there goes to that face, whose class the hold
   * keeps, and not to a face not yet shown beside it. Found by the point a millionth of each
   * segment's length off its middle.
   */
  const heldBeside = (into: number, segments: readonly number[], toward: 1 | -1): Held | undefined => {
    const inInto = held.get(into);
    if (!inInto) return undefined;
    const found = new Set<Held>();
    for (let i = 0; i + 1 < segments.length; i += 2) {
      const [x, y] = besidePoint(segments[i]!, segments[i + 1]!, toward);
      const h = inInto.find((c) => c.area.contains(x, y));
      if (h) found.add(h);
    }
    return found.size === 1 ? [...found][0] : undefined;
  };
  /**
   * The face a removal's triangle (corner v) going to `upper` shows: beside a face held back in
   * `upper` (across the triangle's two sides at v, outside it: on the right of its
   * counterclockwise edges), the corner goes to that face, whose area then holds the triangle.
   */
  const removalShownAs = (upper: number, tri: number[], v: number): number => {
    const h = byFace && heldBeside(upper, [0, 1, 2].flatMap((j) => (tri[j] === v || tri[(j + 1) % 3] === v ? [tri[j]!, tri[(j + 1) % 3]!] : [])), -1);
    if (!h) return upper;
    h.area.add(tri, xs, ys);
    stats.removalsToHeld++;
    return h.face;
  };
  /**
   * The face held back in `into` that shows along all of a loser's (or a split's part's)
   * boundary `shared` with `into` at zMerge (every vertex's face there held back until after
   * it), if one face does.
   */
  const heldAlong = (into: number, shared: readonly number[], s: number, zMerge: number): Held | undefined => {
    if (!held.has(into) || shared.length === 0) return undefined;
    const left: number[] = [], right: number[] = [];
    for (const e of shared) {
      const side = sideOf(e, into, s);
      for (const z of sides.vertexTimes(e, side).values()) if (z < zMerge) return undefined;
      const verts = edges[e]!.verts;
      for (let i = 0; i + 1 < verts.length; i++) (side === Side.Left ? left : right).push(verts[i]!, verts[i + 1]!);
    }
    const l = left.length > 0 ? heldBeside(into, left, 1) : undefined, r = right.length > 0 ? heldBeside(into, right, -1) : undefined;
    return (l && r && l !== r) || !(l ?? r) ? undefined : (l ?? r);
  };
  /** The faces held back in the loser's area end with it at step k (into: the winner, -1 for a split), over its transition. */
  const carryOn = (loser: number, k: number, into: number, zStart: number, zEnd: number): number[] | undefined => {
    const inLoser = held.get(loser);
    held.delete(loser);
    for (const h of inLoser ?? []) {
      carried.set(h.face, { step: k, into });
      Object.assign(h.transition, { zStart, zMerge: zEnd });
    }
    return inLoser?.map((h) => h.face);
  };

  for (const e of born[0]!) if (edges[e]!.stepHigh > 0) attach(e, 0);
  for (let f = 1; f < faces.length; f++) {
    if (faces[f]!.stepLow === 0 && faces[f]!.stepHigh > 0) {
      const first = out.count;
      stats.floor += emitFace(f, 0, 0, f, 0);
      origin('floor', 0, 0, f, first);
    }
  }
  let ev = 0;
  for (let k = 1; k <= steps; k++) {
    const z0 = phaseZ(k, 0);
    const before = (f: number): number => resolveFace(faces, f, k - 1);
    // Phase 0: the areas that change face in this step, as they were in state k - 1.
    const handOn: [number, number][] = []; // [face, into]: faces whose edges go to another face
    const reemits: [number, number][] = [];
    for (; ev < t.events.length && t.events[ev]!.step === k; ev++) {
      const e = t.events[ev]!;
      if (e.kind === EventKind.Merge) {
        const shared = sharedEdges(e.loser, e.into, k - 1);
        const first = out.count;
        let ramp: Ramp = { zStart: z0, end: first, zFront: z0 };
        let carries: number[] | undefined;
        let shownAs: Held | undefined;
        const zFoot = byFace ? footOf(z0) : z0;
        // The loser's area as it is before the merge, triangulated once if a hold needs it.
        let area: AreaIndex | undefined;
        const loserArea = (): AreaIndex => {
          if (!area) {
            triangulate(e.loser, k - 1);
            area = new AreaIndex(tris, xs, ys);
          }
          return area;
        };
        const zOn = byFace ? holdUntil(e.loser, e.into, k, loserArea) : undefined;
        if (byFace && zOn !== undefined) {
          // The loser's area keeps showing it until the face of the winner's line that brings it back carries it on.
          const inLoser = held.get(e.loser) ?? [];
          held.delete(e.loser);
          const transition: MergeTransition = { step: k, loser: e.loser, into: e.into, zStart: z0, zMerge: z0, zFoot, zFront: z0, tilted: false, held: true, first, end: first };
          transitions.push(transition);
          stats.heldMerges++;
          for (const h of inLoser) h.until = zOn;
          inLoser.push({ face: e.loser, area: loserArea(), transition, until: zOn });
          // Innermost first: a face held earlier lies in the area of one held later.
          held.set(e.into, [...(held.get(e.into) ?? []), ...inLoser].sort((a, b) => a.transition.zMerge - b.transition.zMerge));
          byFace.hand(e.loser, e.into);
          // No merge into the winner may start from the loser's boundary: the loser is still there.
          relabel(e.loser, zOn, before, true);
          handOn.push([e.loser, e.into]);
          continue;
        }
        if (byFace) {
          // Beside a face held back in the winner only: the loser goes to that face, and moves on with it.
          const h = heldAlong(e.into, shared, k - 1, z0);
          if (h) {
            triangulate(e.loser, k - 1);
            ramp = emitTilted(byFace, tris, e.loser, e.into, k - 1, shared, zFoot, z0, `m${ev}`, 'merge', h.face, lowerUnder(e.loser), false);
            if (ramp.zStart < z0) stats.tiltedMerges++;
            // (emitTilted adds to h's area what it takes.)
            stats.mergesToHeld++;
            shownAs = h;
          } else {
            // No further back than reachBackZ (the winner's re-emits meanwhile are handled there).
            ramp = emitSmoothMerge(byFace, e.loser, e.into, k - 1, shared, zFoot, z0, `m${ev}`, lowerUnder(e.loser));
          }
          carries = carryOn(e.loser, k, e.into, ramp.zStart, z0);
          lieIn(e.into, first);
          byFace.hand(e.loser, e.into);
        } else {
          stats.merge += emitFace(e.loser, k - 1, z0, e.into, e.loser);
          ramp.end = out.count;
        }
        transitions.push({ step: k, loser: e.loser, into: e.into, zStart: ramp.zStart, zMerge: z0, zFoot, zFront: ramp.zFront, tilted: ramp.zStart < z0, first, end: ramp.end, ...(carries ? { carries } : {}), ...(shownAs ? { shownAs: shownAs.face } : {}), ...(ramp.takers ? { takers: ramp.takers } : {}) });
        origin('merge', k, e.loser, shownAs?.face ?? e.into, first);
        // The winner grows; the loser's neighbours now border the winner (or the held face that took it, until its hold ends).
        relabel(e.loser, z0, before);
        if (shownAs) relabel(e.loser, shownAs.until, before, true);
        handOn.push([e.loser, e.into]);
      } else if (e.kind === EventKind.Split) {
        const tv = e.tris!, tf = e.triFaces!;
        if (byFace) {
          // Smooth: each neighbour grows into the face from its own side up to the split line,
          // as in a merge, so the face narrows and closes.
          const byInto = new Map<number, number[]>();
          for (let i = 0; i < tf.length; i++) {
            let l = byInto.get(tf[i]!);
            if (!l) byInto.set(tf[i]!, (l = []));
            l.push(tv[3 * i]!, tv[3 * i + 1]!, tv[3 * i + 2]!);
          }
          let zStart = z0;
          const lowerOf = lowerUnder(e.loser);
          // Faces held back in the split face that a part's face brings back to their class
          // (followSplit) stay, held back in that face: the part's triangles over them are
          // theirs (the road between them and the split line too, as far as those triangles go).
          // Parts of their class carry them on where they lie, as they would without.
          const follows = new Map<number, Held[]>();
          const inSplit = held.get(e.loser) ?? [];
          for (const h of inSplit) {
            const cl = faces[h.face]!.classIndex;
            const f = followSplit(e, h.area, cl, h.transition.zMerge);
            if (!f) continue;
            h.until = f.until;
            let l = follows.get(f.into);
            if (!l) follows.set(f.into, (l = []));
            l.push(h);
            stats.splitFollows++;
          }
          for (const [into, area] of [...byInto].sort((p, q) => p[0] - q[0])) {
            const first = out.count;
            const shared = sharedEdges(e.loser, into, k - 1);
            // Beside a face held back in `into` only: the part goes to that face, and moves on with it.
            const h = heldAlong(into, shared, k - 1, z0);
            const shownAs = h?.face ?? into;
            const zFoot = footOf(z0);
            const shown = withoutSlivers(e.loser, area);
            const staying = follows.get(into);
            const upperOf = staying && ((a: number, b: number, c: number): number | undefined => {
              const [x, y] = out.centre(a, b, c);
              return staying.find((q) => q.area.contains(x, y))?.face;
            });
            const part = emitTilted(byFace, shown, e.loser, into, k - 1, shared, zFoot, z0, `p${ev}:${shownAs}`, 'split', shownAs, lowerOf, !h, upperOf);
            // A face that stays shows from now on where this part's triangles are its own; the
            // rest of its area went to other parts. (emitTilted adds to h's area what it takes.)
            for (const q of staying ?? []) {
              const l = out.trianglesOf(first, part.end, q.face);
              if (l.length > 0) q.area = new AreaIndex(l, out.xs, out.ys);
            }
            if (part.zStart < z0) stats.tiltedSplits++;
            if (h) stats.splitPartsToHeld++;
            zStart = Math.min(zStart, part.zStart);
            lieIn(into, first);
            origin('split', k, e.loser, shownAs, first);
          }
          // The faces that stay move on to the face that took them; the others end with the split.
          const moving = new Set([...follows.values()].flat());
          if (moving.size > 0) {
            const rest = inSplit.filter((h) => !moving.has(h));
            if (rest.length > 0) held.set(e.loser, rest);
            else held.delete(e.loser);
          }
          for (const [into, l] of follows) held.set(into, [...(held.get(into) ?? []), ...l].sort((a, b) => a.transition.zMerge - b.transition.zMerge));
          const carries = carryOn(e.loser, k, -1, zStart, z0);
          splits.push({ step: k, loser: e.loser, zStart, zSplit: z0, ...(carries ? { carries } : {}) });
        } else {
          const first = out.count;
          for (let i = 0; i < tf.length; i++) out.add(tv[3 * i]!, tv[3 * i + 1]!, tv[3 * i + 2]!, z0, tf[i]!, e.loser);
          stats.split += tf.length;
          origin('split', k, e.loser, 0, first);
        }
        byFace?.drop(e.loser);
        relabel(e.loser, z0, before);
        faceEdges.delete(e.loser);
      } else {
        // A re-emit: not a change of side, the same face under a new id (what is given to the face
        // before the re-emit may name the new id: its record's stepLow says so, below).
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
    const removals: Removal[] = [];
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
        const [upper, lower] = o > 0 ? [left, right] : [right, left];
        removals.push({ tri: o > 0 ? [a, b, v] : [a, v, b], v, upper, lower, edge: e, side: o > 0 ? Side.Left : Side.Right, phase: edge.removedPhase[r]! });
      }
    }
    // Left out (givesBack): they are not drawn, so they take no share of the step's time either.
    const skip = removals.map(({ upper, lower, phase, tri, v }) => byFace !== undefined && givesBack(upper, lower, phaseZ(k, phase), tri, v));
    const drawn = removals.filter((_, r) => !skip[r]);
    const drawnHeights = byFace ? removalHeights(Float64Array.from(drawn.flatMap(({ tri }) => tri.flatMap((w) => [xs[w]!, ys[w]!]))), drawn.map((r) => r.phase)) : undefined;
    const heights: number[] = [];
    let nd = 0;
    for (let r = 0; r < removals.length; r++) heights.push(skip[r] ? 0 : drawnHeights?.[nd++] ?? 0);
    let lastDrawn: Removal | undefined;
    removals.forEach(({ tri, v, upper, lower, edge, side, phase }, r) => {
      const z = phaseZ(k, phase);
      if (skip[r]) {
        stats.skippedRemovals++;
        let l = slivers.get(lower);
        if (!l) slivers.set(lower, (l = []));
        l.push({ tri, v, face: upper });
        let m = notches.get(upper);
        if (!m) notches.set(upper, (m = new Map()));
        const [a, b] = tri.filter((w) => w !== v);
        m.set(edgeKey(a!, b!), v);
        return;
      }
      let zCorner = z, zChord = z;
      const shownAs = removalShownAs(upper, tri, v);
      if (byFace) {
        zCorner = smoothRemovalStart(byFace, tri, lower, z, { edge, side });
        zChord = zCorner + (z - zCorner) / (heights[r]! + 1);
      }
      if (zCorner < zChord) {
        out.addTilted(tri[0]!, tri[1]!, tri[2]!, tri[0] === v ? zCorner : zChord, tri[1] === v ? zCorner : zChord, tri[2] === v ? zCorner : zChord, shownAs, lower, `s${out.count}`);
        stats.tiltedRemovals++;
      } else {
        out.add(tri[0]!, tri[1]!, tri[2]!, z, shownAs, lower);
      }
      lieIn(upper, out.count - 1);
      stats.simplify++;
      // One origin per edge version and side (its removals are consecutive).
      if (lastDrawn?.edge === edge && lastDrawn.upper === upper && origins[origins.length - 1]!.into === shownAs) origins[origins.length - 1]!.end = out.count;
      else origin('simplify', k, lower, shownAs, out.count - 1);
      lastDrawn = removals[r];
    });
    // Replaced faces: their whole area, as it is at the end of the step, drawn again.
    for (const [f, g] of reemits) {
      // reemitsHeldAcross leaves out every re-emit a hold could cross: one kept would draw the
      // face again over what is held in it.
      if (held.has(f)) throw new Error(`smooth cube: the re-emit of face ${f} at step ${k} would cover faces held back in it (${held.get(f)!.map((h) => h.face).join(', ')})`);
      const first = out.count;
      stats.reemit += emitFace(g, k, phaseZ(k, REEMIT_PHASE), g, f);
      // Those of its slivers whose tGAP face is still there, the chord still its boundary (no later
      // removal has handed part of the sliver on to a third face), move on with it.
      const kept: Sliver[] = [], dropped: Sliver[] = [];
      for (const sl of slivers.get(f) ?? []) {
        const [a, b] = sl.tri.filter((w) => w !== sl.v);
        (faces[sl.face]!.stepHigh > k && onBoundary(sl.face, a!, b!) ? kept : dropped).push(sl);
      }
      slivers.delete(f);
      if (kept.length > 0) slivers.set(g, kept);
      for (const { tri } of kept) out.add(tri[0]!, tri[1]!, tri[2]!, phaseZ(k, REEMIT_PHASE), g, f);
      origin('reemit', k, f, g, first);
      lieIn(g, first);
      // The others showed f, which ends here, and its new id does not cover them (the tGAP gave
      // them away): each goes, as its removal would have, to its winner or what the winner has
      // become, where that face holds it now and is not new at this step (its own re-emit covers
      // it). The face may hold part of it, g the rest (a later removal of the same step gave
      // that part back to f): drawn just under g's re-emit, the sliver shows g there all the
      // same. Each probe (below) must lie in one of the two, one at least in that face: a part
      // a third face has taken from the winner since must not show the winner. Else f's older surfaces would go on
      // showing f there, or nothing where the map does not fetch their chunk. The rest stay as
      // they were.
      const z = phaseZ(k, REEMIT_PHASE) - SURFACE_GAP;
      for (const sl of dropped) {
        const owner = resolveFace(faces, sl.face, k);
        if (owner === g) continue; // the winner merged into f: its area is g's
        // sliverProbes, and a point a quarter of the way from each end of the chord to the centre
        // (a third face may hold a corner of the sliver); each a hair towards the centre: the
        // corner and the chord lie on lines of the tGAP.
        const [a, b] = sl.tri.filter((w) => w !== sl.v) as [number, number];
        const probes = sliverProbes(sl.tri, sl.v);
        for (const w of [a, b]) probes.push(xs[w]! + (probes[0]! - xs[w]!) / 4, ys[w]! + (probes[1]! - ys[w]!) / 4);
        const inFace = (face: number): boolean[] => Array.from({ length: probes.length / 2 }, (_, i) => insideFace(face, probes[2 * i]! + (probes[0]! - probes[2 * i]!) * 1e-3, probes[2 * i + 1]! + (probes[1]! - probes[2 * i + 1]!) * 1e-3, k));
        const inG = inFace(g);
        const inOwner = owner > 0 && owner !== f && faces[owner]!.stepLow !== k ? inFace(owner) : null;
        if (!inOwner || !inOwner.some(Boolean) || !inOwner.every((x, i) => x || inG[i])) {
          // Where the tGAP has given it back to f meanwhile, the new id covers it.
          if (!inG.every(Boolean)) stats.sliversLeftShowing++;
          continue;
        }
        const at = out.count;
        const shownAs = removalShownAs(owner, sl.tri, sl.v);
        const zCorner = byFace ? smoothRemovalStart(byFace, sl.tri, f, z) : z;
        const zOf = (w: number): number => (w === sl.v ? zCorner : z);
        if (zCorner < z) out.addTilted(sl.tri[0]!, sl.tri[1]!, sl.tri[2]!, zOf(sl.tri[0]!), zOf(sl.tri[1]!), zOf(sl.tri[2]!), shownAs, f, `s${at}`);
        else out.add(sl.tri[0]!, sl.tri[1]!, sl.tri[2]!, z, shownAs, f);
        origin('simplify', k, f, shownAs, at);
        lieIn(owner, at);
        stats.sliversHandedOn++;
        // The sliver is the face's now: its notch would keep it out of the face's later surfaces
        // (a ramp, a re-emit), and the sliver would go on showing the face after it ended. (The
        // same chord may have notched the face again since, for another vertex: that one stays.)
        const notched = notches.get(owner);
        if (owner === sl.face && notched?.get(edgeKey(a, b)) === sl.v) notched.delete(edgeKey(a, b));
      }
      byFace?.drop(f);
    }
  }
  // Every hold ends at a step of its line (returnOnLine): none is left uncarried.
  if (held.size > 0) throw new Error(`smooth cube: faces held back never carried on: ${[...held.values()].flat().map((h) => h.face).join(', ')}`);
  // An id a re-emit made may show before the re-emit, where a merge or removal into it reaches
  // back across it: its record starts at the last state s with phaseZ(s, REEMIT_PHASE) <= z,
  // z the lowest it shows from, so that it is alive wherever the map shows it.
  const shownFrom = new Map<number, number>();
  for (let i = 0; i < out.count; i++) {
    const u = out.upper[i]!;
    if (u > 0 && out.zMin[i]! < faceStartZ(faces[u]!)) shownFrom.set(u, Math.min(shownFrom.get(u) ?? Infinity, out.zMin[i]!));
  }
  // A face held back ends where the merge that carried it on ends it.
  const cube: Tgap = carried.size === 0 && shownFrom.size === 0 ? t : { ...t, faces: faces.map((f, i) => {
    const c = carried.get(i);
    const z = shownFrom.get(i);
    const g = z === undefined ? f : { ...f, stepLow: Math.max(0, Math.floor(z + 1 - phaseZ(1, REEMIT_PHASE))) };
    return c ? { ...g, stepHigh: c.step, mergedInto: c.into, endPhase: 0 } : g;
  }) };
  // Each triangle matters until its upper face ends; after that newer surfaces cover it.
  for (let i = 0; i < out.count; i++) {
    const u = out.upper[i]!;
    out.zEnd[i] = u > 0 ? Math.min(zTop, faceEndZ(cube.faces[u]!, steps)) : zTop;
  }
  return { surfaces: out, stats, transitions, splits, origins, tgap: cube };
}
