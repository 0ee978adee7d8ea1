// The tGAP as it is built and stored: vertices, edge versions and face versions with step
// ranges, and the events that link them (the DAG). A state s (0 = input, s = after s steps)
// holds the edges and faces with stepLow <= s < stepHigh.

/** Sub-steps of one step: phase 0 is the merge or split, phases 1.. hold line simplification. */
export const PHASES = 8;

/** z of a phase of step k (k >= 1) in the Space-Scale Cube: strictly inside (k - 1, k). */
export function phaseZ(step: number, phase: number): number {
  return step - 1 + (phase + 1) / (PHASES + 1);
}

export const enum EventKind {
  Merge = 1,
  Split = 2,
}

export interface TgapEdge {
  start: number;
  end: number;
  /** Faces as they were when this version was made; later merges are followed with `resolveFace`. */
  left: number;
  right: number;
  verts: Int32Array;
  stepLow: number;
  stepHigh: number;
  /** The versions this one was made from, in order: a negative entry -(id + 1) is used reversed. */
  parents: Int32Array;
  /** Vertices of the parents' chain removed by simplification, in order, with their phase. */
  removed: Int32Array;
  removedPhase: Uint8Array;
}

export interface TgapFace {
  classIndex: number;
  /** Index of the input feature whose attributes the face carries (-1: none). */
  feature: number;
  stepLow: number;
  stepHigh: number;
  /** The face this one was merged into at stepHigh (-1: none, or split). */
  mergedInto: number;
  /** Twice the area when the face was made. */
  area2: number;
}

export interface TgapEvent {
  kind: EventKind;
  step: number;
  loser: number;
  /** Merge: the face the loser's area goes to (the winner, or a new face made from both). */
  into: number;
  /** Merge only: the winner, when `into` is a new face replacing it (else -1). */
  winner: number;
  /**
   * Split: the loser's area as triangles (vertex ids, 3 per triangle) with the face each one
   * goes to.
   */
  tris?: Int32Array;
  triFaces?: Int32Array;
}

export interface TgapMeta {
  version: number;
  crs: string;
  projectedFrom?: string;
  proj4?: string;
  extent: [number, number, number, number];
  baseScale: number;
  resolutionMm: number;
  baseFaces: number;
  steps: number;
  /** Faces alive after each step (index = step): gives the scale of every step. */
  facesAlive: number[];
  holes: { area: number; x: number; y: number }[];
  repairs: Record<string, number>;
  source: string;
  style: Record<string, unknown>;
  /** Input attributes, by feature index. */
  attributes: Record<string, unknown>[];
  options: Record<string, unknown>;
}

export interface Tgap {
  meta: TgapMeta;
  xs: Float64Array;
  ys: Float64Array;
  faces: TgapFace[];
  edges: TgapEdge[];
  events: TgapEvent[];
}

/** The face that holds f's area at state s (follows merges that happened at or before s). */
export function resolveFace(faces: TgapFace[], f: number, s: number): number {
  let g = f;
  while (g > 0) {
    const face = faces[g]!;
    if (face.stepHigh > s || face.mergedInto < 0) return g;
    g = face.mergedInto;
  }
  return g;
}

/** Scale denominator at a step: constant number of faces per map area. */
export function scaleAtStep(meta: Pick<TgapMeta, 'baseScale' | 'baseFaces' | 'facesAlive'>, step: number): number {
  const alive = meta.facesAlive[Math.max(0, Math.min(meta.facesAlive.length - 1, step))]!;
  return meta.baseScale * Math.sqrt(meta.baseFaces / Math.max(1, alive));
}

/** The (fractional) step at which the map has the given scale denominator. */
export function stepAtScale(meta: Pick<TgapMeta, 'baseScale' | 'baseFaces' | 'facesAlive'>, scale: number): number {
  const alive = meta.baseFaces * (meta.baseScale / scale) ** 2;
  const fa = meta.facesAlive;
  if (alive >= fa[0]!) return 0;
  if (alive <= fa[fa.length - 1]!) return fa.length - 1;
  // facesAlive decreases with the step: binary search the bracket, then interpolate.
  let lo = 0, hi = fa.length - 1;
  while (hi - lo > 1) {
    const mid = (lo + hi) >> 1;
    if (fa[mid]! > alive) lo = mid;
    else hi = mid;
  }
  const a = fa[lo]!, b = fa[hi]!;
  return a === b ? lo : lo + (a - alive) / (a - b);
}
