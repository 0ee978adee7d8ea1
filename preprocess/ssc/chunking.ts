// Surface triangles into chunks of nearly equal size with compact 3D boxes, triangles never
// cut (each goes to exactly one chunk). A recursive best split, like a kd-tree built with a
// cost model: every set is halved (in bytes) along the axis - x, y, the z a triangle appears
// at or the z it is covered at - that makes the two halves least likely to be fetched
// (view-hit-chance.ts). The first cuts are fixed: the triangles the map's default first view (the
// whole extent, on a desktop screen and on a phone) needs are chunked apart from the rest, as
// the model, spread over all scales, gives that one view no weight of its own.
import { candidateCuts, sideBoxes, type SortedRange, type TriangleBoxes } from './chunk-cuts.js';
import { sortedBy } from './sorted-by-key.js';
import type { Surfaces } from './surfaces.js';
import { triangleBytes } from './triangle-bytes.js';
import { viewHitChance, type Box6, type ViewModel } from './view-hit-chance.js';

export interface ChunkPlan {
  /** Triangle indices, chunk by chunk: chunk c holds order[start[c] .. start[c + 1]). */
  order: Uint32Array;
  start: number[];
}

export interface ChunkingInput extends ViewModel {
  surfaces: Surfaces;
  xs: Float64Array;
  ys: Float64Array;
  targetBytes: number;
}

/** Sizes of the two sides of each chunk may differ from even by this share. */
const EVEN_WITHIN = 0.15;

/**
 * The chunks' worth the triangles above the whole extent's z take at most (each band of them
 * rounded to whole chunks): as a first view of the whole extent needs all of them, a large set
 * of them goes into fewer, larger chunks (8 rounds of the 6 requests a browser makes to a host
 * at once over HTTP/1.1). Each chunk repeats the points, z values and faces it shares with its
 * neighbours: nlcd_zion's whole-extent view queried 212 chunks, 1,692 kB gzip, with chunks of
 * the usual size, and 39, 1,463 kB, with 48 (docs/FORMAT.md, "index.json").
 */
export const WHOLE_EXTENT_MAX_CHUNKS = 48;

/**
 * The cube's chunks, so that a first view of the whole extent fetches little it does not need,
 * in few requests (docs/FORMAT.md, "index.json": the figures). `wholeExtentZs` are the z at
 * which the whole extent fits each default view (the model's, a phone's; wholeExtentScale): the
 * triangles covered above the lowest of them (all that a slice there or higher needs) go into
 * `maxAbove` chunks' worth at most (WHOLE_EXTENT_MAX_CHUNKS), apart from the rest, and those
 * covered above each higher one apart again, highest first.
 */
export function planChunks(inp: ChunkingInput, wholeExtentZs: readonly number[], maxAbove = WHOLE_EXTENT_MAX_CHUNKS): ChunkPlan {
  const s = inp.surfaces;
  const boxes = triangleBoxes(s, inp.xs, inp.ys), bytes = triangleBytes(s);
  const cuts = [...new Set(wholeExtentZs.filter((z) => !Number.isNaN(z)))].sort((a, b) => b - a);
  // sets[k] holds the triangles covered above cuts[k] and not above cuts[k - 1]; the last, the rest.
  const sets: number[][] = Array.from({ length: cuts.length + 1 }, () => []);
  let aboveBytes = 0;
  for (let i = 0; i < s.count; i++) {
    let k = 0;
    while (k < cuts.length && !(s.zEnd[i]! > cuts[k]!)) k++;
    sets[k]!.push(i);
    if (k < cuts.length) aboveBytes += bytes[i]!;
  }
  const below = sets[cuts.length]!;
  const nonEmpty = sets.filter((set) => set.length > 0);
  // Cuts that leave all on one side change nothing; a cube of one chunk stays one.
  if (nonEmpty.length < 2 || chunksFor(bytes.reduce((a, b) => a + b, 0), inp.targetBytes) === 1) return planOver(inp, Uint32Array.from({ length: s.count }, (_, i) => i), boxes, bytes);
  const above = { ...inp, targetBytes: Math.max(inp.targetBytes, aboveBytes / maxAbove) };
  return joinPlans(nonEmpty.map((set) => planOver(set === below ? inp : above, Uint32Array.from(set), boxes, bytes)));
}

/** Plans of disjoint sets of triangles, as one: their chunks one set after the other. */
function joinPlans(plans: ChunkPlan[]): ChunkPlan {
  const order = new Uint32Array(plans.reduce((n, p) => n + p.order.length, 0));
  const start: number[] = [];
  let n = 0;
  for (const p of plans) {
    order.set(p.order, n);
    for (let c = 0; c + 1 < p.start.length; c++) start.push(n + p.start[c]!);
    n += p.order.length;
  }
  start.push(n);
  return { order, start };
}

