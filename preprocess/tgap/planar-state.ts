// The planar partition while it is being generalized: the current edges and faces, the
// nodes with their edges, and every version made so far (which becomes the tGAP).
import { chainArea2, chainLength } from '../geom/ring.js';
import type { Topology } from '../topology/build-topology.js';
import type { TgapEdge, TgapFace } from '../../format/tgap-model.js';
import { VertexIndex } from './vertex-index.js';

const NONE = 0x7fffffff; // stepHigh of what is still alive

export class PlanarState {
  xs: Float64Array;
  ys: Float64Array;
  alive: Uint8Array;
  size: number;
  aliveVertices = 0;

  readonly edges: TgapEdge[] = [];
  readonly edgeAlive: number[] = [];
  readonly edgeLength: number[] = [];
  /** Tolerance the edge was last simplified with (0: never). */
  readonly edgeTol: number[] = [];
  readonly nodeEdges = new Map<number, number[]>();

  readonly faces: TgapFace[] = [];
  /** Current alive edges of each face. */
  readonly faceEdges: (Set<number> | null)[] = [];
  /** Current twice-area of each face (follows merges, splits and simplification). */
  readonly faceArea2: number[] = [];
  /** Vertex count of what the face's surfaces in the cube cost since it was made (see reemit.ts). */
  readonly faceCost: number[] = [];
  /** Vertices around each face now (segments of its current edges). */
  readonly faceVerts: number[] = [];
  private readonly cur: number[] = [];
  aliveFaces = 0;

  step = 0;
  readonly index: VertexIndex;
  /** Reference point for areas: keeps the products small for national grid coordinates. */
  readonly rx: number;
  readonly ry: number;

  constructor(topo: Topology, classOf: (face: number) => number) {
    const cap = Math.max(16, Math.ceil(topo.vertexCount * 1.25));
    this.xs = new Float64Array(cap);
    this.ys = new Float64Array(cap);
    this.alive = new Uint8Array(cap);
    this.xs.set(topo.xs.subarray(0, topo.vertexCount));
    this.ys.set(topo.ys.subarray(0, topo.vertexCount));
    this.size = topo.vertexCount;
    this.rx = topo.vertexCount ? topo.xs[0]! : 0;
    this.ry = topo.vertexCount ? topo.ys[0]! : 0;
    this.index = new VertexIndex(this);
    for (let f = 0; f < topo.faceCount; f++) {
      this.faces.push({ classIndex: f === 0 ? 0 : classOf(f), feature: f - 1, stepLow: 0, stepHigh: NONE, mergedInto: -1, endPhase: 0, area2: topo.faceArea2[f]! });
      this.faceEdges.push(f === 0 ? null : new Set());
      this.faceArea2.push(topo.faceArea2[f]!);
      this.faceCost.push(0);
      this.faceVerts.push(0);
      this.cur.push(f);
    }
    this.aliveFaces = topo.faceCount - 1;
    for (const e of topo.edges) {
      this.addEdge(e.start, e.end, e.left, e.right, e.verts, EMPTY_I32, EMPTY_I32, EMPTY_U8);
    }
    const ids: number[] = [];
    for (let v = 0; v < this.size; v++) if (this.alive[v]) ids.push(v);
    this.index.load(ids);
    for (let f = 1; f < topo.faceCount; f++) this.faceCost[f] = this.faceVerts[f]!;
  }

  /** The face that currently holds f's area. */
  resolve(f: number): number {
    let g = f;
    while (this.cur[g] !== g) g = this.cur[g]!;
    // Path compression: later lookups of f are one hop.
    let h = f;
    while (this.cur[h] !== g) {
      const n = this.cur[h]!;
      this.cur[h] = g;
      h = n;
    }
    return g;
  }

  addVertex(x: number, y: number): number {
    if (this.size >= this.xs.length) {
      const n = this.xs.length * 2;
      const xs = new Float64Array(n), ys = new Float64Array(n), alive = new Uint8Array(n);
      xs.set(this.xs);
      ys.set(this.ys);
      alive.set(this.alive);
      this.xs = xs;
      this.ys = ys;
      this.alive = alive;
    }
    const v = this.size++;
    this.xs[v] = x;
    this.ys[v] = y;
    this.alive[v] = 0;
    this.index.insert(v);
    return v;
  }

