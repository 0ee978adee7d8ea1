// The tGAP generalization: again and again the least important face (area x class weight)
// is merged into its most compatible neighbour (shared boundary length x compatibility), or,
// for a linear class, split among its neighbours; after each event the boundaries of the
// changed faces are simplified to the resolution of the new scale.
import FlatQueue from 'flatqueue';
import type { Style } from '../style.js';
import type { Topology } from '../topology/build-topology.js';
import { EventKind, type TgapEdge, type TgapEvent, type TgapFace } from './model.js';
import { EMPTY_U8, PlanarState } from './planar-state.js';
import { simplifyEdge, StepTriangles } from './simplify.js';
import { splitFace } from './split.js';

export interface GeneralizeOptions {
  /** Scale denominator of the input. */
  baseScale: number;
  /** Simplification tolerance on the map, mm. */
  resolutionMm: number;
  /**
   * A winner keeps its id (its surfaces in the cube stay valid) until what was drawn for it
   * exceeds this many times its current size; then it is replaced by a new face whose whole
   * area is drawn afresh with the current, simplified geometry (detail follows scale).
   */
  reemitFactor?: number;
  /** An edge is simplified again once the tolerance has grown by this factor. */
  hysteresis?: number;
  /** Called every `progressEvery` steps. */
  onProgress?: (step: number, aliveFaces: number) => void;
}

export interface GeneralizeResult {
  xs: Float64Array;
  ys: Float64Array;
  faces: TgapFace[];
  edges: TgapEdge[];
  events: TgapEvent[];
  facesAlive: number[];
  stats: { merges: number; splits: number; splitFallbacks: number; reemits: number; removedVertices: number; unmergeable: number };
}

