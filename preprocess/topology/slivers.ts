// Slivers: coordinate noise in real data leaves parts of faces a millimetre wide or less along
// their neighbours. Such a part (a polygon of a feature, with its holes) thinner than the
// sliver width is dissolved into the neighbour with the longest shared boundary, and a ring
// the snapping to the precision collapsed is left out; each is counted, or, when slivers are
// refused, named with its feature and place, all of them in one run.
import { ringArea2, ringArea2Flat, ringLength, ringPerimeterFlat } from '../geom/ring.js';
import type { InputFeature } from '../io/read-input.js';
import { withFaces, type HalfEdges } from './half-edges.js';
import { outsideCycles } from './partition-checks.js';
import type { Refusal } from './refusal.js';
import type { Ring, TopologyRepairs } from './topology-types.js';

export interface SliverOptions {
  /** Parts thinner than this (CRS units) are slivers. */
  width: number;
  /** Named as problems instead of dissolved. */
  refuse: boolean;
  precision: number;
}

/** A part of a feature (polygon `part` of face `face`) and its width, 2 x area / perimeter. */
export interface ThinPart {
  face: number;
  part: number;
  width: number;
}

/**
 * The parts of the features narrower than the precision, from the input's coordinates: the
 * snapping to the precision cannot keep them (it folds their sides onto each other, and they
 * cross), so they are left out before it, and their neighbours, within the precision of each
 * other, meet.
 */
export function partsNarrowerThan(features: readonly InputFeature[], precision: number): ThinPart[] {
  const out: ThinPart[] = [];
  if (!(precision > 0)) return out;
  features.forEach((f, fi) => {
    f.polygons.forEach((rings, part) => {
      let area2 = 0, perimeter = 0;
      rings.forEach((ring, i) => {
        const a2 = Math.abs(ringArea2Flat(ring));
        area2 += i === 0 ? a2 : -a2;
        perimeter += ringPerimeterFlat(ring);
      });
      // A part of no area is the data's own (a degenerate ring), refused as such.
      if (area2 > 0 && perimeter > 0 && area2 / perimeter < precision) out.push({ face: fi + 1, part, width: area2 / perimeter });
    });
  });
  return out;
}

/** The box of a feature's part (its outer ring) in the input, widened by `margin`. */
export function partBox(features: readonly InputFeature[], face: number, part: number, margin: number): [number, number, number, number] {
  const ring = features[face - 1]!.polygons[part]![0]!;
  let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  for (let i = 0; i + 1 < ring.length; i += 2) {
    x0 = Math.min(x0, ring[i]!); x1 = Math.max(x1, ring[i]!);
    y0 = Math.min(y0, ring[i + 1]!); y1 = Math.max(y1, ring[i + 1]!);
  }
  return [x0 - margin, y0 - margin, x1 + margin, y1 + margin];
}

/**
 * Where a sliver left out was not everywhere within the precision of its neighbours' sides,
 * they do not meet: a thin gap is left. Each gap thinner than the sliver width (2 x area /
 * perimeter) inside the box of a sliver left out goes to the face with the longest boundary
 * along it, as a sliver does; other gaps stay, to be refused (or taken as enclaves). Returns
 * the half-edges and the area each gap added to its face.
 */
export function fillSliverGaps(
  he: HalfEdges, xs: Float64Array, ys: Float64Array, width: number, boxes: readonly [number, number, number, number][],
): { he: HalfEdges; gaps: { face: number; area2: number }[] } {
  const gaps: { face: number; area2: number }[] = [];
  if (boxes.length === 0) return { he, gaps };
  let faces: Int32Array | null = null;
  for (const c of outsideCycles(he, xs, ys)) {
    if (!(c.area2 > 0)) continue;
    const [x0, y0, x1, y1] = c.bbox;
    if (!boxes.some((b) => b[0] <= x0 && b[1] <= y0 && b[2] >= x1 && b[3] >= y1)) continue;
    const byFace = new Map<number, number>();
    let perimeter = 0;
    for (const h of c.hs) {
      const len = Math.hypot(xs[he.to[h]!]! - xs[he.from[h]!]!, ys[he.to[h]!]! - ys[he.from[h]!]!);
      perimeter += len;
      const f = he.face[he.twin[h]!]!;
      if (f > 0) byFace.set(f, (byFace.get(f) ?? 0) + len);
    }
    const best = argMax(byFace);
    if (best < 0 || !(c.area2 / perimeter < width)) continue;
    faces ??= Int32Array.from(he.face);
    for (const h of c.hs) faces[h] = best;
    gaps.push({ face: best, area2: c.area2 });
  }
  return { he: faces ? withFaces(he, faces, xs, ys) : he, gaps };
}

