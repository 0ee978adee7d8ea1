// With grouping (GeneralizeOptions.group) several events share a step. They may all work on
// the state before the step only when none of them changes what another one reads: their
// neighbourhoods must not meet.
import type { PlanarState } from './planar-state.js';

/** The faces an event on L (merging into `best`, or a split) changes or reshapes. */
export function eventNeighbourhood(st: PlanarState, L: number, best: number, split: boolean): Set<number> {
  const out = new Set<number>([L]);
  const around = (f: number): void => {
    for (const e of st.faceEdges[f] ?? []) for (const g of st.sides(e)) if (g > 0) out.add(g);
  };
  around(L);
  // A merge also simplifies the winner's edges, a split every receiver's: their neighbours too.
  for (const f of split ? [...out] : [best]) around(f);
  return out;
}

/** The faces claimed by the events of one step. */
export class StepLocks {
  private readonly locked = new Set<number>();

  /** Claims every face of `hood`, or none when one of them is claimed already; says which. */
  tryLock(hood: Set<number>): boolean {
    if ([...hood].some((f) => this.locked.has(f))) return false;
    for (const f of hood) this.locked.add(f);
    return true;
  }
}
