// The tGAP generalization: again and again the least important face (area x class weight)
// is merged into its most compatible neighbour (shared boundary length x compatibility), or,
// for a linear class, split among its neighbours; after each event the boundaries of the
// changed faces are simplified to the resolution of the new scale.
import type { Style } from '../style.js';
import type { Topology } from '../topology/build-topology.js';
import { EventKind, type TgapEdge, type TgapEvent, type TgapFace } from '../../format/tgap-model.js';
import { scaleOfFaces } from '../../format/scale.js';
import { ALIVE, PlanarState } from './planar-state.js';
import { ImportanceQueue } from './importance-queue.js';
import { mergeFace, mostCompatibleNeighbour } from './merge.js';
import { reemitCostlyFaces, type ReemitLimits } from './reemit.js';
import { simplifyEdge, StepTriangles } from './simplify.js';
import { handOver, splitFace } from './split.js';
import { eventNeighbourhood, StepLocks } from './step-grouping.js';

export interface GeneralizeOptions {
  /** Scale denominator of the input. */
  baseScale: number;
  /** Simplification tolerance on the map, mm. */
  resolutionMm: number;
  /**
   * A winner keeps its id (its surfaces in the cube stay valid) until what was drawn for it
   * exceeds this many times its current size; then it is replaced by a new face whose whole
   * area is drawn afresh with the current, simplified geometry (detail follows scale).
   * Default 3: in a smooth cube, bench:session took nlcd_zion from 6.29 to 5.27 MB (frame
   * 0.82x -> 0.80x MapLibre's) and bgt_otterlo_1800m from 1.89 to 1.82 MB against 2.
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
  /** The chunks' coarsest grid: a split's new points go onto it where they can (split.ts; 0: none). */
  snapStep?: number;
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
  stats: GeneralizeStats;
}

export interface GeneralizeStats {
  merges: number;
  splits: number;
  /** Linear faces that could not be split and were merged whole. */
  splitFallbacks: number;
  reemits: number;
  removedVertices: number;
  /**
   * Faces with no neighbour (a part of the domain on its own, e.g. an isolated building) that
   * left the map: merged into the outside when their turn came, as any face's does.
   */
  intoOutside: number;
  /** Faces with no neighbour left alive: the last face, alone, stays to the end. */
  unmergeable: number;
  /** Times every edge behind the current tolerance was simplified. */
  refreshes: number;
}

export function generalize(topo: Topology, classOf: (face: number) => number, style: Style, opts: GeneralizeOptions): GeneralizeResult {
  return new Generalization(topo, classOf, style, opts).run();
}

/** One run of the generalization: the state, the queue and the settings it works with. */
class Generalization {
  private readonly st: PlanarState;
  private readonly queue: ImportanceQueue;
  private readonly linear: boolean[];
  private readonly compat: Float64Array[];
  private readonly reemitLimits: ReemitLimits;
  private readonly hysteresis: number;
  private readonly snapStep: number;
  private readonly group: number;
  /** Faces at step 0: the base of the scale of every step. */
  private readonly nb: number;
  private readonly metresPerMm: number;
  /** The tolerance every edge was last brought up to. */
  private refreshedTol: number;
  private readonly tris = new StepTriangles();
  private readonly events: TgapEvent[] = [];
  private readonly facesAlive: number[];
  private readonly stats: GeneralizeStats = { merges: 0, splits: 0, splitFallbacks: 0, reemits: 0, removedVertices: 0, intoOutside: 0, unmergeable: 0, refreshes: 0 };

  constructor(topo: Topology, classOf: (face: number) => number, style: Style, private readonly opts: GeneralizeOptions) {
    const st = new PlanarState(topo, classOf);
    this.st = st;
    this.reemitLimits = { factor: opts.reemitFactor ?? 3, slack: opts.reemitSlack ?? 8 };
    this.hysteresis = opts.hysteresis ?? 1.25;
    this.snapStep = opts.snapStep ?? 0;
    this.group = Math.max(1, Math.floor(opts.group ?? 1));
    this.nb = st.aliveFaces;
    this.facesAlive = [this.nb];
    this.linear = style.classes.map((c) => c.linear);
    this.compat = style.compat;
    this.metresPerMm = opts.resolutionMm / 1000;
    this.refreshedTol = opts.baseScale * this.metresPerMm;
    // Room for the faces and their first redraws; the table grows when redraws need more.
    this.queue = new ImportanceQueue(st, style.classes.map((c) => c.weight), topo.faceCount * 2 + 16);
    for (let f = 1; f < topo.faceCount; f++) this.queue.update(f);
  }

  run(): GeneralizeResult {
    while (this.queue.length > 0) if (!this.runStep()) break;
    return this.finish();
  }

