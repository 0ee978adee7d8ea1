// Input that is not a planar partition is refused, with the feature and the place named:
// every problem is noted, and the run stops at the end of the stage that found them.
import { describeFeature, type FeatureRef } from '../io/errors.js';
import type { ProblemKind, ProblemList } from '../io/problems.js';
import type { InputFeature } from '../io/read-input.js';

export class Refusal {
  constructor(private readonly features: readonly InputFeature[], readonly problems: ProblemList) {}

  /** The input feature of face f (> 0). */
  refOf(face: number): FeatureRef {
    return this.features[face - 1]!.ref;
  }

  /** Face f's feature as a message names it: `feature #3 (id "a")`. */
  describe(face: number): string {
    return describeFeature(this.refOf(face));
  }

  /** Notes a problem of face's feature (none for the outside, 0) at a place; the check goes on. */
  note(kind: ProblemKind, msg: string, face: number | undefined, x?: number, y?: number): void {
    this.problems.add({
      kind,
      message: msg,
      ...(face !== undefined && face > 0 ? { feature: this.refOf(face) } : {}),
      ...(x !== undefined && y !== undefined ? { location: [x, y] as [number, number] } : {}),
    });
  }

  /** The end of a stage: refuses the input when it had problems. */
  check(): void {
    this.problems.check();
  }
}
