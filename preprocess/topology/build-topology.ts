// Polygons with classes -> a planar partition: shared vertices, nodes, edges with a face on
// either side. Safe repairs are made and counted; anything that is not a partition is refused
// with the feature and the place named.
import KDBush from 'kdbush';
import Flatbush from 'flatbush';
import { PointHash } from '../geom/point-hash.js';
import { orient, segmentsIntersect } from '../geom/predicates.js';
import { ringArea2 } from '../geom/ring.js';
import { InputError, type FeatureRef } from '../io/errors.js';
import type { InputFeature } from '../io/read-input.js';

export interface TopoEdge {
  start: number;
  end: number;
  /** Face on the left going from start to end (0 = outside the domain). */
  left: number;
  right: number;
  verts: Int32Array;
}

export interface TopologyRepairs {
  closedRings: number;
  duplicatePoints: number;
  reorientedRings: number;
  tJunctions: number;
  snappedPoints: number;
  mergedPoints: number;
  spikes: number;
}

export interface Topology {
  xs: Float64Array;
  ys: Float64Array;
  vertexCount: number;
  edges: TopoEdge[];
  /** faceCount = features + 1; face f > 0 is input feature f - 1, face 0 is outside. */
  faceCount: number;
  /** Twice the area of each face (index 0 unused). */
  faceArea2: Float64Array;
  nodeCount: number;
  repairs: TopologyRepairs;
  /** Holes in the domain accepted with allowHoles: area and one point on each. */
  holes: { area: number; x: number; y: number }[];
}

export interface TopologyOptions {
  /** Coordinates are snapped to this grid and vertices this close to a segment are put on it (CRS units). */
  precision: number;
  file?: string;
  /**
   * Holes in the union of the faces are refused as gaps unless this is set: then they are
   * taken as outside the domain (an enclave of another territory) and listed in the result.
   */
  allowHoles?: boolean;
  /** Repairs already counted while reading. */
  inputRepairs?: { closedRings: number; duplicatePoints: number };
}

interface Ring {
  face: number;
  outer: boolean;
  ids: Int32Array;
}