  /**
   * One step: the least important face's event and, with grouping, more events on faces
   * whose neighbourhoods do not meet (they may all use the state before the step). Returns
   * false when no event was left to make.
   */
  private runStep(): boolean {
    const { st, queue, group } = this;
    let k = -1;
    let tol = 0;
    const locks = new StepLocks();
    const deferred: number[] = [];
    const changed: number[] = [];
    let done = 0;
    while (done < group && queue.length > 0 && deferred.length < 4 * group) {
      const L = queue.pop();
      if (L < 0) continue;
      let { best, count } = mostCompatibleNeighbour(st, L, this.compat);
      if (best < 0) {
        // No neighbour but the outside: too small for the scale now, the face leaves the map
        // (merges into the outside, face 0), unless it is the last one.
        if (st.aliveFaces <= 1) {
          this.stats.unmergeable++;
          continue;
        }
        best = 0;
        count = 0;
      }
      const splitting = this.linear[st.faces[L]!.classIndex] === true && count >= 2;
      if (group > 1 && !locks.tryLock(eventNeighbourhood(st, L, best, splitting))) {
        deferred.push(L);
        continue;
      }
      if (k < 0) {
        k = ++st.step;
        tol = this.openStep();
      }
      changed.push(...this.event(L, best, splitting, k, tol));
      done++;
    }
    // Faces passed over for this step wait for the next one, in their order of importance.
    for (const f of deferred) queue.requeue(f);
    if (k < 0) return false;
    changed.push(...this.refreshStaleEdges(tol));
    this.events.push(...reemitCostlyFaces(st, changed, k, this.reemitLimits, (g) => {
      this.queue.update(g);
      this.stats.reemits++;
    }));
    this.facesAlive.push(st.aliveFaces);
    st.index.compact(st.aliveVertices);
    if (this.opts.onProgress && k % 10000 === 0) this.opts.onProgress(k, st.aliveFaces);
    return true;
  }

  /** Starts a new step; returns the simplification tolerance of its scale (ground units). */
  private openStep(): number {
    const { st, group } = this;
    this.tris.clear();
    // The scale the step ends at: with grouping, as many faces fewer as it may hold events.
    const scale = scaleOfFaces(this.opts.baseScale, this.nb, st.aliveFaces - Math.min(group, st.aliveFaces - 1));
    return scale * this.metresPerMm;
  }

  /** Splits L among its neighbours or merges it into `best`; returns the faces it changed. */
  private event(L: number, best: number, splitting: boolean, k: number, tol: number): number[] {
    const { st } = this;
    const res = splitting ? splitFace(st, L, this.snapStep) : null;
    if (res) {
      const { receivers, edges } = handOver(st, L, res);
      this.events.push({ kind: EventKind.Split, step: k, loser: L, into: -1, tris: res.tris, triFaces: res.triFaces });
      const touched = this.simplifyAround(edges, receivers, tol);
      for (const f of receivers) this.queue.update(f);
      this.stats.splits++;
      return [...receivers, ...touched];
    }
    if (splitting) this.stats.splitFallbacks++;
    const edges = mergeFace(st, L, best);
    this.events.push({ kind: EventKind.Merge, step: k, loser: L, into: best });
    this.stats.merges++;
    if (best === 0) {
      // Into the outside: every edge of L ended with it; nothing else changed.
      this.stats.intoOutside++;
      return [];
    }
    const touched = this.simplifyAround(edges, [best], tol);
    this.queue.update(best);
    return [best, ...touched];
  }

  /**
   * Simplifies the given edges and every edge of `faces` not yet simplified to about `tol`
   * (in id order); returns the faces along the edges that changed.
   */
  private simplifyAround(edges: number[], faces: number[], tol: number): number[] {
    const { st } = this;
    const todo = new Set(edges);
    for (const f of faces) {
      const set = st.faceEdges[f];
      if (!set) continue;
      for (const e of set) if (st.edgeTol[e]! * this.hysteresis < tol) todo.add(e);
    }
    const touched: number[] = [];
    for (const e of [...todo].sort((p, q) => p - q)) {
      if (!st.edgeAlive[e]) continue;
      const before = st.aliveVertices;
      if (simplifyEdge(st, e, tol, this.tris) !== e) touched.push(...st.sides(e));
      this.stats.removedVertices += before - st.aliveVertices;
    }
    return touched;
  }

  /**
   * Lines no event has touched for a while still get simplified: whenever the scale has grown
   * by the hysteresis factor, every edge behind the current tolerance is brought up to it.
   * Returns the faces along the edges that changed.
   */
  private refreshStaleEdges(tol: number): number[] {
    const { st } = this;
    if (tol <= this.refreshedTol * this.hysteresis) return [];
    this.refreshedTol = tol;
    const stale: number[] = [];
    for (let e = 0; e < st.edges.length; e++) if (st.edgeAlive[e] && st.edgeTol[e]! * this.hysteresis < tol) stale.push(e);
    this.stats.refreshes++;
    return this.simplifyAround(stale, [], tol);
  }

  /** What is still alive lives on to the end. */
  private finish(): GeneralizeResult {
    const { st } = this;
    const steps = st.step;
    for (const f of st.faces) if (f.stepHigh === ALIVE) f.stepHigh = steps + 1;
    for (const e of st.edges) if (e.stepHigh === ALIVE) e.stepHigh = steps + 1;
    st.faces[0]!.stepHigh = steps + 1;
    const { events, facesAlive, stats } = this;
    return { xs: st.xs.slice(0, st.size), ys: st.ys.slice(0, st.size), faces: st.faces, edges: st.edges, events, facesAlive, stats };
  }
}
