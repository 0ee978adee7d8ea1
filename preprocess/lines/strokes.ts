// Strokes: chains of lines that continue one another, as a reader follows a road through its
// junctions (the "good continuation" of Thomson and Richardson's strokes). A road area is cut
// into many faces at every junction, so each of its lines is short; weighed alone, the main road
// looks less important than a long street and goes first. Weighed by its stroke, each piece of
// the main road counts the whole road.
//
// Where lines of the same group (style rule) end at one point, the two ends that continue each
// other best (most nearly opposite directions) are paired first, then the next best of the rest,
// as long as the turn is at most `maxTurnDeg`. A line that ends at another's interior (a street
// meeting a main road) continues nothing. Paired lines are one stroke.
import { pointKey, pointUses } from './point-uses.js';

export interface StrokeLine {
  paths: readonly Float64Array[];
  length: number;
}

/** How far along a path its direction at an end is read: a centreline bends near junctions. */
const DIRECTION_REACH = 25;

interface LineEnd {
  line: number;
  /** Unit vector from the end into the line. */
  dx: number;
  dy: number;
}

/** The stroke of each line (the lowest line index in it) and each stroke's length, per line. */
export function strokes(lines: readonly StrokeLine[], group: ArrayLike<number>, maxTurnDeg = 45): { stroke: Int32Array; strokeLength: Float64Array } {
  const n = lines.length;
  const parent = Int32Array.from({ length: n }, (_, i) => i);
  const find = (i: number): number => {
    while (parent[i] !== i) i = parent[i] = parent[parent[i]!]!;
    return i;
  };
  const ends = new Map<string, LineEnd[]>();
  lines.forEach((l, i) => {
    const uses = pointUses(l.paths);
    for (const p of l.paths) {
      for (const atStart of [true, false]) {
        const k = atStart ? 0 : p.length - 2;
        const key = pointKey(p[k]!, p[k + 1]!);
        // A junction inside the line, or a closed path: not an end of the line.
        if (uses.get(key) !== 1) continue;
        const d = direction(p, atStart);
        if (!d) continue;
        const list = ends.get(key) ?? [];
        list.push({ line: i, dx: d[0], dy: d[1] });
        ends.set(key, list);
      }
    }
  });
  // Straight on is a dot product of -1 (both directions point away from the point).
  const limit = -Math.cos((maxTurnDeg * Math.PI) / 180);
  for (const at of ends.values()) {
    if (at.length < 2) continue;
    const pairs: [number, number, number][] = [];
    for (let a = 0; a < at.length; a++) {
      for (let b = a + 1; b < at.length; b++) {
        const ea = at[a]!, eb = at[b]!;
        if (ea.line === eb.line || group[ea.line] !== group[eb.line]) continue;
        const dot = ea.dx * eb.dx + ea.dy * eb.dy;
        if (dot <= limit) pairs.push([dot, a, b]);
      }
    }
    pairs.sort((p, q) => p[0] - q[0] || p[1] - q[1] || p[2] - q[2]);
    const used = new Set<number>();
    for (const [, a, b] of pairs) {
      if (used.has(a) || used.has(b)) continue;
      used.add(a).add(b);
      const ra = find(at[a]!.line), rb = find(at[b]!.line);
      if (ra !== rb) parent[Math.max(ra, rb)] = Math.min(ra, rb);
    }
  }
  const stroke = Int32Array.from({ length: n }, (_, i) => find(i));
  const total = new Float64Array(n);
  lines.forEach((l, i) => (total[stroke[i]!]! += l.length));
  return { stroke, strokeLength: Float64Array.from(stroke, (s) => total[s]!) };
}

/** The unit direction from a path's end toward its point DIRECTION_REACH along (or its far end). */
function direction(p: Float64Array, atStart: boolean): [number, number] | null {
  const m = p.length / 2;
  const at = (k: number): [number, number] => {
    const v = atStart ? k : m - 1 - k;
    return [p[2 * v]!, p[2 * v + 1]!];
  };
  const [x0, y0] = at(0);
  let travelled = 0;
  let [px, py] = [x0, y0];
  let far: [number, number] = [x0, y0];
  for (let k = 1; k < m; k++) {
    const q = at(k);
    travelled += Math.hypot(q[0] - px, q[1] - py);
    [px, py] = q;
    far = q;
    if (travelled >= DIRECTION_REACH) break;
  }
  const dx = far[0] - x0, dy = far[1] - y0, len = Math.hypot(dx, dy);
  return len > 0 ? [dx / len, dy / len] : null;
}