export function buildTopology(features: InputFeature[], opts: TopologyOptions): Topology {
  const file = opts.file;
  const repairs: TopologyRepairs = {
    closedRings: opts.inputRepairs?.closedRings ?? 0,
    duplicatePoints: opts.inputRepairs?.duplicatePoints ?? 0,
    reorientedRings: 0,
    tJunctions: 0,
    snappedPoints: 0,
    mergedPoints: 0,
    spikes: 0,
  };
  const refOf = (face: number): FeatureRef => features[face - 1]!.ref;
  const fail = (msg: string, face: number | undefined, x?: number, y?: number): never => {
    throw new InputError(msg, {
      ...(file ? { file } : {}),
      ...(face !== undefined && face > 0 ? { feature: refOf(face) } : {}),
      ...(x !== undefined && y !== undefined ? { location: [x, y] as [number, number] } : {}),
    });
  };

  // 1. Snap to the precision grid and give every distinct point one id.
  let total = 0;
  for (const f of features) for (const p of f.polygons) for (const r of p) total += r.length >> 1;
  const hash = new PointHash(total);
  const p = opts.precision;
  // Grids of a power of ten round through the decimal text, so values already on the grid stay
  // bit-identical (181477.123 stays 181477.123, not 181477.12300000002).
  const decimals = p > 0 ? Math.round(-Math.log10(p)) : 0;
  const decimalGrid = p > 0 && decimals >= 0 && decimals <= 15 && Math.abs(10 ** -decimals - p) < p * 1e-9;
  const snap = (v: number): number => {
    if (p <= 0) return v;
    if (decimalGrid) return Number(v.toFixed(decimals));
    return Math.round(v / p) * p;
  };
  const rawRings: Ring[] = [];
  features.forEach((f, fi) => {
    const face = fi + 1;
    for (const poly of f.polygons) {
      poly.forEach((r, ri) => {
        const ids: number[] = [];
        for (let i = 0; i < r.length; i += 2) {
          const x = snap(r[i]!), y = snap(r[i + 1]!);
          if (x !== r[i] || y !== r[i + 1]) repairs.snappedPoints++;
          const id = hash.id(x, y);
          if (ids.length > 0 && ids[ids.length - 1] === id) {
            repairs.duplicatePoints++;
            continue;
          }
          ids.push(id);
        }
        while (ids.length > 1 && ids[0] === ids[ids.length - 1]) {
          ids.pop();
          repairs.duplicatePoints++;
        }
        rawRings.push({ face, outer: ri === 0, ids: Int32Array.from(ids) });
      });
    }
  });
  const nv = hash.size;
  const xs = hash.xs.subarray(0, nv), ys = hash.ys.subarray(0, nv);
  const index = new KDBush(nv, 64, Float64Array);
  for (let v = 0; v < nv; v++) index.add(xs[v]!, ys[v]!);
  index.finish();
  // Tolerances compare with a hair of slack so that neighbours exactly one grid step apart count.
  const tol = p * (1 + 1e-9);

  // 2. Points closer than the precision are one point (the first one met in the input).
  const alias = mergeNearPoints(rawRings, index, xs, ys, tol, repairs);

  // 3. T-junctions: a vertex lying on another ring's segment is inserted into that segment.
  const rings = insertTJunctions(rawRings, index, alias, xs, ys, tol, repairs);
  for (const r of rings) r.ids = cleanRing(r.ids, repairs);

  // 4. Ring sanity and orientation (outer counterclockwise, holes clockwise).
  for (const r of rings) {
    const distinct = new Set(r.ids).size;
    if (distinct < 3) {
      fail(`has a ${r.outer ? 'ring' : 'hole'} with fewer than 3 distinct points`, r.face, xs[r.ids[0]!], ys[r.ids[0]!]);
    }
    const a2 = ringArea2(r.ids, xs, ys);
    if (a2 === 0) fail(`has a ${r.outer ? 'ring' : 'hole'} of zero area`, r.face, xs[r.ids[0]!], ys[r.ids[0]!]);
    if ((a2 > 0) !== r.outer) {
      r.ids.reverse();
      repairs.reorientedRings++;
    }
  }

  // 5. Half-edges, each with its face on the left, and their twins.
  const he = buildHalfEdges(rings, nv);
  const { from, to, face } = he;
  const nh0 = he.count;
  const out = outgoing(from, nv, nh0);
  const twin = new Int32Array(nh0 * 2).fill(-1);
  for (let h = 0; h < nh0; h++) {
    const u = from[h]!, v = to[h]!;
    for (let k = out.start[u]!; k < out.start[u + 1]!; k++) {
      const g = out.list[k]!;
      if (g !== h && to[g] === v) {
        const mx = (xs[u]! + xs[v]!) / 2, my = (ys[u]! + ys[v]!) / 2;
        if (face[g] === face[h]) fail('has a boundary segment twice in the same direction (a repeated ring or part)', face[h], mx, my);
        throw new InputError(
          `overlaps ${describeFace(refOf(face[g]!))}: both lie on the same side of the segment`,
          { ...(file ? { file } : {}), feature: refOf(face[h]!), location: [mx, my] },
        );
      }
    }
    for (let k = out.start[v]!; k < out.start[v + 1]!; k++) {
      const g = out.list[k]!;
      if (to[g] === u) {
        if (face[g] === face[h]) {
          fail('touches itself along a segment (a ring or hole that is not a simple boundary)', face[h], (xs[u]! + xs[v]!) / 2, (ys[u]! + ys[v]!) / 2);
        }
        twin[h] = g;
        break;
      }
    }
  }
  // Unmatched half-edges border the outside: give each a twin with face 0.
  let nh = nh0;
  const fromAll = new Int32Array(nh0 * 2), toAll = new Int32Array(nh0 * 2), faceAll = new Int32Array(nh0 * 2);
  fromAll.set(from);
  toAll.set(to);
  faceAll.set(face);
  for (let h = 0; h < nh0; h++) {
    if (twin[h]! >= 0) continue;
    fromAll[nh] = to[h]!;
    toAll[nh] = from[h]!;
    faceAll[nh] = 0;
    twin[h] = nh;
    twin[nh] = h;
    nh++;
  }

  // 6. No two segments may cross or touch except at shared vertices.
  checkCrossings(fromAll, toAll, faceAll, twin, nh, xs, ys, fail, refOf, file);

  // 7. The outside's boundary: a hole in the union is a gap, a part inside another an overlap.
  const outAll = outgoing(fromAll, nv, nh);
  sortByAngle(outAll, fromAll, toAll, xs, ys);
  const holes = checkOutside(fromAll, toAll, faceAll, twin, nh, outAll, xs, ys, fail, refOf, file, opts.allowHoles ?? false);

  // 8. Nodes are where other than two segments meet; edges are the chains between them.
  const degree = new Int32Array(nv);
  for (let h = 0; h < nh; h++) degree[fromAll[h]!]!++;
  const isNode = new Uint8Array(nv);
  let nodeCount = 0;
  for (let v = 0; v < nv; v++) {
    if (degree[v]! > 0 && degree[v] !== 2) {
      isNode[v] = 1;
      nodeCount++;
    }
  }
  const edges: TopoEdge[] = [];
  const visited = new Uint8Array(nh);
  const nextAlong = (h: number): number => {
    // At a vertex of degree 2 the chain continues on the outgoing half-edge that is not the way back.
    const v = toAll[h]!;
    const s = outAll.start[v]!;
    const g = outAll.list[s]!;
    return g === twin[h] ? outAll.list[s + 1]! : g;
  };
  const trace = (h0: number): void => {
    const verts: number[] = [fromAll[h0]!];
    let h = h0;
    for (;;) {
      visited[h] = 1;
      visited[twin[h]!] = 1;
      const v = toAll[h]!;
      verts.push(v);
      if (isNode[v] || v === fromAll[h0]) break;
      h = nextAlong(h);
    }
    edges.push({ start: verts[0]!, end: verts[verts.length - 1]!, left: faceAll[h0]!, right: faceAll[twin[h0]!]!, verts: Int32Array.from(verts) });
  };
  for (let h = 0; h < nh; h++) if (!visited[h] && isNode[fromAll[h]!]) trace(h);
  // Rings without any node (an island, or a face inside one other face): one loop edge each,
  // starting at its first vertex, which becomes a node.
  for (let h = 0; h < nh; h++) {
    if (visited[h]) continue;
    isNode[fromAll[h]!] = 1;
    nodeCount++;
    trace(faceAll[h] === 0 ? twin[h]! : h);
  }

  const faceCount = features.length + 1;
  const faceArea2 = new Float64Array(faceCount);
  for (const r of rings) faceArea2[r.face]! += ringArea2(r.ids, xs, ys);

  // Points that no edge uses (a removed spike's tip, a point merged into a nearer one) are
  // dropped: kept, they were counted as vertices and widened the extent of the output. Ids
  // keep their order, so input without such points keeps the same numbering.
  const used = new Uint8Array(nv);
  for (const e of edges) for (const v of e.verts) used[v] = 1;
  const newId = new Int32Array(nv);
  let kept = 0;
  for (let v = 0; v < nv; v++) newId[v] = used[v] ? kept++ : -1;
  const keptXs = new Float64Array(kept), keptYs = new Float64Array(kept);
  for (let v = 0; v < nv; v++) {
    if (newId[v]! < 0) continue;
    keptXs[newId[v]!] = xs[v]!;
    keptYs[newId[v]!] = ys[v]!;
  }
  if (kept < nv) {
    for (const e of edges) {
      e.start = newId[e.start]!;
      e.end = newId[e.end]!;
      for (let i = 0; i < e.verts.length; i++) e.verts[i] = newId[e.verts[i]!]!;
    }
  }
  return { xs: keptXs, ys: keptYs, vertexCount: kept, edges, faceCount, faceArea2, nodeCount, repairs, holes };
}

