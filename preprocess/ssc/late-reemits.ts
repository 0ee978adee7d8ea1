// A smooth cube skips the re-emits of faces that end soon after (docs/FORMAT.md, "Smooth
// cube"). A re-emit draws a face again under a new id only because its surfaces have grown
// many (preprocess/tgap/reemit.ts); nothing on the map changes. But its horizontal surface lies
// under everything the face does next, so when the face merges or is split soon after, its
// transition could start no earlier than the re-emit and was squeezed into the steps between.
// On bgt_otterlo_1800m such transitions held three quarters of the merged area. When the face
// ends within a transition's reach of its re-emit, it keeps its old id until it ends instead.
// A merge into the new id may reach back across the re-emit: its ramp names the new id
// throughout (surfaces.ts), so that re-emit stays.
import { EventKind, faceEndZ, faceStartZ, REEMIT_PHASE, type Tgap, type TgapFace } from '../../format/tgap-model.js';

/**
 * The tGAP with those re-emits taken out: the replaced face lives on until the new one would
 * have ended, every reference to the new face names the old one, and the new face's record is
 * left never alive (stepLow = stepHigh). `earliest(z)`: how far back a transition ending at z
 * may start; `also`: new faces whose re-emits are skipped as well (a merge held back across
 * them, hold-line.ts). The input is not changed.
 */
export function skipLateReemits(t: Tgap, earliest: (z: number) => number, also: ReadonlySet<number> = new Set()): { tgap: Tgap; skipped: number } {
  const { faces, events } = t;
  const steps = t.meta.steps;
  const replacedBy = (f: TgapFace): number => (f.endPhase === REEMIT_PHASE && f.mergedInto > 0 ? f.mergedInto : -1);
  const alias = Int32Array.from({ length: faces.length }, (_, i) => i);
  let skipped = 0;
  for (const e of events) {
    if (e.kind !== EventKind.Reemit) continue;
    // The face's last id: where its area finally merges, is split or lives to the top.
    let last = e.into;
    while (replacedBy(faces[last]!) > 0) last = replacedBy(faces[last]!);
    const end = faceEndZ(faces[last]!, steps);
    const start = faceStartZ(faces[e.into]!);
    if ((end === Infinity || earliest(end) >= start) && !also.has(e.into)) continue;
    alias[e.into] = alias[e.loser]!;
    skipped++;
  }
  if (skipped === 0) return { tgap: t, skipped };
  const out = faces.map((f) => ({ ...f }));
  // In id order, so that along a chain of skipped re-emits the last one's end is the one kept.
  for (let g = 1; g < faces.length; g++) {
    const f = alias[g]!;
    if (f === g) continue;
    const root = out[f]!, gone = out[g]!;
    root.stepHigh = gone.stepHigh;
    root.endPhase = gone.endPhase;
    root.mergedInto = gone.mergedInto;
    gone.stepHigh = gone.stepLow;
    gone.mergedInto = -1;
    gone.endPhase = 0;
  }
  for (const f of out) if (f.mergedInto > 0) f.mergedInto = alias[f.mergedInto]!;
  const named = (f: number): number => (f > 0 ? alias[f]! : f);
  return {
    tgap: {
      ...t,
      faces: out,
      edges: t.edges.map((e) => (named(e.left) === e.left && named(e.right) === e.right ? e : { ...e, left: named(e.left), right: named(e.right) })),
      events: events
        .filter((e) => !(e.kind === EventKind.Reemit && alias[e.into] !== e.into))
        .map((e) => ({ ...e, loser: named(e.loser), into: named(e.into), ...(e.triFaces ? { triFaces: e.triFaces.map(named) } : {}) })),
    },
    skipped,
  };
}
