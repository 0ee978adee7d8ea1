// The outline of one value's pixels in a raster (a face in the ID buffer): closed rings along
// the pixel edges, in pixel corner coordinates (x right, y down; pixel (i, j) spans
// [i, i + 1] x [j, j + 1]). Rings are walked with the region on the left as seen on screen, so
// that on the map (y up) outer rings run counter-clockwise and holes clockwise (GeoJSON's rule). Two pixels touching only at a corner belong to separate rings. Pure.

export type Ring = [number, number][];

/** The rings around the pixels of `raster` (width x height, rows from the top) equal to `value`. */
export function pixelOutline(raster: ArrayLike<number>, width: number, height: number, value: number): Ring[] {
  if (raster.length !== width * height) throw new Error(`pixelOutline: ${raster.length} pixels for ${width} x ${height}`);
  const inside = (i: number, j: number): boolean => i >= 0 && j >= 0 && i < width && j < height && raster[j * width + i] === value;
  const W1 = width + 1;
  // Directed edges between pixel corners (corner key = y * (width + 1) + x), the region on the left.
  const from: number[] = [], to: number[] = [];
  const outgoing = new Map<number, number[]>();
  const edge = (x0: number, y0: number, x1: number, y1: number): void => {
    const a = y0 * W1 + x0;
    from.push(a);
    to.push(y1 * W1 + x1);
    const list = outgoing.get(a);
    if (list) list.push(from.length - 1);
    else outgoing.set(a, [from.length - 1]);
  };
  for (let j = 0; j < height; j++) {
    for (let i = 0; i < width; i++) {
      if (raster[j * width + i] !== value) continue;
      if (!inside(i, j - 1)) edge(i + 1, j, i, j);
      if (!inside(i + 1, j)) edge(i + 1, j + 1, i + 1, j);
      if (!inside(i, j + 1)) edge(i, j + 1, i + 1, j + 1);
      if (!inside(i - 1, j)) edge(i, j, i, j + 1);
    }
  }
  const used = new Uint8Array(from.length);
  const xy = (k: number): [number, number] => [k % W1, Math.floor(k / W1)];
  const rings: Ring[] = [];
  for (let start = 0; start < from.length; start++) {
    if (used[start]) continue;
    const corners: number[] = [];
    let e = start;
    while (!used[e]) {
      used[e] = 1;
      corners.push(from[e]!);
      const [x0, y0] = xy(from[e]!), [x1, y1] = xy(to[e]!);
      const choices = outgoing.get(to[e]!)!.filter((n) => !used[n]);
      if (choices.length === 0) break;
      // At a corner shared by two diagonal pixels, turn left (toward the region): the rings
      // of the two pixels stay apart instead of crossing there.
      const left: [number, number] = [y1 - y0, -(x1 - x0)];
      e = choices.find((n) => {
        const [a, b] = xy(from[n]!), [c, d] = xy(to[n]!);
        return c - a === left[0] && d - b === left[1];
      }) ?? choices[0]!;
    }
    rings.push(withoutStraightCorners(corners.map(xy)));
  }
  return rings;
}

/** The ring without corners where it goes straight on; closed (first point repeated). */
function withoutStraightCorners(points: [number, number][]): Ring {
  const n = points.length;
  const out: Ring = [];
  for (let k = 0; k < n; k++) {
    const p = points[(k + n - 1) % n]!, q = points[k]!, r = points[(k + 1) % n]!;
    const cross = (q[0] - p[0]) * (r[1] - q[1]) - (q[1] - p[1]) * (r[0] - q[0]);
    if (cross !== 0) out.push(q);
  }
  out.push(out[0]!);
  return out;
}