function describeFace(ref: FeatureRef): string {
  return ref.id === null ? `feature #${ref.index}` : `feature #${ref.index} (id ${JSON.stringify(ref.id)})`;
}

/** Inserts every vertex that lies on a segment (within the precision) into that segment. */
function insertTJunctions(rings: Ring[], index: KDBush, alias: Int32Array, xs: Float64Array, ys: Float64Array, tol: number, repairs: TopologyRepairs): Ring[] {
  const tol2 = tol * tol;
  const out: Ring[] = [];
  for (const r of rings) {
    const ids = r.ids;
    const n = ids.length;
    let result: number[] | null = null;
    for (let i = 0; i < n; i++) {
      const a = ids[i]!, b = ids[(i + 1) % n]!;
      const ax = xs[a]!, ay = ys[a]!, bx = xs[b]!, by = ys[b]!;
      const found = index.range(Math.min(ax, bx) - tol, Math.min(ay, by) - tol, Math.max(ax, bx) + tol, Math.max(ay, by) + tol);
      let inserts: { v: number; t: number }[] | null = null;
      if (found.length > 2) {
        const dx = bx - ax, dy = by - ay;
        const len2 = dx * dx + dy * dy;
        for (const v of found) {
          if (v === a || v === b || alias[v] !== v) continue;
          const px = xs[v]! - ax, py = ys[v]! - ay;
          const t = (px * dx + py * dy) / len2;
          if (t <= 0 || t >= 1) continue;
          // Within the precision of an end point it is that end point (merged before), not a T.
          if (px * px + py * py <= tol2) continue;
          const qx = xs[v]! - bx, qy = ys[v]! - by;
          if (qx * qx + qy * qy <= tol2) continue;
          const o = orient(ax, ay, bx, by, xs[v]!, ys[v]!);
          if (o !== 0) {
            // o is twice the triangle area: distance to the line is o / |ab|.
            if (tol === 0 || (o * o) / len2 > tol2) continue;
          }
          (inserts ??= []).push({ v, t });
        }
      }
      if (inserts) {
        if (!result) result = Array.from(ids.subarray(0, i + 1));
        inserts.sort((p, q) => p.t - q.t || p.v - q.v);
        for (const ins of inserts) result.push(ins.v);
        repairs.tJunctions += inserts.length;
        if (i + 1 < n) result.push(b);
      } else if (result && i + 1 < n) {
        result.push(b);
      }
    }
    out.push(result ? { face: r.face, outer: r.outer, ids: Int32Array.from(result) } : r);
  }
  return out;
}

