// Faces by importance (area x class weight), least important first. A face's entry is not
// removed when its importance changes: a new one is pushed, and the stale one is skipped when
// it comes up (its priority no longer matches, or the face has ended).
import FlatQueue from 'flatqueue';
import { ALIVE, type PlanarState } from './planar-state.js';

export class ImportanceQueue {
  private importance: Float64Array;
  private readonly queue = new FlatQueue<number>();

  /**
   * `capacity`: the face ids expected. Redrawn faces take new ids, as many as the redraws,
   * which no face count bounds: the table doubles when an id outgrows it.
   */
  constructor(private readonly st: PlanarState, private readonly weight: readonly number[], capacity: number) {
    this.importance = new Float64Array(Math.max(1, capacity));
  }

  get length(): number {
    return this.queue.length;
  }

  /** (Re)computes the importance of face f from its current area and queues it. */
  update(f: number): void {
    if (f >= this.importance.length) {
      let n = this.importance.length;
      while (n <= f) n *= 2;
      const grown = new Float64Array(n);
      grown.set(this.importance);
      this.importance = grown;
    }
    const imp = (Math.abs(this.st.faceArea2[f]!) / 2) * this.weight[this.st.faces[f]!.classIndex]!;
    this.importance[f] = imp;
    this.queue.push(f, imp);
  }

  /** Takes the least important entry: its face, or -1 when the entry was stale. */
  pop(): number {
    const pr = this.queue.peekValue()!;
    const f = this.queue.pop()!;
    return this.st.faces[f]!.stepHigh !== ALIVE || pr !== this.importance[f] ? -1 : f;
  }

  /** Queues face f again with its importance unchanged (an event put off to a later step). */
  requeue(f: number): void {
    this.queue.push(f, this.importance[f]!);
  }
}
