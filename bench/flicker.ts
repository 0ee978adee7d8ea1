// No flicker (issue 11): during a monotone zoom, no pixel away from a boundary goes back to a
// class it showed before. Frames are fed in zoom order; a pixel flickers when it shows class A,
// later another class, and later A again. A pixel's showing counts only in a frame where it is
// at least 1 px from a face boundary (its 8 neighbours show its face): on a boundary a pixel
// may swap between the two sides' classes as the boundary moves, and no one sees it as flicker.
// Pixels with no face (outside the data) show nothing.
//
// The tGAP itself can send a pixel back to a class (a face merged into one of another class,
// which later merges into a face of the first class), so a real zoom has class flicker in any
// cube. What only a cube can add is a face coming back: in the tGAP a face never returns to a
// pixel it has left (off boundaries), so `faceReturns` counts the cube's own flicker.
import type { ClassFrame } from './class-change.js';

/** At most this many flickering pixels are described in `examples`. */
const EXAMPLES = 5;

export class FlickerCounter {
  /** Pixels that went back to a class they showed before. */
  flickering = 0;
  /** Pixels that went back to a face they showed before (the cube's own flicker). */
  faceReturns = 0;
  frames = 0;
  /** The first few flickering pixels: column, row, the classes shown and the frame of the return. */
  readonly examples: string[] = [];
  private readonly classes: Shown;
  private readonly faces: Shown;

  constructor(readonly width: number, readonly height: number) {
    if (!(Number.isInteger(width) && Number.isInteger(height) && width > 0 && height > 0)) throw new Error(`frame size must be whole pixels (got ${width}x${height})`);
    this.classes = new Shown(width * height);
    this.faces = new Shown(width * height);
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
        const back = this.classes.show(p, f.classes[p]!, this.frames);
        if (back) {
          this.flickering++;
          if (this.examples.length < EXAMPLES) this.examples.push(`pixel ${i},${j}: classes ${back.join(' ')} (back in frame ${this.frames})`);
        }
        if (this.faces.show(p, id, this.frames)) this.faceReturns++;
      }
    }
    this.frames++;
  }

  /** Whether the pixel at column i, row j has flickered (gone back to a class) so far. */
  flickered(i: number, j: number): boolean {
    return this.classes.returned(j * this.width + i);
  }

  /** Whether the pixel at column i, row j first went back to a class in frame `frame` (0: the first added). */
  flickeredIn(i: number, j: number, frame: number): boolean {
    return this.classes.returnedIn(j * this.width + i, frame);
  }

  /** Whether the pixel at column i, row j has gone back to a face so far. */
  faceReturned(i: number, j: number): boolean {
    return this.faces.returned(j * this.width + i);
  }
}

/** Per pixel, the values (classes or faces) it has shown, and whether one came back. */
class Shown {
  /** The value each pixel shows now (-1: none yet). */
  private readonly last: Int32Array;
  /** Per pixel that changed, the values it showed before its current one. */
  private readonly earlier = new Map<number, number[]>();
  /** Per pixel, 1 + the frame of its first return (0: none). */
  private readonly flagged: Int32Array;

  constructor(n: number) {
    this.last = new Int32Array(n).fill(-1);
    this.flagged = new Int32Array(n);
  }

  /** Pixel p shows `x` in `frame`; the values it went through when this is its first return to one. */
  show(p: number, x: number, frame: number): number[] | null {
    const was = this.last[p]!;
    if (was === x) return null;
    this.last[p] = x;
    if (was < 0) return null;
    let before = this.earlier.get(p);
    if (!before) this.earlier.set(p, (before = []));
    const first = before.includes(x) && !this.flagged[p];
    before.push(was);
    if (!first) return null;
    this.flagged[p] = frame + 1;
    return [...before, x];
  }

  returned(p: number): boolean {
    return this.flagged[p]! > 0;
  }

  returnedIn(p: number, frame: number): boolean {
    return this.flagged[p] === frame + 1;
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
