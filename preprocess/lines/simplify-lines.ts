// Line simplification over scale (issue 12, item 2): every vertex of a line gets the state at
// which it leaves, so that the line at state s is the polyline of its vertices still there.
// The rule is the boundaries' (preprocess/tgap/simplify.ts): Visvalingam-Whyatt, a vertex goes
// once the triangle it spans with its neighbours is smaller than tol²/2, tol being the map's
// resolution (tGAP meta.resolutionMm) at the state's scale; and only when that triangle holds
// no other vertex that is there at some state of the line's remaining life: of any line
// (its own included) or of any tGAP edge version. With no vertex inside the triangle, nothing
// can cross the new chord that did not cross the two segments it replaces, so no crossing is
// made with another line or a face boundary.
// Removals of all lines go in one queue, in order of state (then of area against the state's
// threshold), so a check at state s sees the other lines as they are at s. A neighbour's new
// triangle never goes before the state of the removal that made it (vertex sets shrink with
// scale). A blocked vertex is tried again once the last vertex blocking it is gone.
// Fixed: ends of polylines (joins, free ends), points where a line's polylines meet, and the
// first three points of a closed polyline.
import FlatQueue from 'flatqueue';
import KDBush from 'kdbush';
import { scaleAtZ } from '../../format/scale.js';
import { scaleInfoOf, type Tgap } from '../../format/tgap-model.js';
import { blocksRemoval } from '../geom/predicates.js';
import { pointKey, pointUses } from './point-uses.js';
import type { PrunedLine } from './prune-lines.js';

export interface SimplifiedLine extends PrunedLine {
  /** Per polyline, per vertex: the first state without the vertex (prunedStep when it stays). */
  vertexEnd: Int32Array[];
}

export interface SimplifyStats {
  /** Vertices removed before their line is pruned. */
  removed: number;
  /** Removals put off because a vertex lay in the triangle (tried again later or given up). */
  blocked: number;
  /** Vertices that could not go before their line's end. */
  given: number;
}

/** The Visvalingam threshold (m²) of every state: half the square of the map's resolution in metres. */
export function areaThresholds(tgap: Tgap): Float64Array {
  const info = scaleInfoOf(tgap);
  const out = new Float64Array(tgap.meta.steps + 1);
  for (let s = 0; s <= tgap.meta.steps; s++) {
    const tol = (tgap.meta.resolutionMm / 1000) * scaleAtZ(info, s);
    out[s] = (tol * tol) / 2;
  }
  return out;
}

