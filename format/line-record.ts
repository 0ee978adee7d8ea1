// A line of a linear class over scale (docs/FORMAT.md, "Line chunk file"): its z range in the
// cube, its polylines and, per vertex, the z at which simplification takes it away; the
// polylines and segments it has at a z. Apart from the file's codec (line-chunk.ts) so that the
// map's main thread, which draws segments, does not load the codec's WebAssembly.
//
// Per-vertex leave z rather than one polyline per version: each vertex is stored once, and the
// polyline at z is its vertices whose leave z is above z (`linePathsAtZ`): a test a shader can
// make per vertex, as the CPU does, without a copy of the line per version.

/** One line as the build hands it to the encoder and the reader gives it back (absolute coordinates). */
export interface LineRecord {
  classIndex: number;
  /** Index of the style's line rule that draws it (format/line-style.ts, `lineRules`). */
  rule: number;
  /** Input feature whose attributes the line carries (-1: none). */
  feature: number;
  /** The line is on the map for zStart <= z < zEnd. */
  zStart: number;
  zEnd: number;
  /** Polylines as flat x, y pairs, at least two points each. */
  paths: Float64Array[];
  /** Per polyline, per vertex: the z from which the vertex is gone (zEnd when it stays). */
  leaveZ: Float64Array[];
}

/** The ground box x0, y0, x1, y1 of polylines given as flat x, y pairs. */
export function groundBox(paths: readonly Float64Array[]): [number, number, number, number] {
  let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  for (const p of paths) {
    for (let i = 0; i < p.length; i += 2) {
      x0 = Math.min(x0, p[i]!);
      x1 = Math.max(x1, p[i]!);
      y0 = Math.min(y0, p[i + 1]!);
      y1 = Math.max(y1, p[i + 1]!);
    }
  }
  return [x0, y0, x1, y1];
}

/** Whether a line is on the map at z. */
export const lineAliveAt = (l: Pick<LineRecord, 'zStart' | 'zEnd'>, z: number): boolean => l.zStart <= z && z < l.zEnd;

/** A line's polylines at z: the vertices not yet gone (none when the line is not alive at z). */
export function linePathsAtZ(l: LineRecord, z: number): Float64Array[] {
  if (!lineAliveAt(l, z)) return [];
  return l.paths.map((p, k) => {
    const leave = l.leaveZ[k]!;
    const out: number[] = [];
    for (let j = 0; j < leave.length; j++) if (leave[j]! > z) out.push(p[2 * j]!, p[2 * j + 1]!);
    return Float64Array.from(out);
  });
}

/** A segment of a line that is drawn for z0 <= z < z1. */
export interface LineSegment {
  ax: number;
  ay: number;
  bx: number;
  by: number;
  z0: number;
  z1: number;
  /** Its polyline in the line, and the indices of a and b among that polyline's vertices. */
  path: number;
  a: number;
  b: number;
}

/**
 * Every segment a line has at some z, with its z range: (a, b) joins vertices a and b of a
 * polyline from the z where the last vertex between them is gone (the line's zStart for
 * neighbours) until a or b goes. At any z these are exactly the segments of `linePathsAtZ`,
 * so a slicing surface whose z varies over the map is drawn by testing each pixel against its
 * segment's range (the GPU's rule too).
 */
export function lineSegments(l: LineRecord): LineSegment[] {
  const out: LineSegment[] = [];
  l.paths.forEach((p, k) => {
    const leave = l.leaveZ[k]!, n = leave.length;
    for (let a = 0; a + 1 < n; a++) {
      const la = Math.min(leave[a]!, l.zEnd);
      let between = l.zStart;
      for (let b = a + 1; b < n && between < la; b++) {
        const z1 = Math.min(la, leave[b]!, l.zEnd);
        if (between < z1) out.push({ ax: p[2 * a]!, ay: p[2 * a + 1]!, bx: p[2 * b]!, by: p[2 * b + 1]!, z0: between, z1, path: k, a, b });
        between = Math.max(between, leave[b]!);
      }
    }
  });
  return out;
}