/**
 * The floor triangles (lowest corner at z <= 0) into chunks of their own, for the views whose
 * slice lies below `top` (docs/FORMAT.md, "Floor chunks"): split by ground alone, as their z
 * range is the same.
 */
export function planFloorChunks(inp: ChunkingInput, top: number): ChunkPlan {
  const s = inp.surfaces;
  const floor = floorTriangles(s);
  const boxes = triangleBoxes(s, inp.xs, inp.ys);
  boxes.z0.fill(0);
  boxes.z1.fill(top);
  return planOver(inp, floor, boxes, triangleBytes(s));
}

/** The triangles whose lowest corner lies at or below z = 0: all that a slice below any other's lowest corner shows. */
export function floorTriangles(s: Surfaces): Uint32Array {
  const out: number[] = [];
  for (let i = 0; i < s.count; i++) if (s.zMin[i]! <= 0) out.push(i);
  return Uint32Array.from(out);
}

/**
 * The z below which a slice shows floor triangles only: the lowest corner of every other
 * triangle; null when there is none (the floor is the whole cube).
 */
export function floorTop(s: Surfaces): number | null {
  let top = Infinity;
  for (let i = 0; i < s.count; i++) if (s.zMin[i]! > 0) top = Math.min(top, s.zMin[i]!);
  return top === Infinity ? null : top;
}

/** Triangles `tris` (boxes and bytes by triangle index) into chunks; the plan names triangle indices. */
function planOver(inp: ChunkingInput, tris: Uint32Array, boxes: TriangleBoxes, bytes: Float64Array): ChunkPlan {
  const s = inp.surfaces;
  const pick = (a: Float64Array): Float64Array => Float64Array.from(tris, (i) => a[i]!);
  const sub: TriangleBoxes = { x0: pick(boxes.x0), y0: pick(boxes.y0), x1: pick(boxes.x1), y1: pick(boxes.y1), z0: pick(boxes.z0), z1: pick(boxes.z1) };
  const { chunkOf, start } = splitEvenly(sub, pick(bytes), inp);
  // Within a chunk, keep a piece's triangles together (shared vertices) in a fixed order.
  const order = sortedBy(tris.length, (k) => chunkOf[k]! * 4294967296 + s.piece[tris[k]!]!).map((k) => tris[k]!);
  return { order, start };
}

/**
 * Items (triangles, lines) with boxes and sizes in bytes into chunks of nearly
 * `targetBytes` each: the chunk of every item, and the first position of each chunk in items
 * ordered by chunk (with the count last).
 */
export function splitEvenly(boxes: TriangleBoxes, cost: Float64Array, inp: ViewModel & { targetBytes: number }): { chunkOf: Int32Array; start: number[] } {
  const n = cost.length;
  let total = 0;
  for (let i = 0; i < n; i++) total += cost[i]!;
  const split = new ChunkSplit(boxes, cost, viewHitChance(inp));
  split.split(0, n, chunksFor(total, inp.targetBytes), total);
  const start = [...split.start, n];
  // The chunks' items in the order of the first axis list (any list holds the same sets).
  const chunkOf = new Int32Array(n);
  const x = split.lists[0]!;
  for (let c = 0; c + 1 < start.length; c++) for (let k = start[c]!; k < start[c + 1]!; k++) chunkOf[x[k]!] = c;
  return { chunkOf, start };
}

/** How many chunks of about `targetBytes` `total` bytes make (at least one). */
const chunksFor = (total: number, targetBytes: number): number => Math.max(1, Math.round(total / Math.min(targetBytes, total)));

/** Per triangle: its ground box and its z range. */
function triangleBoxes(s: Surfaces, xs: Float64Array, ys: Float64Array): TriangleBoxes {
  const n = s.count;
  const b: TriangleBoxes = {
    x0: new Float64Array(n), y0: new Float64Array(n), x1: new Float64Array(n), y1: new Float64Array(n),
    z0: new Float64Array(n), z1: new Float64Array(n),
  };
  for (let i = 0; i < n; i++) {
    const p = s.v[3 * i]!, q = s.v[3 * i + 1]!, r = s.v[3 * i + 2]!;
    b.x0[i] = Math.min(xs[p]!, xs[q]!, xs[r]!);
    b.x1[i] = Math.max(xs[p]!, xs[q]!, xs[r]!);
    b.y0[i] = Math.min(ys[p]!, ys[q]!, ys[r]!);
    b.y1[i] = Math.max(ys[p]!, ys[q]!, ys[r]!);
    b.z0[i] = s.zMin[i]!;
    // Already capped at the top of the cube by buildSurfaces.
    b.z1[i] = s.zEnd[i]!;
  }
  return b;
}

