// Surface triangles into chunks of nearly equal size with compact 3D boxes, triangles never
// cut (each goes to exactly one chunk). A recursive best split, like a kd-tree built with a
// cost model: every set is halved (in bytes) along the axis - x, y, the z a triangle appears
// at or the z it is covered at - that makes the two halves least likely to be fetched. A chunk
// is fetched by the views whose ground box meets its box at a z in its z range, so that
// likelihood is the chance that a view placed at random, at a scale drawn evenly in log-scale
// from the chunk's z range, meets the chunk's ground box.
import type { Surfaces } from './surfaces.js';

export interface ChunkPlan {
  /** Triangle indices, chunk by chunk: chunk c holds order[start[c] .. start[c + 1]). */
  order: Uint32Array;
  start: number[];
}

export interface ChunkingInput {
  surfaces: Surfaces;
  xs: Float64Array;
  ys: Float64Array;
  extent: [number, number, number, number];
  /** Scale denominator at z. */
  scaleAt: (z: number) => number;
  /** Ground width and height of a view per unit of scale denominator (1280 x 720 px at 0.28 mm: 0.3584, 0.2016). */
  viewPerScale: [number, number];
  targetBytes: number;
}

const AXES = 4;

export function planChunks(inp: ChunkingInput): ChunkPlan {
  const { surfaces: s, xs, ys } = inp;
  const n = s.count;
  // Per triangle: its ground box, its z range and what it adds to a chunk's bytes.
  const bx0 = new Float64Array(n), by0 = new Float64Array(n), bx1 = new Float64Array(n), by1 = new Float64Array(n);
  const zl = new Float64Array(n), zh = new Float64Array(n);
  for (let i = 0; i < n; i++) {
    const a = s.v[3 * i]!, b = s.v[3 * i + 1]!, c = s.v[3 * i + 2]!;
    bx0[i] = Math.min(xs[a]!, xs[b]!, xs[c]!);
    bx1[i] = Math.max(xs[a]!, xs[b]!, xs[c]!);
    by0[i] = Math.min(ys[a]!, ys[b]!, ys[c]!);
    by1[i] = Math.max(ys[a]!, ys[b]!, ys[c]!);
    zl[i] = s.z[i]!;
    // Already capped at the top of the cube by buildSurfaces.
    zh[i] = s.zEnd[i]!;
  }
  const cost = triangleBytes(s);
  let total = 0;
  for (let i = 0; i < n; i++) total += cost[i]!;
  const target = Math.min(inp.targetBytes, total);

  // One list of all triangles per axis, sorted by it; splitting keeps each list sorted.
  const keys: ((i: number) => number)[] = [(i) => bx0[i]! + bx1[i]!, (i) => by0[i]! + by1[i]!, (i) => zl[i]!, (i) => zh[i]!];
  const lists = keys.map((key) => sortedBy(n, key));
  const tmp = new Uint32Array(n);
  const left = new Uint8Array(n);
  const [vw, vh] = inp.viewPerScale;
  const [ex0, ey0, ex1, ey1] = inp.extent;
  const ew = ex1 - ex0, eh = ey1 - ey0;
  // Views are drawn evenly in log-scale from the base scale to where the whole extent fits.
  const sMin = Math.log(inp.scaleAt(0)), sMax = Math.max(sMin + 0.1, Math.log(Math.max(ew / vw, eh / vh)));
  /** Chance that a random view at a scale within the box's z range meets its ground box. */
  const hitChance = (x0: number, y0: number, x1: number, y1: number, z0: number, z1: number): number => {
    const s0 = Math.min(sMax, Math.log(inp.scaleAt(z0))), s1 = Math.min(sMax, Math.log(inp.scaleAt(Math.max(z0, z1))));
    if (s1 <= sMin && s0 <= sMin) return 0.05;
    const steps = 8;
    let sum = 0;
    for (let k = 0; k < steps; k++) {
      const sc = Math.exp(s0 + ((k + 0.5) / steps) * (s1 - s0));
      const w = vw * sc, h = vh * sc;
      sum += Math.min(1, (x1 - x0 + w) / (ew + w)) * Math.min(1, (y1 - y0 + h) / (eh + h));
    }
    return (sum / steps) * Math.max(1e-9, s1 - s0 + 0.05);
  };
  const start: number[] = [];
  const split = (lo: number, hi: number, k: number, bytes: number): void => {
    if (k <= 1 || hi - lo <= 1) {
      start.push(lo);
      return;
    }
    let best = -1, bestCost = Infinity, bestAt = lo, bestLeftBytes = 0, bestKl = 1;
    for (let a = 0; a < AXES; a++) {
      const list = lists[a]!;
      const key = keys[a]!;
      // Candidate cuts: at each whole number of chunks' worth of bytes (at most 15 of them),
      // moved to where the key changes when that is near (a set of equal keys, say every
      // triangle appearing at z = 0, is then not cut through).
      const js: number[] = [];
      const step = Math.max(1, Math.floor((k - 1) / 15));
      for (let j = 1; j < k; j += step) js.push(j);
      if (js[js.length - 1] !== k - 1) js.push(k - 1);
      const cuts: { at: number; kl: number }[] = [];
      let acc = 0, at = lo;
      const cum: number[] = [];
      for (const j of js) {
        const want = (bytes * j) / k;
        while (at < hi - 1 && acc + cost[list[at]!]! / 2 < want) acc += cost[list[at++]!]!;
        cum.push(at);
      }
      const slack = Math.max(1, Math.floor((hi - lo) / (8 * k)));
      js.forEach((j, ji) => {
        let c = Math.max(lo + 1, cum[ji]!);
        // Look a little either way for a change of key.
        const kc = key(list[c - 1]!);
        if (key(list[c]!) === kc) {
          let f = c, b = c;
          while (f < Math.min(hi - 1, c + slack) && key(list[f]!) === kc) f++;
          while (b > Math.max(lo + 1, c - slack) && key(list[b - 1]!) === key(list[b]!)) b--;
          if (key(list[f - 1]!) !== key(list[f]!)) c = f;
          else if (key(list[b - 1]!) !== key(list[b]!)) c = b;
        }
        cuts.push({ at: c, kl: j });
      });
      // Boxes of every candidate's two sides: one pass forward, one backward.
      const order = cuts.map((_, i) => i).sort((p, q) => cuts[p]!.at - cuts[q]!.at);
      const leftBox: number[][] = [], rightBox: number[][] = [], leftBytes: number[] = [];
      {
        let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity, z0 = Infinity, z1 = -Infinity, sum = 0;
        let kk = lo;
        for (const ci of order) {
          for (; kk < cuts[ci]!.at; kk++) {
            const i = list[kk]!;
            if (bx0[i]! < x0) x0 = bx0[i]!;
            if (bx1[i]! > x1) x1 = bx1[i]!;
            if (by0[i]! < y0) y0 = by0[i]!;
            if (by1[i]! > y1) y1 = by1[i]!;
            if (zl[i]! < z0) z0 = zl[i]!;
            if (zh[i]! > z1) z1 = zh[i]!;
            sum += cost[i]!;
          }
          leftBox[ci] = [x0, y0, x1, y1, z0, z1];
          leftBytes[ci] = sum;
        }
      }
      {
        let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity, z0 = Infinity, z1 = -Infinity;
        let kk = hi - 1;
        for (let oi = order.length - 1; oi >= 0; oi--) {
          const ci = order[oi]!;
          for (; kk >= cuts[ci]!.at; kk--) {
            const i = list[kk]!;
            if (bx0[i]! < x0) x0 = bx0[i]!;
            if (bx1[i]! > x1) x1 = bx1[i]!;
            if (by0[i]! < y0) y0 = by0[i]!;
            if (by1[i]! > y1) y1 = by1[i]!;
            if (zl[i]! < z0) z0 = zl[i]!;
            if (zh[i]! > z1) z1 = zh[i]!;
          }
          rightBox[ci] = [x0, y0, x1, y1, z0, z1];
        }
      }
      cuts.forEach((cut, ci) => {
        const lb = leftBytes[ci]!, rb = bytes - lb;
        // Keep chunk sizes even: each side must fit its number of chunks within 15%.
        const kl = Math.min(k - 1, Math.max(1, Math.round((k * lb) / bytes)));
        if (Math.abs(lb / kl / (bytes / k) - 1) > 0.15 || Math.abs(rb / (k - kl) / (bytes / k) - 1) > 0.15) return;
        const L = leftBox[ci]! as [number, number, number, number, number, number];
        const R = rightBox[ci]! as [number, number, number, number, number, number];
        const c = hitChance(...L) * lb + hitChance(...R) * rb;
        if (c < bestCost) {
          bestCost = c;
          best = a;
          bestAt = cut.at;
          bestLeftBytes = lb;
          bestKl = kl;
        }
      });
    }
    if (best < 0) {
      // No candidate kept the sizes even (a few huge triangles): halve by bytes along x.
      best = 0;
      let acc = 0, at = lo;
      const list = lists[0]!;
      bestKl = Math.floor(k / 2);
      while (at < hi - 1 && acc + cost[list[at]!]! / 2 < (bytes * bestKl) / k) acc += cost[list[at++]!]!;
      bestAt = Math.max(lo + 1, at);
      bestLeftBytes = 0;
      for (let kk = lo; kk < bestAt; kk++) bestLeftBytes += cost[list[kk]!]!;
    }
    const kl = bestKl;
    const chosen = lists[best]!;
    for (let k2 = lo; k2 < hi; k2++) left[chosen[k2]!] = k2 < bestAt ? 1 : 0;
    for (let a = 0; a < AXES; a++) {
      if (a === best) continue;
      // Stable partition: each side stays sorted by this axis.
      const list = lists[a]!;
      let l = lo, r = 0;
      for (let k2 = lo; k2 < hi; k2++) {
        const i = list[k2]!;
        if (left[i]) list[l++] = i;
        else tmp[r++] = i;
      }
      list.set(tmp.subarray(0, r), l);
    }
    split(lo, bestAt, kl, bestLeftBytes);
    split(bestAt, hi, k - kl, bytes - bestLeftBytes);
  };
  split(0, n, Math.max(1, Math.round(total / target)), total);
  start.push(n);
  // The chunks' triangles in the order of the first axis list (any list holds the same sets).
  const chunkOf = new Int32Array(n);
  const x = lists[0]!;
  for (let c = 0; c + 1 < start.length; c++) for (let k = start[c]!; k < start[c + 1]!; k++) chunkOf[x[k]!] = c;
  // Within a chunk, keep a piece's triangles together (shared vertices) in a fixed order.
  const order = sortedBy(n, (i) => chunkOf[i]! * 4294967296 + s.piece[i]!);
  return { order, start };
}