/** Union of points within `tol` of each other, each replaced by the lowest id of its group. */
function mergeNearPoints(rings: Ring[], index: KDBush, xs: Float64Array, ys: Float64Array, tol: number, repairs: TopologyRepairs): Int32Array {
  const nv = xs.length;
  const alias = new Int32Array(nv);
  for (let v = 0; v < nv; v++) alias[v] = v;
  if (tol <= 0) return alias;
  const find = (v: number): number => {
    while (alias[v] !== v) {
      alias[v] = alias[alias[v]!]!;
      v = alias[v]!;
    }
    return v;
  };
  let merged = false;
  for (let v = 0; v < nv; v++) {
    for (const w of index.within(xs[v]!, ys[v]!, tol)) {
      if (w === v) continue;
      const a = find(v), b = find(w);
      if (a === b) continue;
      if (a < b) alias[b] = a;
      else alias[a] = b;
      merged = true;
    }
  }
  if (!merged) return alias;
  for (let v = 0; v < nv; v++) alias[v] = find(v);
  for (const r of rings) {
    for (let i = 0; i < r.ids.length; i++) {
      const v = r.ids[i]!;
      if (alias[v] !== v) {
        r.ids[i] = alias[v]!;
        repairs.mergedPoints++;
      }
    }
  }
  return alias;
}

