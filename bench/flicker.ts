// No flicker (issue 11): during a monotone zoom, no pixel away from a boundary goes back to a
// class it showed before. Frames are fed in zoom order; a pixel flickers when it shows class A,
// later another class, and later A again. A pixel's showing counts only in a frame where it is
// at least 1 px from a face boundary (its 8 neighbours show its face): on a boundary a pixel
// may swap between the two sides' classes as the boundary moves, and no one sees it as flicker.
// Pixels with no face (outside the data) show nothing.
import type { ClassFrame } from './class-change.js';

/** At most this many flickering pixels are described in `examples`. */
const EXAMPLES = 5;

export class FlickerCounter {
  /** Pixels that went back to a class they showed before. */
  flickering = 0;
  frames = 0;
  /** The first few flickering pixels: column, row, the classes shown and the frame of the return. */
  readonly examples: string[] = [];
  /** Per pixel the class it shows now (-1: none yet). */
  private readonly last: Int32Array;
  /** Per pixel that changed class, the classes it showed before its current one. */
  private readonly earlier = new Map<number, number[]>();
  private readonly flagged: Uint8Array;

  constructor(readonly width: number, readonly height: number) {
    if (!(Number.isInteger(width) && Number.isInteger(height) && width > 0 && height > 0)) throw new Error(`frame size must be whole pixels (got ${width}x${height})`);
    this.last = new Int32Array(width * height).fill(-1);
    this.flagged = new Uint8Array(width * height);
  }

  /** The next frame of the zoom. */
  add(f: ClassFrame): void {
    const { width: W, height: H } = this;
    if (f.ids.length !== W * H || f.classes.length !== W * H) throw new Error(`frame of ${f.ids.length} pixels; the counter takes ${W}x${H}`);
    for (let j = 0; j < H; j++) {
      for (let i = 0; i < W; i++) {
        const p = j * W + i;
        const id = f.ids[p]!;
        if (id === 0 || nearBoundary(f.ids, W, H, i, j)) continue;
        const c = f.classes[p]!;
        const was = this.last[p]!;
        if (was === c) continue;
        this.last[p] = c;
        if (was < 0) continue;
        let before = this.earlier.get(p);
        if (!before) this.earlier.set(p, (before = []));
        if (before.includes(c) && !this.flagged[p]) {
          this.flagged[p] = 1;
          this.flickering++;
          if (this.examples.length < EXAMPLES) this.examples.push(`pixel ${i},${j}: classes ${[...before, was, c].join(' ')} (back in frame ${this.frames})`);
        }
        before.push(was);
      }
    }
    this.frames++;
  }

  /** Whether the pixel at column i, row j has flickered so far. */
  flickered(i: number, j: number): boolean {
    return this.flagged[j * this.width + i] === 1;
  }
}

/** Whether a neighbour of pixel (i, j) inside the frame shows another face (or none). */
function nearBoundary(ids: ArrayLike<number>, W: number, H: number, i: number, j: number): boolean {
  const id = ids[j * W + i];
  for (let jj = Math.max(0, j - 1); jj <= Math.min(H - 1, j + 1); jj++) {
    for (let ii = Math.max(0, i - 1); ii <= Math.min(W - 1, i + 1); ii++) if (ids[jj * W + ii] !== id) return true;
  }
  return false;
}