/** True when ring r had an area in the input: the snapping, not the data, collapsed it (a sliver). */
export function hadArea(features: readonly InputFeature[], r: Ring): boolean {
  const raw = features[r.face - 1]?.polygons[r.part]?.[r.ring];
  return raw !== undefined && ringArea2Flat(raw) !== 0;
}

/**
 * Counts (or names) the parts narrower than the precision and the rings the snapping collapsed,
 * which are left out of the partition.
 */
export function noteLeftOut(narrow: readonly ThinPart[], collapsed: readonly Ring[], features: readonly InputFeature[], opts: SliverOptions, refusal: Refusal, repairs: TopologyRepairs): void {
  if (!opts.refuse) {
    repairs.slivers += narrow.length + collapsed.length;
    return;
  }
  const firstPoint = (face: number, part: number, ring: number): [number, number] => {
    const raw = features[face - 1]!.polygons[part]![ring]!;
    return [raw[0]!, raw[1]!];
  };
  for (const p of narrow) {
    refusal.note(
      'sliver',
      `has a part ${p.width.toPrecision(3)} wide (2 x area / perimeter), narrower than the precision ${opts.precision}, which the snapping cannot keep (without --refuse-slivers it is left out, and its neighbours meet)`,
      p.face, ...firstPoint(p.face, p.part, 0),
    );
  }
  for (const r of collapsed) {
    refusal.note(
      'sliver',
      `has a ${r.outer ? 'part' : 'hole'} that the snapping to the precision ${opts.precision} collapses (without --refuse-slivers it is left out, and its neighbours meet)`,
      r.face, ...firstPoint(r.face, r.part, r.ring),
    );
  }
}

/**
 * Dissolves the parts thinner than the sliver width into their neighbours: returns the
 * half-edges with the new faces (the boundaries inside a face gone) and sets each ring's face
 * to the one that now holds it. With `refuse`, names every sliver and changes nothing.
 * `he` is as buildHalfEdges made it from `rings` (ring after ring, in the same order).
 */
export function dissolveSlivers(he: HalfEdges, rings: Ring[], xs: Float64Array, ys: Float64Array, opts: SliverOptions, refusal: Refusal, repairs: TopologyRepairs): HalfEdges {
  const p = new Pieces(he, rings, xs, ys);
  // Thinness is 2 x area / perimeter: one pass over the vertices, no medial axis to compute,
  // and for the long thin strips noise makes it is their width (a compact shape gets about
  // half its diameter, so only a part that small anyway counts as a sliver).
  const thin: { piece: number; width: number }[] = [];
  for (let k = 0; k < p.count; k++) {
    const w = p.perimeter[k]! > 0 ? p.area2[k]! / p.perimeter[k]! : 0;
    if (w < opts.width) thin.push({ piece: k, width: w });
  }
  // The thinnest first: a sliver next to a thinner one takes it in before going itself.
  thin.sort((a, b) => a.width - b.width || a.piece - b.piece);
  let dissolved = 0;
  for (const { piece, width } of thin) {
    const target = p.neighbour(piece);
    // A part with no neighbour but the outside stays: there is nothing to dissolve it into.
    if (target < 0) continue;
    if (opts.refuse) {
      const [x, y] = p.firstPoint(piece);
      refusal.note(
        'sliver',
        `has a part ${width.toPrecision(3)} wide (2 x area / perimeter), under the sliver width ${opts.width.toPrecision(3)} (without --refuse-slivers it is dissolved into ${refusal.describe(p.face[target]!)})`,
        p.face[piece], x, y,
      );
      continue;
    }
    p.join(piece, target);
    dissolved++;
  }
  if (dissolved === 0) return he;
  repairs.slivers += dissolved;
  const faces = new Int32Array(he.count);
  for (let h = 0; h < he.count; h++) faces[h] = h < p.ringHalfEdges ? p.faceOfHalfEdge(h) : 0;
  rings.forEach((r, k) => {
    r.face = p.face[p.find(p.ringPiece[k]!)]!;
  });
  return withFaces(he, faces, xs, ys);
}