/** Drops repeated points and zero-width spikes (a, b, a) that merging can leave in a ring. */
function cleanRing(ids: Int32Array, repairs: TopologyRepairs): Int32Array {
  const out: number[] = [];
  let changed = false;
  for (const v of ids) {
    if (out.length > 0 && out[out.length - 1] === v) {
      repairs.duplicatePoints++;
      changed = true;
      continue;
    }
    if (out.length >= 2 && out[out.length - 2] === v) {
      out.pop();
      repairs.spikes++;
      changed = true;
      continue;
    }
    out.push(v);
  }
  // The same across the ring's closing point.
  for (;;) {
    const n = out.length;
    if (n >= 2 && out[0] === out[n - 1]) {
      out.pop();
      repairs.duplicatePoints++;
      changed = true;
    } else if (n >= 3 && out[1] === out[n - 1]) {
      out.shift();
      out.pop();
      repairs.spikes++;
      changed = true;
    } else if (n >= 3 && out[0] === out[n - 2]) {
      out.pop();
      out.pop();
      repairs.spikes++;
      changed = true;
    } else break;
  }
  return changed ? Int32Array.from(out) : ids;
}

function buildHalfEdges(rings: Ring[], _nv: number): { from: Int32Array; to: Int32Array; face: Int32Array; count: number } {
  let n = 0;
  for (const r of rings) n += r.ids.length;
  const from = new Int32Array(n), to = new Int32Array(n), face = new Int32Array(n);
  let h = 0;
  for (const r of rings) {
    const m = r.ids.length;
    for (let i = 0; i < m; i++) {
      from[h] = r.ids[i]!;
      to[h] = r.ids[(i + 1) % m]!;
      face[h] = r.face;
      h++;
    }
  }
  return { from, to, face, count: n };
}

interface Outgoing {
  start: Int32Array;
  list: Int32Array;
}

/** Half-edges grouped by their start vertex (compressed rows). */
function outgoing(from: Int32Array, nv: number, nh: number): Outgoing {
  const start = new Int32Array(nv + 1);
  for (let h = 0; h < nh; h++) start[from[h]! + 1]!++;
  for (let v = 0; v < nv; v++) start[v + 1]! += start[v]!;
  const fill = start.slice(0, nv);
  const list = new Int32Array(nh);
  for (let h = 0; h < nh; h++) list[fill[from[h]!]!++] = h;
  return { start, list };
}

/** Sorts each vertex's outgoing half-edges counterclockwise by direction. */
function sortByAngle(out: Outgoing, from: Int32Array, to: Int32Array, xs: Float64Array, ys: Float64Array): void {
  const nv = out.start.length - 1;
  for (let v = 0; v < nv; v++) {
    const s = out.start[v]!, e = out.start[v + 1]!;
    if (e - s <= 2) continue; // two directions are in order either way for our use
    const hs = Array.from(out.list.subarray(s, e));
    const ang = (h: number): number => Math.atan2(ys[to[h]!]! - ys[from[h]!]!, xs[to[h]!]! - xs[from[h]!]!);
    hs.sort((a, b) => ang(a) - ang(b));
    out.list.set(hs, s);
  }
}

/** The next half-edge around the face on the left of h: clockwise-next after h's twin at h's end. */
function nextInFace(h: number, twin: Int32Array, to: Int32Array, out: Outgoing): number {
  const v = to[h]!;
  const s = out.start[v]!, e = out.start[v + 1]!;
  const t = twin[h]!;
  for (let k = s; k < e; k++) {
    if (out.list[k] === t) return out.list[k === s ? e - 1 : k - 1]!;
  }
  throw new Error('half-edge structure is inconsistent');
}

