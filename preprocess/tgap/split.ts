// Splitting a face of a linear class (a road, a watercourse) among its neighbours along its
// length: the face is triangulated (constrained Delaunay), every triangle is cut into fan
// pieces around its centroid and the midpoints of its inner edges, and each piece goes to the
// neighbour it touches. The cuts through midpoints follow the face's centre line, so each
// neighbour takes the half of the road on its side. Runs of triangles along the road are cut
// as one where the centre line is nearly straight: fewer pieces, which every later surface
// over the road's area inherits.
import { snapNewVertices } from '../geom/snap-new-vertices.js';
import { triangulateRegion } from '../geom/cdt.js';
import { orient } from '../geom/predicates.js';
import { pointSegmentDistance } from '../../format/point-segment.js';
import { LocalVertices } from '../geom/local-vertices.js';
import type { PlanarState } from './planar-state.js';
import { EMPTY_I32, EMPTY_U8 } from './planar-state.js';
import { dissolveNodes } from './dissolve-node.js';

export interface SplitResult {
  /** Twice the area each receiving face gets. */
  gains: Map<number, number>;
  /** The loser's area as triangles (3 vertex ids each) and the face each goes to. */
  tris: Int32Array;
  triFaces: Int32Array;
  /** Ids of the edges made for the new boundaries. */
  newEdges: number[];
  /** Nodes whose edges changed (to dissolve where only two edges remain). */
  touchedNodes: number[];
}

interface Seg {
  a: number; // local vertex
  b: number;
  label: number; // face across (0 = outside)
}

/**
 * Splits face L among its neighbours. Returns null, changing nothing, when the face cannot be
 * triangulated (the caller then merges it whole). The midpoints and centres it makes go onto the
 * grid of `snapStep` (0: none) where their triangles stay counterclockwise (snap-new-vertices.ts).
 */
