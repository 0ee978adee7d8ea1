// The tGAP generalization: again and again the least important face (area x class weight)
// is merged into its most compatible neighbour (shared boundary length x compatibility), or,
// for a linear class, split among its neighbours; after each event the boundaries of the
// changed faces are simplified to the resolution of the new scale.
import FlatQueue from 'flatqueue';
import type { Style } from '../style.js';
import type { Topology } from '../topology/build-topology.js';
import { EventKind, REEMIT_PHASE, type TgapEdge, type TgapEvent, type TgapFace } from '../../format/tgap-model.js';
import { ALIVE, EMPTY_U8, PlanarState } from './planar-state.js';
import { simplifyEdge, StepTriangles } from './simplify.js';
import { splitFace } from './split.js';
import { scaleOfFaces } from '../../format/scale.js';

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
  /** Vertices a face may cost beyond reemitFactor times its size (small faces are cheap to keep). */
  reemitSlack?: number;
  /** An edge is simplified again once the tolerance has grown by this factor. */
  hysteresis?: number;
  /**
   * Events per step (default 1): more groups that many independent merges or splits (whose
   * neighbourhoods do not meet) into one step, so each step's transition is longer.
   */
  group?: number;
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
  stats: { merges: number; splits: number; splitFallbacks: number; reemits: number; removedVertices: number; unmergeable: number; refreshes: number };
}