export function generalize(topo: Topology, classOf: (face: number) => number, style: Style, opts: GeneralizeOptions): GeneralizeResult {
  const st = new PlanarState(topo, classOf);
  const reemitFactor = opts.reemitFactor ?? 2;
  const hysteresis = opts.hysteresis ?? 1.25;
  const nb = st.aliveFaces;
  const weight = style.classes.map((c) => c.weight);
  const linear = style.classes.map((c) => c.linear);
  const compat = style.compat;
  const importance = new Float64Array(topo.faceCount * 2 + 16);
  const queue = new FlatQueue<number>();
  const setImportance = (f: number): void => {
    if (f >= importance.length) throw new Error('face ids outgrew the importance table');
    const imp = (Math.abs(st.faceArea2[f]!) / 2) * weight[st.faces[f]!.classIndex]!;
    importance[f] = imp;
    queue.push(f, imp);
  };
  for (let f = 1; f < topo.faceCount; f++) setImportance(f);

  const events: TgapEvent[] = [];
  const facesAlive: number[] = [nb];
  const tris = new StepTriangles();
  const stats = { merges: 0, splits: 0, splitFallbacks: 0, reemits: 0, removedVertices: 0, unmergeable: 0 };
  const metresPerMm = opts.resolutionMm / 1000;

  /** Joins the two edges at a node where only they remain; returns the new edge or -1. */
  const dissolve = (v: number): number => {
    const list = st.nodeEdges.get(v);
    if (!list || list.length !== 2 || list[0] === list[1]) return -1;
    const e1 = list[0]!, e2 = list[1]!;
    const a = st.edges[e1]!, b = st.edges[e2]!;
    const aEnds = a.end === v; // a runs into v
    const bStarts = b.start === v; // b runs out of v
    const [al, ar] = st.sides(e1);
    const [bl, br] = st.sides(e2);
    const left = aEnds ? al : ar, right = aEnds ? ar : al;
    const bLeft = bStarts ? bl : br, bRight = bStarts ? br : bl;
    if (left !== bLeft || right !== bRight) return -1; // not one boundary: keep the node
    const av = aEnds ? a.verts : a.verts.slice().reverse();
    const bv = bStarts ? b.verts : b.verts.slice().reverse();
    const verts = new Int32Array(av.length + bv.length - 1);
    verts.set(av);
    verts.set(bv.subarray(1), av.length);
    const parents = Int32Array.of(aEnds ? e1 : -(e1 + 1), bStarts ? e2 : -(e2 + 1));
    st.endEdge(e1);
    st.endEdge(e2);
    return st.addEdge(verts[0]!, verts[verts.length - 1]!, left, right, verts, parents, new Int32Array(0), EMPTY_U8);
  };

  /** Simplifies the given edges and every edge of `faces` not yet simplified to about `tol`. */
  const simplifyAround = (edges: number[], faces: number[], tol: number): void => {
    const todo = new Set(edges);
    for (const f of faces) {
      const set = st.faceEdges[f];
      if (!set) continue;
      for (const e of set) if (st.edgeTol[e]! * hysteresis < tol) todo.add(e);
    }
    for (const e of [...todo].sort((p, q) => p - q)) {
      if (!st.edgeAlive[e]) continue;
      const before = st.aliveVertices;
      simplifyEdge(st, e, tol, tris);
      stats.removedVertices += before - st.aliveVertices;
    }
  };

  const bestNeighbour = (f: number): { best: number; count: number } => {
    const shared = new Map<number, number>();
    for (const e of st.faceEdges[f]!) {
      const [l, r] = st.sides(e);
      const o = l === f ? r : l;
      if (o > 0) shared.set(o, (shared.get(o) ?? 0) + st.edgeLength[e]!);
    }
    const cf = st.faces[f]!.classIndex;
    let best = -1, bestScore = -1;
    for (const [o, len] of shared) {
      const score = len * compat[cf]![st.faces[o]!.classIndex]!;
      if (score > bestScore || (score === bestScore && o < best)) {
        best = o;
        bestScore = score;
      }
    }
    return { best, count: shared.size };
  };

  const merge = (L: number, W: number, k: number, tol: number): void => {
    const vL = st.faceVertexCount(L), vW = st.faceVertexCount(W);
    st.faceCost[W]! += vL;
    const reemit = st.faceCost[W]! > reemitFactor * (vW + vL) + 64;
    const removed: number[] = [];
    const kept: number[] = [];
    for (const e of st.faceEdges[L]!) {
      const [l, r] = st.sides(e);
      (l === W || r === W ? removed : kept).push(e);
    }
    removed.sort((p, q) => p - q);
    kept.sort((p, q) => p - q);
    const nodes = new Set<number>();
    for (const e of removed) {
      nodes.add(st.edges[e]!.start);
      nodes.add(st.edges[e]!.end);
      st.endEdge(e);
    }
    const area2 = st.faceArea2[W]! + st.faceArea2[L]!;
    let into = W;
    const wEdges = st.faceEdges[W]!;
    for (const e of kept) wEdges.add(e);
    if (reemit) {
      // Both end; the new face is their child (the classic tGAP merge).
      const wf = st.faces[W]!;
      into = st.addFace(wf.classIndex, wf.feature, area2);
      st.endFace(W, into);
      st.faceEdges[into] = wEdges;
      st.faceCost[into] = vW + vL;
      stats.reemits++;
    }
    st.endFace(L, into);
    st.faceArea2[into] = area2;
    const joined: number[] = [];
    for (const v of [...nodes].sort((p, q) => p - q)) {
      const e = dissolve(v);
      if (e >= 0) joined.push(e);
    }
    simplifyAround([...joined, ...kept], [into], tol);
    events.push({ kind: EventKind.Merge, step: k, loser: L, into, winner: reemit ? W : -1 });
    setImportance(into);
    stats.merges++;
  };

  while (queue.length > 0) {
    const pr = queue.peekValue()!;
    const L = queue.pop()!;
    if (st.faces[L]!.stepHigh !== 0x7fffffff || pr !== importance[L]) continue;
    const { best, count } = bestNeighbour(L);
    if (best < 0) {
      stats.unmergeable++;
      continue; // nothing to merge with (a part of the domain on its own)
    }
    const k = ++st.step;
    tris.clear();
    const scale = opts.baseScale * Math.sqrt(nb / Math.max(1, st.aliveFaces - 1));
    const tol = scale * metresPerMm;
    if (linear[st.faces[L]!.classIndex] && count >= 2) {
      const res = splitFace(st, L);
      if (res) {
        st.endFace(L, -1);
        const receivers = [...res.gains.keys()].sort((p, q) => p - q);
        for (const f of receivers) st.faceArea2[f]! += res.gains.get(f)!;
        for (const f of res.triFaces) st.faceCost[f]!++;
        const joined: number[] = [];
        for (const v of res.touchedNodes) {
          const e = dissolve(v);
          if (e >= 0) joined.push(e);
        }
        simplifyAround([...res.newEdges, ...joined], receivers, tol);
        events.push({ kind: EventKind.Split, step: k, loser: L, into: -1, winner: -1, tris: res.tris, triFaces: res.triFaces });
        for (const f of receivers) setImportance(f);
        stats.splits++;
      } else {
        stats.splitFallbacks++;
        merge(L, best, k, tol);
      }
    } else {
      merge(L, best, k, tol);
    }
    facesAlive.push(st.aliveFaces);
    st.index.compact(st.aliveVertices);
    if (opts.onProgress && k % 10000 === 0) opts.onProgress(k, st.aliveFaces);
  }
  const steps = st.step;
  // What is still alive lives on to the end.
  for (const f of st.faces) if (f.stepHigh === 0x7fffffff) f.stepHigh = steps + 1;
  for (const e of st.edges) if (e.stepHigh === 0x7fffffff) e.stepHigh = steps + 1;
  st.faces[0]!.stepHigh = steps + 1;
  return { xs: st.xs.slice(0, st.size), ys: st.ys.slice(0, st.size), faces: st.faces, edges: st.edges, events, facesAlive, stats };
}