export function splitFace(st: PlanarState, L: number, snapStep = 0): SplitResult | null {
  const edgeSet = st.faceEdges[L];
  if (!edgeSet || edgeSet.size === 0) return null;
  const edgesOfL = [...edgeSet].sort((p, q) => p - q);
  const lv = new LocalVertices();
  const loc = (v: number): number => lv.of(v);
  const ids = lv.ids;
  const segs: Seg[] = [];
  const shared = new Map<number, number>();
  for (const e of edgesOfL) {
    const [l, r] = st.sides(e);
    const verts = st.edges[e]!.verts;
    const forward = l === L;
    const label = forward ? r : l;
    shared.set(label, (shared.get(label) ?? 0) + st.edgeLength[e]!);
    for (let i = 0; i + 1 < verts.length; i++) {
      const a = verts[i]!, b = verts[i + 1]!;
      segs.push(forward ? { a: loc(a), b: loc(b), label } : { a: loc(b), b: loc(a), label });
    }
  }
  const nl = ids.length;
  if (nl < 3) return null;
  const coords = lv.coords(st.xs, st.ys);

  // Constrained Delaunay triangulation of the face's vertices with its boundary as constraints.
  const segPairs = new Int32Array(segs.length * 2);
  segs.forEach((sg, i) => {
    segPairs[2 * i] = sg.a;
    segPairs[2 * i + 1] = sg.b;
  });
  const cdt = triangulateRegion(coords, segPairs);
  if (!cdt) return null;
  const tri = cdt.triangles;
  const nt = tri.length / 3;

  // Labels: a boundary segment goes to the face across it; a vertex to one of its segments'
  // faces (the one sharing the longest boundary with L), outside excluded.
  const segLabel = new Map<number, number>(); // key a * nl + b
  const vlabel = new Int32Array(nl).fill(-1);
  const better = (p: number, q: number): boolean => {
    const sp = shared.get(p) ?? 0, sq = shared.get(q) ?? 0;
    return sp > sq || (sp === sq && p < q);
  };
  for (const s of segs) {
    segLabel.set(s.a * nl + s.b, s.label);
    if (s.label === 0) continue;
    for (const v of [s.a, s.b]) {
      if (vlabel[v]! < 0 || better(s.label, vlabel[v]!)) vlabel[v] = s.label;
    }
  }
  // Vertices with only the outside around them take the label of the nearest labelled vertex
  // along the triangulation (breadth first, in a fixed order).
  {
    const queue: number[] = [];
    for (let v = 0; v < nl; v++) if (vlabel[v]! >= 0) queue.push(v);
    if (queue.length === 0) return null;
    const adj: number[][] = Array.from({ length: nl }, () => []);
    for (let t = 0; t < nt; t++) {
      for (let k = 0; k < 3; k++) {
        const a = tri[3 * t + k]!, b = tri[3 * t + ((k + 1) % 3)]!;
        adj[a]!.push(b);
      }
    }
    for (let qi = 0; qi < queue.length; qi++) {
      const v = queue[qi]!;
      for (const w of adj[v]!.sort((p, q) => p - q)) {
        if (vlabel[w]! < 0) {
          vlabel[w] = vlabel[v]!;
          queue.push(w);
        }
      }
    }
    for (let v = 0; v < nl; v++) if (vlabel[v]! < 0) return null;
  }

  // Fan pieces. A diagonal (inner edge) gets a midpoint when its ends go to different faces;
  // a triangle gets its centroid when its pieces go to more than one face. A ring lists a
  // triangle's corners (local ids) and the midpoints on its sides (-1 - diagonal key), with
  // the face of the piece from each entry to the next.
  const rings: { v: number[]; labels: number[] }[] = [];
  for (let t = 0; t < nt; t++) {
    const p = [tri[3 * t]!, tri[3 * t + 1]!, tri[3 * t + 2]!];
    const v: number[] = [], labels: number[] = [];
    for (let k = 0; k < 3; k++) {
      const a = p[k]!, b = p[(k + 1) % 3]!;
      const sl = segLabel.get(a * nl + b);
      v.push(a);
      if (sl !== undefined) {
        labels.push(sl !== 0 ? sl : vlabel[a]!);
      } else if (vlabel[a] === vlabel[b]) {
        labels.push(vlabel[a]!);
      } else {
        v.push(-1 - (Math.min(a, b) * nl + Math.max(a, b)));
        labels.push(vlabel[a]!, vlabel[b]!);
      }
    }
    rings.push({ v, labels });
  }
  const changesOf = (labels: number[]): number[] => {
    const m = labels.length, out: number[] = [];
    for (let i = 0; i < m; i++) if (labels[i] !== labels[(i + m - 1) % m]) out.push(i);
    return out;
  };
  // A straight cut: two changes of face, each side at least two pieces of ring.
  const straightCut = (labels: number[]): [number, number] | null => {
    const c = changesOf(labels), m = labels.length;
    return c.length === 2 && c[1]! - c[0]! >= 2 && m - (c[1]! - c[0]!) >= 2 ? [c[0]!, c[1]!] : null;
  };
  /** The two local vertices of the diagonal whose midpoint ring entry r (< 0) names. */
  const diagonalEnds = (r: number): [number, number] => [Math.floor((-1 - r) / nl), (-1 - r) % nl];
  const px = (r: number): number => (r >= 0 ? coords[2 * r]! : diagonalEnds(r).reduce((sum, e) => sum + coords[2 * e]!, 0) / 2);
  const py = (r: number): number => (r >= 0 ? coords[2 * r + 1]! : diagonalEnds(r).reduce((sum, e) => sum + coords[2 * e + 1]!, 0) / 2);
  /** The fans of a straight cut from i1 to i2: pieces [apex, ring k, ring k + 1] with their face. */
  const cutFans = (v: number[], labels: number[], [i1, i2]: [number, number]): [number, number, number, number][] => {
    const m = v.length, out: [number, number, number, number][] = [];
    for (let k = i1 + 1; k < i2; k++) out.push([v[i1]!, v[k]!, v[k + 1]!, labels[i1]!]);
    for (let k = i2 + 1; k < i1 + m; k++) out.push([v[i2]!, v[k % m]!, v[(k + 1) % m]!, labels[i2]!]);
    return out;
  };
  // Neighbouring triangles cut straight through the midpoints of their common diagonals are cut
  // as one, from the first change of face to the last, while every piece of the fans stays
  // counterclockwise and every midpoint skipped lies within a quarter of the road's width there
  // of the cut (so the cut stays in the middle half of the road): the centre line skips those
  // midpoints, and k triangles make k + 2 pieces instead of 3k.
  const sharing = new Map<number, number[]>(); // diagonal key -> triangles cut through its midpoint
  const cuts = rings.map((r) => straightCut(r.labels));
  rings.forEach((r, t) => {
    if (!cuts[t]) return;
    for (const e of r.v) if (e < 0) (sharing.get(e) ?? (sharing.set(e, []), sharing.get(e)!)).push(t);
  });
  /** Ring r1 and ring r2 joined through the midpoint `key` that both hold. */
  const joinRings = (r1: { v: number[]; labels: number[] }, r2: { v: number[]; labels: number[] }, key: number): { v: number[]; labels: number[] } => {
    const m1 = r1.v.length, m2 = r2.v.length, j1 = r1.v.indexOf(key), j2 = r2.v.indexOf(key);
    const v: number[] = [], labels: number[] = [];
    for (let k = 1; k < m1; k++) {
      v.push(r1.v[(j1 + k) % m1]!);
      labels.push(k < m1 - 1 ? r1.labels[(j1 + k) % m1]! : r2.labels[(j2 + 1) % m2]!);
    }
    for (let k = 2; k < m2 - 1; k++) {
      v.push(r2.v[(j2 + k) % m2]!);
      labels.push(r2.labels[(j2 + k) % m2]!);
    }
    return { v, labels };
  };
  // The road's half width at a midpoint: its distance to the boundary next to its diagonal's ends.
  const boundaryAt: number[][] = Array.from({ length: nl }, () => []);
  segs.forEach((sg, i) => { boundaryAt[sg.a]!.push(i); boundaryAt[sg.b]!.push(i); });
  const halfWidth = (key: number): number => {
    let d = Infinity;
    for (const end of diagonalEnds(key)) {
      for (const i of boundaryAt[end]!) {
        const sg = segs[i]!;
        d = Math.min(d, pointSegmentDistance(px(key), py(key), px(sg.a), py(sg.a), px(sg.b), py(sg.b)));
      }
    }
    return d;
  };
  const inMiddle = (key: number, a: number, b: number): boolean =>
    pointSegmentDistance(px(key), py(key), px(a), py(a), px(b), py(b)) <= halfWidth(key) / 2;
  const joinedTo = new Int32Array(nt).fill(-1); // the first triangle of the group a triangle is cut with
  const joined = new Map<number, { v: number[]; labels: number[]; cut: [number, number] }>();
  for (let t = 0; t < nt; t++) {
    if (!cuts[t] || joinedTo[t]! >= 0) continue;
    let ring = rings[t]!;
    let cut = cuts[t]!;
    const members = [t], skipped: number[] = [];
    for (let grown = true; grown;) {
      grown = false;
      for (const key of ring.v) {
        if (key >= 0) continue;
        const u = sharing.get(key)!.find((w) => !members.includes(w));
        if (u === undefined || joinedTo[u]! >= 0) continue;
        const next = joinRings(ring, rings[u]!, key);
        const c = straightCut(next.labels);
        if (!c) continue;
        const a = next.v[c[0]]!, b = next.v[c[1]]!;
        if (![...skipped, key].every((k) => inMiddle(k, a, b))) continue;
        if (!cutFans(next.v, next.labels, c).every(([p, q, r]) => orient(px(p), py(p), px(q), py(q), px(r), py(r)) > 0)) continue;
        ring = next;
        cut = c;
        members.push(u);
        skipped.push(key);
        grown = true;
        break;
      }
    }
    if (members.length === 1) continue;
    for (const u of members) joinedTo[u] = t;
    joined.set(t, { ...ring, cut });
  }

  const outTris: number[] = [];
  const outFaces: number[] = [];
  const mid = new Map<number, number>(); // diagonal key -> global vertex
  const newSegs: { a: number; b: number; left: number; right: number }[] = []; // global vertex ids
  const gx = (v: number): number => st.xs[v]!, gy = (v: number): number => st.ys[v]!;
  const firstNew = st.size;
  const global = (r: number): number => {
    if (r >= 0) return ids[r]!;
    let m = mid.get(r);
    if (m === undefined) {
      const [a, b] = diagonalEnds(r).map((e) => ids[e]!) as [number, number];
      m = st.addVertex((gx(a) + gx(b)) / 2, (gy(a) + gy(b)) / 2);
      mid.set(r, m);
    }
    return m;
  };
  const emit = (a: number, b: number, c: number, face: number): void => {
    outTris.push(a, b, c);
    outFaces.push(face);
  };
  for (let t = 0; t < nt; t++) {
    const one = joined.get(t);
    if (!one && joinedTo[t]! >= 0) continue; // cut with the group it was joined to
    const { v, labels } = one ?? rings[t]!;
    const ring = v.map(global);
    if (labels.every((l) => l === labels[0])) {
      emit(ring[0]!, ring[1]!, ring[2]!, labels[0]!);
      continue;
    }
    // Two faces meeting in this triangle: cut it straight from one change of face to the other
    // (midpoint to midpoint along a road, which follows its centre line).
    const cut = one?.cut ?? cuts[t];
    if (cut) {
      for (const [a, b, c, face] of cutFans(ring, labels, cut)) emit(a, b, c, face);
      newSegs.push({ a: ring[cut[1]]!, b: ring[cut[0]]!, left: labels[cut[0]]!, right: labels[cut[1]]! });
      continue;
    }
    const p = rings[t]!.v.filter((r) => r >= 0).map((r) => ids[r]!);
    const cx = (gx(p[0]!) + gx(p[1]!) + gx(p[2]!)) / 3;
    const cy = (gy(p[0]!) + gy(p[1]!) + gy(p[2]!)) / 3;
    const cen = st.addVertex(cx, cy);
    const m = ring.length;
    for (let i = 0; i < m; i++) {
      emit(cen, ring[i]!, ring[(i + 1) % m]!, labels[i]!);
      // Spoke cen -> ring[i]: piece i on its left, piece i - 1 on its right.
      const before = labels[(i + m - 1) % m]!, after = labels[i]!;
      if (before !== after) newSegs.push({ a: cen, b: ring[i]!, left: after, right: before });
    }
  }
  snapNewVertices(outTris, st.xs, st.ys, firstNew, st.size, snapStep);
  // Each receiver's gain of area, from the triangles as they finally lie.
  const gains = new Map<number, number>();
  for (let t = 0; t < outFaces.length; t++) {
    const a = outTris[3 * t]!, b = outTris[3 * t + 1]!, c = outTris[3 * t + 2]!;
    const ax = gx(a), ay = gy(a);
    const a2 = (gx(b) - ax) * (gy(c) - ay) - (gx(c) - ax) * (gy(b) - ay);
    gains.set(outFaces[t]!, (gains.get(outFaces[t]!) ?? 0) + a2);
  }
  // Boundary with the outside stays, now with the receiving faces inside.
  for (const s of segs) {
    if (s.label === 0) newSegs.push({ a: ids[s.a]!, b: ids[s.b]!, left: vlabel[s.a]!, right: 0 });
  }

  // The loser's edges go; the new boundaries become edges between nodes.
  const oldNodes = new Set<number>();
  for (const e of edgesOfL) {
    const edge = st.edges[e]!;
    oldNodes.add(edge.start);
    oldNodes.add(edge.end);
    st.endEdge(e);
  }
  const newEdges = chainSegments(st, newSegs);
  const touched = new Set<number>(oldNodes);
  for (const e of newEdges) {
    touched.add(st.edges[e]!.start);
    touched.add(st.edges[e]!.end);
  }
  return {
    gains,
    tris: Int32Array.from(outTris),
    triFaces: Int32Array.from(outFaces),
    newEdges,
    touchedNodes: [...touched].sort((p, q) => p - q),
  };
}

