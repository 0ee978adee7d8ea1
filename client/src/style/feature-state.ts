// Feature state (as MapLibre's setFeatureState): any keys a page keeps per face, of which
// `hover: true` and `highlight: true` are drawn (the map's state paints). A face id names one face of the cube
// wherever it is shown: in its own scale range, over the whole slice. Pure.

export interface FeatureRef {
  /** The face id, as queryFeatures and the click event give it. */
  face: number;
}

export type FeatureState = Record<string, unknown>;

export class FeatureStates {
  private readonly states = new Map<number, FeatureState>();
  /** Faces are 1 .. faceCount - 1 (0 is "no face"); until the cube is known, any positive integer. */
  faceCount = Infinity;

  /** Merges `state` into the face's state; returns the face. */
  set(ref: FeatureRef, state: FeatureState, caller = 'setFeatureState'): number {
    const face = this.check(ref, caller);
    if (typeof state !== 'object' || state === null || Array.isArray(state)) throw new Error(`${caller}: the state must be an object such as { highlight: true }, not ${JSON.stringify(state)}`);
    this.states.set(face, { ...this.states.get(face), ...state });
    return face;
  }

  /** A copy of the face's state ({} when it has none). */
  get(ref: FeatureRef): FeatureState {
    return { ...this.states.get(this.check(ref, 'getFeatureState')) };
  }

  /** Removes one key of the face's state, or all of it; returns the face. */
  remove(ref: FeatureRef, key?: string): number {
    const face = this.check(ref, 'removeFeatureState');
    const s = this.states.get(face);
    if (s && key !== undefined) {
      const rest = { ...s };
      delete rest[key];
      if (Object.keys(rest).length) this.states.set(face, rest);
      else this.states.delete(face);
    } else this.states.delete(face);
    return face;
  }

  /** Which of `drawn` (state keys) are true for the face: bit i for drawn[i]. */
  bits(face: number, drawn: readonly string[]): number {
    const s = this.states.get(face);
    return drawn.reduce((b, key, i) => (s?.[key] === true ? b | (1 << i) : b), 0);
  }

  private check(ref: FeatureRef, caller: string): number {
    const face = (ref as Partial<FeatureRef> | null)?.face;
    if (typeof face !== 'number' || !Number.isInteger(face) || face < 1 || face >= this.faceCount) {
      const range = Number.isFinite(this.faceCount) ? `an integer from 1 to ${this.faceCount - 1}` : 'a positive integer';
      throw new Error(`${caller}: { face } must be a face id (${range}), not ${JSON.stringify(face)}`);
    }
    return face;
  }
}
