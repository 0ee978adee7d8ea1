// A face keeps its id while it grows and its lines are simplified: the cube then only needs
// the changes (cheap). But its old surfaces stay in use as long as it lives, so once what was
// drawn for it exceeds `factor` times its current size it is replaced by a new face (same
// class and attributes) whose whole area is drawn afresh, already simplified.
import { EventKind, REEMIT_PHASE, type TgapEvent } from '../../format/tgap-model.js';
import { ALIVE, type PlanarState } from './planar-state.js';

export interface ReemitLimits {
  /** Drawn vertices allowed per current vertex of the face. */
  factor: number;
  /** Drawn vertices allowed beyond that (small faces are cheap to keep). */
  slack: number;
}

/**
 * Replaces each alive face among `faces` that has cost more than the limits allow, in step k
 * (in id order); `onNew(g)` is called for every replacement. Returns the events made.
 */
export function reemitCostlyFaces(st: PlanarState, faces: Iterable<number>, k: number, limits: ReemitLimits, onNew: (g: number) => void): TgapEvent[] {
  const events: TgapEvent[] = [];
  for (const f of [...new Set(faces)].sort((p, q) => p - q)) {
    if (f <= 0 || st.faces[f]!.stepHigh !== ALIVE) continue;
    if (st.faceCost[f]! <= limits.factor * st.faceVerts[f]! + limits.slack) continue;
    const face = st.faces[f]!;
    const g = st.addFace(face.classIndex, face.feature, st.faceArea2[f]!);
    st.endFace(f, g, REEMIT_PHASE);
    st.faceCost[g] = st.faceVerts[g]!;
    events.push({ kind: EventKind.Reemit, step: k, loser: f, into: g });
    onNew(g);
  }
  return events;
}