/**
 * Completes the split of L that `splitFace` made: L ends, each receiver gets its area (and
 * pays a drawn vertex per triangle it got), and nodes left between two edges of one boundary
 * are dissolved. Returns the receivers (in id order) and the edges that may need simplifying:
 * the new ones, then the joined ones.
 */
export function handOver(st: PlanarState, L: number, res: SplitResult): { receivers: number[]; edges: number[] } {
  st.endFace(L, -1);
  const receivers = [...res.gains.keys()].sort((p, q) => p - q);
  for (const f of receivers) st.faceArea2[f]! += res.gains.get(f)!;
  for (const f of res.triFaces) st.faceCost[f]!++;
  const joined = dissolveNodes(st, res.touchedNodes);
  return { receivers, edges: [...res.newEdges, ...joined] };
}

/**
 * Joins directed segments (with their left and right faces) into edges. A chain ends at a
 * vertex that already has edges, or where other than two segments meet.
 */
function chainSegments(st: PlanarState, segs: { a: number; b: number; left: number; right: number }[]): number[] {
  const at = new Map<number, number[]>();
  segs.forEach((s, i) => {
    for (const v of [s.a, s.b]) {
      let l = at.get(v);
      if (!l) at.set(v, (l = []));
      l.push(i);
    }
  });
  const isNode = (v: number): boolean => st.nodeEdges.has(v) || at.get(v)!.length !== 2;
  const used = new Uint8Array(segs.length);
  const out: number[] = [];
  const trace = (i0: number, from: number): void => {
    const verts = [from];
    let i = i0;
    let v = from;
    const s0 = segs[i0]!;
    const forward0 = s0.a === from;
    const left = forward0 ? s0.left : s0.right, right = forward0 ? s0.right : s0.left;
    for (;;) {
      used[i] = 1;
      const s = segs[i]!;
      v = s.a === v ? s.b : s.a;
      verts.push(v);
      if (isNode(v) || v === from) break;
      const list = at.get(v)!;
      const j = list[0] === i ? list[1]! : list[0]!;
      if (used[j]) break;
      i = j;
    }
    out.push(st.addEdge(from, v, left, right, Int32Array.from(verts), EMPTY_I32, EMPTY_I32, EMPTY_U8));
  };
  // Node vertices in a fixed order, so the result does not depend on map iteration order.
  const starts = [...at.keys()].filter(isNode).sort((p, q) => p - q);
  for (const v of starts) {
    for (const i of at.get(v)!) if (!used[i]) trace(i, v);
  }
  for (let i = 0; i < segs.length; i++) if (!used[i]) trace(i, segs[i]!.a);
  return out;
}
