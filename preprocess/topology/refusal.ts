// Input that is not a planar partition is refused, with the feature and the place named.
import { InputError, type FeatureRef } from '../io/errors.js';
import type { InputFeature } from '../io/read-input.js';

export class Refusal {
  constructor(private readonly features: readonly InputFeature[], private readonly file: string | undefined) {}

  /** The input feature of face f (> 0). */
  refOf(face: number): FeatureRef {
    return this.features[face - 1]!.ref;
  }

  /** Face f's feature as a message names it: `feature #3 (id "a")`. */
  describe(face: number): string {
    const ref = this.refOf(face);
    return ref.id === null ? `feature #${ref.index}` : `feature #${ref.index} (id ${JSON.stringify(ref.id)})`;
  }

  /** Throws an InputError naming the file, face's feature (none for the outside, 0) and the place. */
  fail(msg: string, face: number | undefined, x?: number, y?: number): never {
    const file = this.file;
    throw new InputError(msg, {
      ...(file ? { file } : {}),
      ...(face !== undefined && face > 0 ? { feature: this.refOf(face) } : {}),
      ...(x !== undefined && y !== undefined ? { location: [x, y] as [number, number] } : {}),
    });
  }
}
