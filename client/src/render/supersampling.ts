// Accumulating supersampling while the view is still: frame n (from 0) is drawn shifted by a
// sub-pixel offset from a Halton sequence (0 for the first, so the first frame is the plain
// image) and weighted 1 / (n + 1) into the running mean.

function halton(i: number, b: number): number {
  let f = 1, r = 0;
  while (i > 0) {
    f /= b;
    r += f * (i % b);
    i = Math.floor(i / b);
  }
  return r;
}

/** Offset of frame n in device pixels, within (-0.5, 0.5). */
export function jitter(n: number): [number, number] {
  return n === 0 ? [0, 0] : [halton(n, 2) - 0.5, halton(n, 3) - 0.5];
}

export function weight(n: number): number {
  return 1 / (n + 1);
}