function checkCrossings(
  from: Int32Array, to: Int32Array, face: Int32Array, twin: Int32Array, nh: number,
  xs: Float64Array, ys: Float64Array,
  fail: (msg: string, face: number | undefined, x?: number, y?: number) => never,
  refOf: (face: number) => FeatureRef, file: string | undefined,
): void {
  const segs: number[] = [];
  for (let h = 0; h < nh; h++) if (h < twin[h]!) segs.push(h);
  if (segs.length === 0) return;
  const index = new Flatbush(segs.length);
  for (const h of segs) {
    const a = from[h]!, b = to[h]!;
    index.add(Math.min(xs[a]!, xs[b]!), Math.min(ys[a]!, ys[b]!), Math.max(xs[a]!, xs[b]!), Math.max(ys[a]!, ys[b]!));
  }
  index.finish();
  const hits: number[] = [];
  for (let i = 0; i < segs.length; i++) {
    const h = segs[i]!;
    const a = from[h]!, b = to[h]!;
    hits.length = 0;
    index.search(Math.min(xs[a]!, xs[b]!), Math.min(ys[a]!, ys[b]!), Math.max(xs[a]!, xs[b]!), Math.max(ys[a]!, ys[b]!), (j) => {
      if (j > i) hits.push(j);
      return false;
    });
    for (const j of hits) {
      const g = segs[j]!;
      const c = from[g]!, d = to[g]!;
      let bad: boolean;
      if (a === c || a === d || b === c || b === d) {
        // Sharing one vertex is fine unless the two run along each other.
        const shared = a === c || a === d ? a : b;
        const p = shared === a ? b : a, q = shared === c ? d : c;
        bad = p === q || (orient(xs[shared]!, ys[shared]!, xs[p]!, ys[p]!, xs[q]!, ys[q]!) === 0 &&
          (xs[p]! - xs[shared]!) * (xs[q]! - xs[shared]!) + (ys[p]! - ys[shared]!) * (ys[q]! - ys[shared]!) > 0);
      } else {
        bad = segmentsIntersect(xs[a]!, ys[a]!, xs[b]!, ys[b]!, xs[c]!, ys[c]!, xs[d]!, ys[d]!);
      }
      if (!bad) continue;
      const [ix, iy] = crossingPoint(xs[a]!, ys[a]!, xs[b]!, ys[b]!, xs[c]!, ys[c]!, xs[d]!, ys[d]!);
      const f1 = face[h] || face[twin[h]!]!, f2 = face[g] || face[twin[g]!]!;
      const faces1 = [face[h]!, face[twin[h]!]!].filter((f) => f > 0);
      const faces2 = [face[g]!, face[twin[g]!]!].filter((f) => f > 0);
      if (faces1.some((f) => faces2.includes(f)) && faces1.length + faces2.length <= 2) {
        fail('is self-intersecting: its boundary crosses itself', f1, ix, iy);
      }
      const other = faces2.find((f) => !faces1.includes(f)) ?? f2;
      throw new InputError(
        f1 === other
          ? 'is self-intersecting: its boundary crosses itself'
          : `crosses ${describeFace(refOf(other))} (self-intersection or overlap)`,
        { ...(file ? { file } : {}), feature: refOf(f1), location: [ix, iy] },
      );
    }
  }
}

function crossingPoint(ax: number, ay: number, bx: number, by: number, cx: number, cy: number, dx: number, dy: number): [number, number] {
  const den = (bx - ax) * (dy - cy) - (by - ay) * (dx - cx);
  if (den === 0) return [(ax + bx) / 2, (ay + by) / 2];
  const t = ((cx - ax) * (dy - cy) - (cy - ay) * (dx - cx)) / den;
  const tc = Math.max(0, Math.min(1, t));
  return [ax + tc * (bx - ax), ay + tc * (by - ay)];
}