export function generalize(topo: Topology, classOf: (face: number) => number, style: Style, opts: GeneralizeOptions): GeneralizeResult {
  const st = new PlanarState(topo, classOf);
  const reemitFactor = opts.reemitFactor ?? 2;
  const reemitSlack = opts.reemitSlack ?? 8;
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
  const stats = { merges: 0, splits: 0, splitFallbacks: 0, reemits: 0, removedVertices: 0, unmergeable: 0, refreshes: 0 };
  const metresPerMm = opts.resolutionMm / 1000;
  let refreshedTol = opts.baseScale * metresPerMm;

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

  /**
   * Simplifies the given edges and every edge of `faces` not yet simplified to about `tol`;
   * returns the faces along the edges that changed.
   */
  const simplifyAround = (edges: number[], faces: number[], tol: number): number[] => {
    const todo = new Set(edges);
    for (const f of faces) {
      const set = st.faceEdges[f];
      if (!set) continue;
      for (const e of set) if (st.edgeTol[e]! * hysteresis < tol) todo.add(e);
    }
    const touched: number[] = [];
    for (const e of [...todo].sort((p, q) => p - q)) {
      if (!st.edgeAlive[e]) continue;
      const before = st.aliveVertices;
      if (simplifyEdge(st, e, tol, tris) !== e) touched.push(...st.sides(e));
      stats.removedVertices += before - st.aliveVertices;
    }
    return touched;
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

  /**
   * A face keeps its id while it grows and its lines are simplified: the cube then only needs
   * the changes (cheap). But its old surfaces stay in use as long as it lives, so once what was
   * drawn for it exceeds `reemitFactor` times its current size it is replaced by a new face
   * (same class and attributes) whose whole area is drawn afresh, already simplified.
   */
  const maybeReemit = (faces: Iterable<number>, k: number): void => {
    for (const f of [...new Set(faces)].sort((p, q) => p - q)) {
      if (f <= 0 || st.faces[f]!.stepHigh !== ALIVE) continue;
      if (st.faceCost[f]! <= reemitFactor * st.faceVerts[f]! + reemitSlack) continue;
      const face = st.faces[f]!;
      const g = st.addFace(face.classIndex, face.feature, st.faceArea2[f]!);
      st.endFace(f, g, REEMIT_PHASE);
      st.faceCost[g] = st.faceVerts[g]!;
      events.push({ kind: EventKind.Reemit, step: k, loser: f, into: g });
      setImportance(g);
      stats.reemits++;
    }
  };

  const merge = (L: number, W: number, k: number, tol: number): number[] => {
    st.faceCost[W]! += st.faceVerts[L]!;
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
    st.faceArea2[W]! += st.faceArea2[L]!;
    st.endFace(L, W);
    const joined: number[] = [];
    for (const v of [...nodes].sort((p, q) => p - q)) {
      const e = dissolve(v);
      if (e >= 0) joined.push(e);
    }
    events.push({ kind: EventKind.Merge, step: k, loser: L, into: W });
    const touched = simplifyAround([...joined, ...kept], [W], tol);
    setImportance(W);
    stats.merges++;
    return [W, ...touched];
  };

  /** The faces an event on L (merging into `best`, or split) changes or reshapes. */
  const neighbourhood = (L: number, best: number, split: boolean): Set<number> => {
    const out = new Set<number>([L]);
    const around = (f: number): void => {
      for (const e of st.faceEdges[f] ?? []) for (const g of st.sides(e)) if (g > 0) out.add(g);
    };
    around(L);
    // A merge also simplifies the winner's edges, a split every receiver's: their neighbours too.
    for (const f of split ? [...out] : [best]) around(f);
    return out;
  };

  const group = Math.max(1, Math.floor(opts.group ?? 1));
  while (queue.length > 0) {
    // One step: the least important face's event and, with grouping, more events on faces
    // whose neighbourhoods do not meet (they may all use the state before the step).
    let k = -1;
    let tol = 0;
    const locked = new Set<number>();
    const deferred: number[] = [];
    const changed: number[] = [];
    let done = 0;
    while (done < group && queue.length > 0 && deferred.length < 4 * group) {
      const pr = queue.peekValue()!;
      const L = queue.pop()!;
      if (st.faces[L]!.stepHigh !== ALIVE || pr !== importance[L]) continue;
      const { best, count } = bestNeighbour(L);
      if (best < 0) {
        stats.unmergeable++;
        continue; // nothing to merge with (a part of the domain on its own)
      }
      const splitting = linear[st.faces[L]!.classIndex] === true && count >= 2;
      if (group > 1) {
        const hood = neighbourhood(L, best, splitting);
        if ([...hood].some((f) => locked.has(f))) {
          deferred.push(L);
          continue;
        }
        for (const f of hood) locked.add(f);
      }
      if (k < 0) {
        k = ++st.step;
        tris.clear();
        const scale = scaleOfFaces(opts.baseScale, nb, st.aliveFaces - Math.min(group, st.aliveFaces - 1));
        tol = scale * metresPerMm;
      }
      const res = splitting ? splitFace(st, L) : null;
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
        events.push({ kind: EventKind.Split, step: k, loser: L, into: -1, tris: res.tris, triFaces: res.triFaces });
        const touched = simplifyAround([...res.newEdges, ...joined], receivers, tol);
        for (const f of receivers) setImportance(f);
        stats.splits++;
        changed.push(...receivers, ...touched);
      } else {
        if (splitting) stats.splitFallbacks++;
        changed.push(...merge(L, best, k, tol));
      }
      done++;
    }
    // Faces passed over for this step wait for the next one, in their order of importance.
    for (const f of deferred) queue.push(f, importance[f]!);
    if (k < 0) break;
    // Lines no event has touched for a while still get simplified: whenever the scale has grown
    // by the hysteresis factor, every edge behind the current tolerance is brought up to it.
    if (tol > refreshedTol * hysteresis) {
      refreshedTol = tol;
      const stale: number[] = [];
      for (let e = 0; e < st.edges.length; e++) if (st.edgeAlive[e] && st.edgeTol[e]! * hysteresis < tol) stale.push(e);
      changed.push(...simplifyAround(stale, [], tol));
      stats.refreshes++;
    }
    maybeReemit(changed, k);
    facesAlive.push(st.aliveFaces);
    st.index.compact(st.aliveVertices);
    if (opts.onProgress && k % 10000 === 0) opts.onProgress(k, st.aliveFaces);
  }
  const steps = st.step;
  // What is still alive lives on to the end.
  for (const f of st.faces) if (f.stepHigh === ALIVE) f.stepHigh = steps + 1;
  for (const e of st.edges) if (e.stepHigh === ALIVE) e.stepHigh = steps + 1;
  st.faces[0]!.stepHigh = steps + 1;
  return { xs: st.xs.slice(0, st.size), ys: st.ys.slice(0, st.size), faces: st.faces, edges: st.edges, events, facesAlive, stats };
}