export function simplifyLines(lines: readonly PrunedLine[], tgap: Tgap): { lines: SimplifiedLine[]; stats: SimplifyStats } {
  const thr = areaThresholds(tgap);
  const top = thr.length - 1;
  lines.forEach((l, i) => {
    if (!(Number.isInteger(l.prunedStep) && l.step <= l.prunedStep && l.prunedStep <= top + 1)) {
      throw new Error(`line ${i} (face ${l.face}, feature #${l.feature}): its range [${l.step}, ${l.prunedStep}) is not a range of states of the tGAP (0..${top + 1})`);
    }
  });
  /** The first state >= from whose threshold is above `area` (top + 1: none). */
  const stateFor = (area: number, from: number): number => {
    let lo = Math.max(0, from), hi = top + 1;
    while (lo < hi) {
      const mid = (lo + hi) >> 1;
      if (thr[mid]! > area) hi = mid;
      else lo = mid + 1;
    }
    return lo;
  };

  // Every vertex of every line, numbered in order; polylines as linked lists.
  let n = 0;
  for (const l of lines) for (const p of l.paths) n += p.length / 2;
  const xs = new Float64Array(n), ys = new Float64Array(n);
  const owner = new Int32Array(n), prev = new Int32Array(n), next = new Int32Array(n);
  const fixed = new Uint8Array(n), end = new Int32Array(n);
  /** Per line, the id of each polyline's first vertex. */
  const starts: number[][] = [];
  let id = 0;
  lines.forEach((l, li) => {
    const uses = pointUses(l.paths);
    const mine: number[] = [];
    for (const p of l.paths) {
      const m = p.length / 2;
      const isClosed = m > 2 && p[0] === p[p.length - 2] && p[1] === p[p.length - 1];
      mine.push(id);
      for (let k = 0; k < m; k++, id++) {
        xs[id] = p[2 * k]!;
        ys[id] = p[2 * k + 1]!;
        owner[id] = li;
        prev[id] = k > 0 ? id - 1 : -1;
        next[id] = k < m - 1 ? id + 1 : -1;
        end[id] = l.prunedStep;
        // A closed polyline's first point is also its last: counted twice in `uses`.
        const shared = uses.get(pointKey(p[2 * k]!, p[2 * k + 1]!))! > (isClosed && (k === 0 || k === m - 1) ? 2 : 1);
        if (k === 0 || k === m - 1 || shared || (isClosed && k <= 2)) fixed[id] = 1;
      }
    }
    starts.push(mine);
  });

  // Obstacles: line vertices (there while not removed and their line is), tGAP vertices (there
  // from the first edge version holding them to the last one's end).
  const lineIndex = new KDBush(Math.max(1, n), 64, Float64Array);
  for (let v = 0; v < n; v++) lineIndex.add(xs[v]!, ys[v]!);
  if (n === 0) lineIndex.add(0, 0);
  lineIndex.finish();
  const nv = tgap.xs.length;
  const lo = new Int32Array(nv).fill(-1), hi = new Int32Array(nv);
  for (const e of tgap.edges) {
    for (const v of e.verts) {
      if (lo[v]! < 0 || e.stepLow < lo[v]!) lo[v] = e.stepLow;
      hi[v] = Math.max(hi[v]!, e.stepHigh);
    }
  }
  const edgeIndex = new KDBush(Math.max(1, nv), 64, Float64Array);
  for (let v = 0; v < nv; v++) edgeIndex.add(tgap.xs[v]!, tgap.ys[v]!);
  if (nv === 0) edgeIndex.add(0, 0);
  edgeIndex.finish();

  const area = (v: number): number => {
    const a = prev[v]!, b = next[v]!;
    return Math.abs((xs[v]! - xs[a]!) * (ys[b]! - ys[a]!) - (xs[b]! - xs[a]!) * (ys[v]! - ys[a]!)) / 2;
  };
  // Queued by state, then by area against the state's threshold (below 1): the state is kept
  // apart, as state + fraction may round up to the next state.
  const priority = new Float64Array(n).fill(-1);
  const stateOf = new Int32Array(n);
  const queue = new FlatQueue<number>();
  const push = (v: number, state: number): void => {
    if (state >= lines[owner[v]!]!.prunedStep) {
      priority[v] = -1;
      return;
    }
    stateOf[v] = state;
    priority[v] = state + area(v) / thr[state]!;
    queue.push(v, priority[v]);
  };
  for (let v = 0; v < n; v++) if (!fixed[v]) push(v, stateFor(area(v), lines[owner[v]!]!.step));

  /**
   * At state s, the latest end of the vertices in v's triangle that are there at some state of
   * [s, P) (P: the line's prune step); -1 when there are none.
   */
  const blockedUntil = (v: number, s: number): number => {
    const a = prev[v]!, b = next[v]!;
    const P = lines[owner[v]!]!.prunedStep;
    const ax = xs[a]!, ay = ys[a]!, vx = xs[v]!, vy = ys[v]!, bx = xs[b]!, by = ys[b]!;
    const minX = Math.min(ax, vx, bx), minY = Math.min(ay, vy, by), maxX = Math.max(ax, vx, bx), maxY = Math.max(ay, vy, by);
    let until = -1;
    for (const w of lineIndex.range(minX, minY, maxX, maxY)) {
      if (w === a || w === v || w === b || end[w]! <= s || lines[owner[w]!]!.step >= P) continue;
      if (blocksRemoval(ax, ay, vx, vy, bx, by, xs[w]!, ys[w]!)) until = Math.max(until, end[w]!);
    }
    for (const w of edgeIndex.range(minX, minY, maxX, maxY)) {
      if (lo[w]! < 0 || hi[w]! <= s || lo[w]! >= P) continue;
      if (blocksRemoval(ax, ay, vx, vy, bx, by, tgap.xs[w]!, tgap.ys[w]!)) until = Math.max(until, hi[w]!);
    }
    return until;
  };

  const stats: SimplifyStats = { removed: 0, blocked: 0, given: 0 };
  while (queue.length > 0) {
    const pr = queue.peekValue()!;
    const v = queue.pop()!;
    if (pr !== priority[v]) continue; // removed, or a stale entry
    const s = stateOf[v]!;
    const until = blockedUntil(v, s);
    if (until >= 0) {
      stats.blocked++;
      if (until < lines[owner[v]!]!.prunedStep) push(v, until);
      else {
        priority[v] = -1;
        stats.given++;
      }
      continue;
    }
    end[v] = s;
    priority[v] = -1;
    stats.removed++;
    const a = prev[v]!, b = next[v]!;
    next[a] = b;
    prev[b] = a;
    // The neighbours' new triangles go no earlier than this removal's state.
    for (const w of [a, b]) if (!fixed[w]) push(w, stateFor(area(w), s));
  }

  const out = lines.map((l, li): SimplifiedLine => {
    const vertexEnd = l.paths.map((p, k) => end.slice(starts[li]![k], starts[li]![k]! + p.length / 2));
    return { ...l, vertexEnd };
  });
  return { lines: out, stats };
}

/** A simplified line's polylines at state s (its vertices still there then). */
export function linePathsAt(line: SimplifiedLine, s: number): Float64Array[] {
  return line.paths.map((p, k) => {
    const ends = line.vertexEnd[k]!;
    const out: number[] = [];
    for (let i = 0; i < ends.length; i++) if (ends[i]! > s) out.push(p[2 * i]!, p[2 * i + 1]!);
    return Float64Array.from(out);
  });
}

/** A simplified line's versions: each with the state it starts at, up to the next one's (the last up to prunedStep). */
export function lineVersions(line: SimplifiedLine): { step: number; paths: Float64Array[] }[] {
  const starts = new Set<number>([line.step]);
  for (const ends of line.vertexEnd) for (const e of ends) if (e > line.step && e < line.prunedStep) starts.add(e);
  return [...starts].sort((a, b) => a - b).map((step) => ({ step, paths: linePathsAt(line, step) }));
}
