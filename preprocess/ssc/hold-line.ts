// Which merges a smooth cube holds back, as far as the tGAP alone tells (docs/FORMAT.md, "Smooth
// cube"). A loser of class A merged into a face of class B, whose area later goes back to class
// A, would show A, then B (and maybe more classes), then A again: flicker. The cube keeps the
// loser until its area goes on to A. Where the area goes is the winner's line: the faces it is
// merged into (or re-emitted as) in turn, until one of them merges into a face of class A, or is
// split (which may give part of it back, or hand it to a face whose own line comes back to A).
import { EventKind, phaseZ, REEMIT_PHASE, type Tgap, type TgapFace } from '../../format/tgap-model.js';
import { scaleAtZ, zAtScale, type ScaleInfo } from '../../format/scale.js';

/**
 * The face of `into`'s line whose end brings an area of class `cl` back to its class (a merge
 * into a face of class cl, or a split), ending no later than zLast; -1 if none does.
 */
export function returnOnLine(faces: readonly TgapFace[], into: number, cl: number, steps: number, zLast: number): number {
  // A line is at most as long as there are faces (a tGAP's links only go up in step).
  for (let f = into, n = 0; n < faces.length; f = faces[f]!.mergedInto, n++) {
    const x = faces[f]!;
    if (!(x.stepHigh <= steps) || phaseZ(x.stepHigh, 0) > zLast) return -1;
    if (x.mergedInto <= 0) return x.endPhase === 0 ? f : -1;
    if (faces[x.mergedInto]!.classIndex === cl) return f;
  }
  throw new Error(`face ${into}: its line of merges and re-emits runs in a circle`);
}

/**
 * Whether a face of `from`'s line before `end` (a face of it: returnOnLine) is re-emitted: a
 * re-emit draws its face's whole area again, over what a hold keeps in it.
 */
export function reemitBefore(faces: readonly TgapFace[], from: number, end: number): boolean {
  for (let f = from; f !== end; f = faces[f]!.mergedInto) if (faces[f]!.endPhase === REEMIT_PHASE) return true;
  return false;
}

/** The latest z a hold that starts at z may last to: `maxRatio` times its scale. */
export function holdLimitZ(info: ScaleInfo, z: number, maxRatio: number): number {
  return zAtScale(info, maxRatio * scaleAtZ(info, z));
}

/**
 * The faces made by re-emits that a merge may be held back across: the loser's class differs
 * from the winner's, and the re-emit lies on the winner's line before the face that brings the
 * loser's area back to its class (returnOnLine, at most `maxRatio` in scale after the merge; a
 * split must give some of its triangles to that class). A re-emit draws its face's whole area
 * again, over a face held back in it, so a smooth cube keeps the old id instead
 * (late-reemits.ts). The build's holds of this kind are among these (its split must give back
 * over the loser's area, and faces held inside the loser shorten the limit). Its other holds,
 * of a loser that holds faces still waiting, lie on the line of the hold that put them there:
 * covered too. Holds that a split hands on to one of its parts (surfaces.ts, followSplit) are
 * made only where no re-emit lies on the way (reemitBefore). The build throws if a kept
 * re-emit would cover a held face.
 */
export function reemitsHeldAcross(t: Tgap, info: ScaleInfo, maxRatio: number): Set<number> {
  const { faces } = t;
  const steps = t.meta.steps;
  const out = new Set<number>();
  const splitTo = new Map(t.events.filter((e) => e.kind === EventKind.Split).map((e) => [e.loser, new Set(Array.from(e.triFaces ?? [], (f) => faces[f]!.classIndex))]));
  for (const e of t.events) {
    if (e.kind !== EventKind.Merge) continue;
    const cl = faces[e.loser]!.classIndex;
    if (faces[e.into]!.classIndex === cl) continue;
    const end = returnOnLine(faces, e.into, cl, steps, holdLimitZ(info, phaseZ(e.step, 0), maxRatio));
    if (end < 0 || (faces[end]!.mergedInto <= 0 && !splitTo.get(end)?.has(cl))) continue;
    for (let f = e.into; f !== end; f = faces[f]!.mergedInto) if (faces[f]!.endPhase === REEMIT_PHASE) out.add(faces[f]!.mergedInto);
  }
  return out;
}
