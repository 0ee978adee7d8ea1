// The tGAP as it is built and stored (docs/FORMAT.md, "tGAP file"): vertices, edge versions
// and face versions with step ranges, and the events that link them (the DAG). A state s
// (0 = input, s = after s steps) holds the edges and faces with stepLow <= s < stepHigh.
import { scaleKnots, type ScaleInfo } from './scale.js';

/**
 * Sub-steps of one step: phase 0 is the merge or split, phases 1..6 hold line simplification,
 * phase 7 re-draws faces whose surfaces have grown costly (see preprocess/tgap/generalize.ts).
 */
export const PHASES = 8;
export const LAST_REMOVAL_PHASE = PHASES - 2;
export const REEMIT_PHASE = PHASES - 1;

/** z of a phase of step k (k >= 1) in the Space-Scale Cube: strictly inside (k - 1, k). */
export function phaseZ(step: number, phase: number): number {
  return step - 1 + (phase + 1) / (PHASES + 1);
}

export const enum EventKind {
  Merge = 1,
  Split = 2,
  /** The face is replaced by a new one with the same class and attributes, drawn afresh. */
  Reemit = 3,
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
  /** The face this one was merged into (or replaced by) at stepHigh (-1: none, or split). */
  mergedInto: number;
  /** Phase of step stepHigh in which the face ends (0: merge or split, REEMIT_PHASE: replaced). */
  endPhase: number;
  /** Twice the area when the face was made. */
  area2: number;
}

export interface TgapEvent {
  kind: EventKind;
  step: number;
  /** The face that ends. */
  loser: number;
  /** Merge: the winner, which takes the loser's area; re-emit: the new face. */
  into: number;
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
  return resolveFaceAt(faces, f, s, REEMIT_PHASE);
}

/** The same inside step `step`, just after `phase`. */
export function resolveFaceAt(faces: TgapFace[], f: number, step: number, phase: number): number {
  let g = f;
  while (g > 0) {
    const face = faces[g]!;
    if (face.mergedInto < 0 || face.stepHigh > step || (face.stepHigh === step && face.endPhase > phase)) return g;
    g = face.mergedInto;
  }
  return g;
}

/** z from which a face's surfaces are covered by newer ones (Infinity: it lives to the top). */
/** z from which a face is shown: the floor for an input face, else its re-emit (the only way faces are made). */
export function faceStartZ(face: TgapFace): number {
  return face.stepLow === 0 ? 0 : phaseZ(face.stepLow, REEMIT_PHASE);
}

/** Per face made by a re-emit, the face it replaced (same class and attributes, new id). */
export function replacedFaces(faces: readonly TgapFace[]): Map<number, number> {
  const replaced = new Map<number, number>();
  faces.forEach((f, i) => {
    if (i > 0 && f.endPhase === REEMIT_PHASE && f.mergedInto > 0) replaced.set(f.mergedInto, i);
  });
  return replaced;
}

export function faceEndZ(face: TgapFace, steps: number): number {
  return face.stepHigh > steps ? Infinity : phaseZ(face.stepHigh, face.endPhase);
}

/** Whether a face is shown at z: from faceStartZ, up to faceEndZ. */
export function faceAliveAt(face: TgapFace, z: number, steps: number): boolean {
  return faceStartZ(face) <= z && z < faceEndZ(face, steps);
}

/** The scale of every step (a constant number of faces per map area), as the cube states it. */
export function scaleInfoOf(t: Pick<Tgap, 'meta'>): ScaleInfo {
  return { baseScale: t.meta.baseScale, baseFaces: t.meta.baseFaces, scaleTable: scaleKnots(t.meta.facesAlive), zMax: t.meta.steps };
}