/**
 * Indices 0..n-1 sorted by key, with a native numeric sort: the key, quantized to 2^26 levels
 * over its range, and the index are packed into one exact double (ties go by index).
 */
function sortedBy(n: number, key: (i: number) => number): Uint32Array {
  const k = new Float64Array(n);
  let lo = Infinity, hi = -Infinity;
  for (let i = 0; i < n; i++) {
    const v = key(i);
    k[i] = v;
    if (v < lo) lo = v;
    if (v > hi) hi = v;
  }
  const levels = 67108863;
  const scale = hi > lo ? levels / (hi - lo) : 0;
  const packed = new Float64Array(n);
  for (let i = 0; i < n; i++) packed[i] = Math.min(levels, Math.floor((k[i]! - lo) * scale)) * 67108864 + i;
  packed.sort();
  const idx = new Uint32Array(n);
  for (let i = 0; i < n; i++) idx[i] = packed[i]! % 67108864;
  return idx;
}

/**
 * Bytes each triangle costs in a chunk: its three u16 indices and its share of its piece's
 * vertices (docs/FORMAT.md: 24 bytes a vertex).
 */
function triangleBytes(s: Surfaces): Float64Array {
  const n = s.count;
  const verts = new Float64Array(s.pieces), tris = new Float64Array(s.pieces);
  // A piece's triangles come in runs; vertices are counted per run (an estimate, a little high
  // for a piece split over several runs).
  let run = new Set<number>();
  for (let i = 0; i < n; i++) {
    const p = s.piece[i]!;
    if (i > 0 && s.piece[i - 1] !== p) run = new Set();
    tris[p]!++;
    for (let j = 0; j < 3; j++) {
      const v = s.v[3 * i + j]!;
      if (!run.has(v)) {
        run.add(v);
        verts[p]!++;
      }
    }
  }
  const cost = new Float64Array(n);
  for (let i = 0; i < n; i++) cost[i] = 6 + (24 * verts[s.piece[i]!]!) / tris[s.piece[i]!]!;
  return cost;
}