  addFace(classIndex: number, feature: number, area2: number): number {
    const f = this.faces.length;
    this.faces.push({ classIndex, feature, stepLow: this.step, stepHigh: NONE, mergedInto: -1, endPhase: 0, area2 });
    this.faceEdges.push(new Set());
    this.faceArea2.push(area2);
    this.faceCost.push(0);
    this.faceVerts.push(0);
    this.cur.push(f);
    this.aliveFaces++;
    return f;
  }

  /**
   * Ends face f in the current step; its area (and its edges) now belong to `into` (a merge or
   * a re-emit) or to several faces (-1, a split: its edges must have ended first).
   */
  endFace(f: number, into: number, phase = 0): void {
    const face = this.faces[f]!;
    face.stepHigh = this.step;
    face.mergedInto = into;
    face.endPhase = phase;
    if (into >= 0) this.cur[f] = into;
    // The outside (0) keeps no edges: a face merged into it has none left.
    if (into > 0) {
      const mine = this.faceEdges[f]!, theirs = this.faceEdges[into]!;
      // Keep the larger set object: merging small into large keeps this linear overall.
      if (mine.size > theirs.size) {
        for (const e of theirs) mine.add(e);
        this.faceEdges[into] = mine;
      } else {
        for (const e of mine) theirs.add(e);
      }
      this.faceVerts[into]! += this.faceVerts[f]!;
    }
    this.faceVerts[f] = 0;
    this.faceEdges[f] = null;
    this.aliveFaces--;
  }

  addEdge(
    start: number, end: number, left: number, right: number, verts: Int32Array,
    parents: Int32Array, removed: Int32Array, removedPhase: Uint8Array,
  ): number {
    const id = this.edges.length;
    this.edges.push({ start, end, left, right, verts, stepLow: this.step, stepHigh: NONE, parents, removed, removedPhase });
    this.edgeAlive.push(1);
    this.edgeLength.push(chainLength(verts, this.xs, this.ys));
    this.edgeTol.push(0);
    for (const v of verts) {
      if (!this.alive[v]) {
        this.alive[v] = 1;
        this.aliveVertices++;
      }
    }
    this.nodeList(start).push(id);
    this.nodeList(end).push(id);
    const l = this.resolve(left), r = this.resolve(right);
    const segs = verts.length - 1;
    if (l > 0) {
      this.faceEdges[l]!.add(id);
      this.faceVerts[l]! += segs;
    }
    if (r > 0) {
      this.faceEdges[r]!.add(id);
      this.faceVerts[r]! += segs;
    }
    return id;
  }

  /** Ends edge e at the current step; its inner vertices die, its nodes when no edge is left. */
  endEdge(e: number): void {
    const edge = this.edges[e]!;
    edge.stepHigh = this.step;
    this.edgeAlive[e] = 0;
    const verts = edge.verts;
    for (let i = 1; i < verts.length - 1; i++) this.kill(verts[i]!);
    for (const n of [edge.start, edge.end]) {
      const list = this.nodeEdges.get(n);
      if (!list) continue;
      const k = list.indexOf(e);
      if (k >= 0) list.splice(k, 1);
      if (list.length === 0) {
        this.nodeEdges.delete(n);
        this.kill(n);
      }
    }
    const l = this.resolve(edge.left), r = this.resolve(edge.right);
    const segs = verts.length - 1;
    if (l > 0 && this.faceEdges[l]?.delete(e)) this.faceVerts[l]! -= segs;
    if (r > 0 && this.faceEdges[r]?.delete(e)) this.faceVerts[r]! -= segs;
  }

  kill(v: number): void {
    if (this.alive[v]) {
      this.alive[v] = 0;
      this.aliveVertices--;
    }
  }

  /** Faces on the left and right of edge e now. */
  sides(e: number): [number, number] {
    const edge = this.edges[e]!;
    return [this.resolve(edge.left), this.resolve(edge.right)];
  }

  /** Twice the signed area an edge adds to the face on its left (the right face gets the negative). */
  edgeArea2(e: number): number {
    return chainArea2(this.edges[e]!.verts, this.xs, this.ys, this.rx, this.ry);
  }

  private nodeList(v: number): number[] {
    let list = this.nodeEdges.get(v);
    if (!list) {
      list = [];
      this.nodeEdges.set(v, list);
    }
    return list;
  }
}

export const EMPTY_I32 = new Int32Array(0);
export const EMPTY_U8 = new Uint8Array(0);
export const ALIVE = NONE;