interface Cut {
  axis: number;
  at: number;
  /** Chunks and bytes on the left side. */
  kl: number;
  leftBytes: number;
}

/**
 * The recursive split. It keeps one list of all triangles per axis, sorted by it; a split
 * partitions every list stably, so each range stays sorted along every axis.
 */
class ChunkSplit {
  /** First triangle position of each chunk (in lists[0]), in order. */
  readonly start: number[] = [];
  readonly lists: Uint32Array[];
  private readonly keys: ((i: number) => number)[];
  private readonly tmp: Uint32Array;
  private readonly left: Uint8Array;

  constructor(private readonly boxes: TriangleBoxes, private readonly cost: Float64Array, private readonly hitChance: (...box: Box6) => number) {
    const b = boxes;
    this.keys = [(i) => b.x0[i]! + b.x1[i]!, (i) => b.y0[i]! + b.y1[i]!, (i) => b.z0[i]!, (i) => b.z1[i]!];
    const n = cost.length;
    this.lists = this.keys.map((key) => sortedBy(n, key));
    this.tmp = new Uint32Array(n);
    this.left = new Uint8Array(n);
  }

  /** Splits positions lo .. hi (holding `bytes`) into k chunks. */
  split(lo: number, hi: number, k: number, bytes: number): void {
    if (k <= 1 || hi - lo <= 1) {
      this.start.push(lo);
      return;
    }
    const cut = this.cheapestEvenCut(lo, hi, k, bytes) ?? this.halveAlongX(lo, hi, k, bytes);
    this.partition(cut.axis, lo, hi, cut.at);
    this.split(lo, cut.at, cut.kl, cut.leftBytes);
    this.split(cut.at, hi, k - cut.kl, bytes - cut.leftBytes);
  }

  /** Of the candidate cuts along every axis that keep chunk sizes even, the one least likely fetched. */
  private cheapestEvenCut(lo: number, hi: number, k: number, bytes: number): Cut | null {
    let best: Cut | null = null, bestCost = Infinity;
    for (let axis = 0; axis < this.lists.length; axis++) {
      const range: SortedRange = { list: this.lists[axis]!, key: this.keys[axis]!, lo, hi, k, bytes };
      const cuts = candidateCuts(range, this.cost);
      const { leftBox, rightBox, leftBytes } = sideBoxes(range, cuts, this.boxes, this.cost);
      cuts.forEach((cut, ci) => {
        const lb = leftBytes[ci]!, rb = bytes - lb;
        // Keep chunk sizes even: each side must fit its number of chunks within 15%.
        const kl = Math.min(k - 1, Math.max(1, Math.round((k * lb) / bytes)));
        if (Math.abs(lb / kl / (bytes / k) - 1) > EVEN_WITHIN || Math.abs(rb / (k - kl) / (bytes / k) - 1) > EVEN_WITHIN) return;
        const c = this.hitChance(...leftBox[ci]!) * lb + this.hitChance(...rightBox[ci]!) * rb;
        if (c < bestCost) {
          bestCost = c;
          best = { axis, at: cut.at, kl, leftBytes: lb };
        }
      });
    }
    return best;
  }

  /** When no candidate kept the sizes even (a few huge triangles): halve by bytes along x. */
  private halveAlongX(lo: number, hi: number, k: number, bytes: number): Cut {
    const cost = this.cost;
    const list = this.lists[0]!;
    const kl = Math.floor(k / 2);
    let acc = 0, at = lo;
    while (at < hi - 1 && acc + cost[list[at]!]! / 2 < (bytes * kl) / k) acc += cost[list[at++]!]!;
    at = Math.max(lo + 1, at);
    let leftBytes = 0;
    for (let kk = lo; kk < at; kk++) leftBytes += cost[list[kk]!]!;
    return { axis: 0, at, kl, leftBytes };
  }

  /** Splits lo .. hi of every list at the cut along `axis` (stable: each side stays sorted by its axis). */
  private partition(axis: number, lo: number, hi: number, at: number): void {
    const { left, tmp } = this;
    const chosen = this.lists[axis]!;
    for (let k2 = lo; k2 < hi; k2++) left[chosen[k2]!] = k2 < at ? 1 : 0;
    for (let a = 0; a < this.lists.length; a++) {
      if (a === axis) continue;
      const list = this.lists[a]!;
      let l = lo, r = 0;
      for (let k2 = lo; k2 < hi; k2++) {
        const i = list[k2]!;
        if (left[i]) list[l++] = i;
        else tmp[r++] = i;
      }
      list.set(tmp.subarray(0, r), l);
    }
  }
}