function checkOutside(
  from: Int32Array, to: Int32Array, face: Int32Array, twin: Int32Array, nh: number, out: Outgoing,
  xs: Float64Array, ys: Float64Array,
  fail: (msg: string, face: number | undefined, x?: number, y?: number) => never,
  refOf: (face: number) => FeatureRef, file: string | undefined, allowHoles: boolean,
): { area: number; x: number; y: number }[] {
  const holes: { area: number; x: number; y: number }[] = [];
  const seen = new Uint8Array(nh);
  const cycles: { hs: number[]; area2: number; bbox: [number, number, number, number] }[] = [];
  for (let h0 = 0; h0 < nh; h0++) {
    if (face[h0] !== 0 || seen[h0]) continue;
    const hs: number[] = [];
    let h = h0;
    let guard = 0;
    do {
      seen[h] = 1;
      hs.push(h);
      h = nextInFace(h, twin, to, out);
      if (++guard > nh) throw new Error('outside boundary does not close');
    } while (h !== h0);
    const ids = hs.map((g) => from[g]!);
    let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
    for (const v of ids) {
      x0 = Math.min(x0, xs[v]!); y0 = Math.min(y0, ys[v]!);
      x1 = Math.max(x1, xs[v]!); y1 = Math.max(y1, ys[v]!);
    }
    cycles.push({ hs, area2: ringArea2(ids, xs, ys), bbox: [x0, y0, x1, y1] });
  }
  for (const c of cycles) {
    if (c.area2 > 0) {
      // The outside on the left going counterclockwise: a hole in the union of all faces.
      const h = c.hs[0]!;
      if (allowHoles) {
        holes.push({ area: c.area2 / 2, x: xs[from[h]!]!, y: ys[from[h]!]! });
        continue;
      }
      const inner = face[twin[h]!]!;
      const [x0, y0, x1, y1] = c.bbox;
      fail(
        `borders a gap inside the domain (an area no feature covers, ${(c.area2 / 2).toPrecision(4)} square units, bounding box ${[x0, y0, x1, y1].map((v) => Math.round(v * 1000) / 1000).join(', ')}); if it is outside the domain on purpose (an enclave), allow holes (--allow-holes, or "allowHoles": true in the style)`,
        inner, xs[from[h]!], ys[from[h]!],
      );
    }
  }
  // A point just outside the faces along any outside boundary must be outside every other
  // boundary too (counting holes): otherwise a component lies inside another one's area.
  if (cycles.length > 1) {
    for (const c of cycles) {
      const h = c.hs[0]!;
      const a = from[h]!, b = to[h]!;
      const mx = (xs[a]! + xs[b]!) / 2, my = (ys[a]! + ys[b]!) / 2;
      // Left of the half-edge lies the outside: inside c itself only when c is a hole.
      let w = c.area2 > 0 ? 1 : 0;
      for (const d of cycles) {
        if (d === c) continue;
        const [x0, y0, x1, y1] = d.bbox;
        if (mx < x0 || mx > x1 || my < y0 || my > y1) continue;
        w += windingAround(d.hs, from, xs, ys, mx, my);
      }
      if (w !== 0) {
        throw new InputError(
          'lies inside the area of other features without a hole for it (overlap)',
          { ...(file ? { file } : {}), feature: refOf(face[twin[h]!]!), location: [mx, my] },
        );
      }
    }
  }
  return holes;
}

function windingAround(hs: number[], from: Int32Array, xs: Float64Array, ys: Float64Array, px: number, py: number): number {
  let w = 0;
  const n = hs.length;
  for (let i = 0; i < n; i++) {
    const a = from[hs[i]!]!, b = from[hs[(i + 1) % n]!]!;
    const ay = ys[a]!, by = ys[b]!;
    if (ay <= py) {
      if (by > py && orient(xs[a]!, ay, xs[b]!, by, px, py) > 0) w++;
    } else if (by <= py && orient(xs[a]!, ay, xs[b]!, by, px, py) < 0) {
      w--;
    }
  }
  return w;
}