/** The parts of the faces (a polygon of a feature: its outer ring and holes), joined as slivers dissolve. */
class Pieces {
  count = 0;
  /** Per piece: its face, its twice-area and perimeter, and its rings (with the pieces joined into it). */
  readonly face: number[] = [];
  readonly area2: number[] = [];
  readonly perimeter: number[] = [];
  private readonly members: number[][] = [];
  private readonly root: number[] = [];
  readonly ringPiece: Int32Array;
  /** Half-edges [ringStart[k], ringStart[k + 1]) are ring k's segments. */
  private readonly ringStart: Int32Array;
  readonly ringHalfEdges: number;
  /** The piece of each of the rings' half-edges. */
  private readonly piece: Int32Array;

  constructor(private readonly he: HalfEdges, private readonly rings: Ring[], private readonly xs: Float64Array, private readonly ys: Float64Array) {
    this.ringPiece = new Int32Array(rings.length);
    this.ringStart = new Int32Array(rings.length + 1);
    const ids = new Map<string, number>();
    rings.forEach((r, k) => {
      const key = `${r.face}:${r.part}`;
      let id = ids.get(key);
      if (id === undefined) {
        ids.set(key, (id = this.count++));
        this.face.push(r.face);
        this.area2.push(0);
        this.perimeter.push(0);
        this.members.push([]);
        this.root.push(id);
      }
      this.ringPiece[k] = id;
      this.members[id]!.push(k);
      this.area2[id]! += ringArea2(r.ids, xs, ys);
      this.perimeter[id]! += ringLength(r.ids, xs, ys);
      this.ringStart[k + 1] = this.ringStart[k]! + r.ids.length;
    });
    this.ringHalfEdges = this.ringStart[rings.length]!;
    this.piece = new Int32Array(this.ringHalfEdges);
    for (let k = 0; k < rings.length; k++) this.piece.fill(this.ringPiece[k]!, this.ringStart[k], this.ringStart[k + 1]);
  }

  find(k: number): number {
    while (this.root[k] !== k) k = this.root[k] = this.root[this.root[k]!]!;
    return k;
  }

  faceOfHalfEdge(h: number): number {
    return this.face[this.find(this.piece[h]!)]!;
  }

  /**
   * The piece a sliver goes to: of the neighbouring faces (the outside not counted) the one
   * with the longest shared boundary, and of its pieces the one with the longest; the lower id
   * on a tie. -1: no neighbour.
   */
  neighbour(k: number): number {
    const byFace = new Map<number, number>();
    const byPiece = new Map<number, number>();
    const { he, xs, ys } = this;
    for (const ring of this.members[k]!) {
      for (let h = this.ringStart[ring]!; h < this.ringStart[ring + 1]!; h++) {
        const t = he.twin[h]!;
        if (t >= this.ringHalfEdges) continue; // the outside
        const q = this.find(this.piece[t]!);
        if (q === k) continue;
        const len = Math.hypot(xs[he.to[h]!]! - xs[he.from[h]!]!, ys[he.to[h]!]! - ys[he.from[h]!]!);
        const f = this.face[q]!;
        byFace.set(f, (byFace.get(f) ?? 0) + len);
        byPiece.set(q, (byPiece.get(q) ?? 0) + len);
      }
    }
    const best = argMax(byFace);
    if (best < 0) return -1;
    const ofBest = new Map([...byPiece].filter(([q]) => this.face[q] === best));
    return argMax(ofBest);
  }

  /** Piece k (a root) is dissolved into piece `into` (a root). */
  join(k: number, into: number): void {
    this.root[k] = into;
    for (const ring of this.members[k]!) this.members[into]!.push(ring);
    this.members[k] = [];
    this.area2[into]! += this.area2[k]!;
    this.perimeter[into]! += this.perimeter[k]!;
  }

  /** The first point of the piece's outer ring: where to find it on a map. */
  firstPoint(k: number): [number, number] {
    const r = this.rings[this.members[k]![0]!]!;
    return [this.xs[r.ids[0]!]!, this.ys[r.ids[0]!]!];
  }
}

/** The key with the highest value, the lowest key on a tie; -1 for none. */
function argMax(m: ReadonlyMap<number, number>): number {
  let best = -1, bestLen = -1;
  for (const [k, len] of m) {
    if (len > bestLen || (len === bestLen && k < best)) {
      best = k;
      bestLen = len;
    }
  }
  return best;
}
