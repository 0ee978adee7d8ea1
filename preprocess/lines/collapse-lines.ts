// Collapse (issue 12, item 1): when a face of a linear class ends in a split, its centreline
// lives on as a line object from the split's step. So it does when the face is merged whole
// into a face outside its network (a short road piece into the field around it): else the
// lines that end at its boundary would end there, the network cut where its area went. (A
// merge into a face of its network hands the area on: that face's line covers it later.)
// The face's geometry is the tGAP's at the state before the event. Lines of one network meet
// exactly:
// - where the face shares a boundary with a face of its network that is still an area, the
//   line ends at the middle of that boundary (chain-midpoint.ts): a port;
// - that port is handed to the face across, and to whichever face holds its area later: when
//   that face collapses in turn, its line goes to the port too (an anchor). Split pieces next
//   to the boundary go to the face across, so the port lies inside it, unless simplification
//   has since moved the boundary past it.
import { EventKind, type Tgap } from '../../format/tgap-model.js';
import type { Style } from '../style.js';
import { centreline, type Boundary, type Point } from './centreline.js';
import { chainMidpoint } from './chain-midpoint.js';
import { classNetworks } from './class-networks.js';
import { FaceHistory, type FaceSide } from './face-history.js';

export interface LineObject {
  /** The tGAP face whose area collapses to this line. */
  face: number;
  /** Input feature whose attributes the face carries (-1: none). */
  feature: number;
  classIndex: number;
  /** Step of the split (or merge) that ends the face: the line is there from this step on. */
  step: number;
  /** Polylines as flat x, y pairs (a closed one repeats its first point last). */
  paths: Float64Array[];
  /** Points where this line meets other lines of its network, with exactly these coordinates. */
  joins: LineJoin[];
  length: number;
}

export interface LineJoin {
  x: number;
  y: number;
  /** The line met there (index into `lines`); -1 when the area across never became a line. */
  line: number;
  /**
   * The point lies just outside this line's face (its boundary was simplified past an earlier
   * line's end) and is reached by a bridge from the nearest point of the boundary.
   */
  bridge: boolean;
}

export interface CollapseOptions {
  /** Classes with the same number form one network (default: the style's, class-networks.ts). */
  network?: (classIndex: number) => number;
}

export interface CollapseStats {
  /** Faces of linear classes that end in a split. */
  linearSplits: number;
  /** Faces of linear classes merged whole into a face outside their network. */
  linearMerges: number;
  lines: number;
  /** Linear faces whose centreline came out empty (too small for an axis, no port). */
  empty: number;
  length: number;
  /** Ports made on boundaries shared with faces of the network that were still areas. */
  ports: number;
  /** Ports taken up by a later line (anchors reached). */
  anchorsReached: number;
  /** Of those, anchors just outside their face by then, reached by a bridge. */
  anchorsBridged: number;
  /** Anchors too far outside their face by the time it collapsed. */
  anchorsOutside: number;
  /** Anchors whose face never collapsed as a line of the network. */
  anchorsLeft: number;
}

interface Anchor extends Point {
  /** The line and the join on it that wait for this anchor. */
  line: number;
  join: number;
  network: number;
}

export function collapseLines(tgap: Tgap, style: Pick<Style, 'classes'>, opts: CollapseOptions = {}): { lines: LineObject[]; stats: CollapseStats } {
  const byClass = classNetworks(style.classes);
  const network = opts.network ?? ((c: number): number => byClass[c]!);
  const linear = style.classes.map((c) => c.linear);
  const history = new FaceHistory(tgap);
  const lines: LineObject[] = [];
  const stats: CollapseStats = { linearSplits: 0, linearMerges: 0, lines: 0, empty: 0, length: 0, ports: 0, anchorsReached: 0, anchorsBridged: 0, anchorsOutside: 0, anchorsLeft: 0 };
  /** Anchors by the face they were handed to. */
  const pending = new Map<number, Anchor[]>();

  for (const ev of tgap.events) {
    if (ev.kind !== EventKind.Split && ev.kind !== EventKind.Merge) continue;
    const L = ev.loser;
    const face = tgap.faces[L]!;
    if (!linear[face.classIndex]) continue;
    const net = network(face.classIndex);
    if (ev.kind === EventKind.Merge) {
      const into = ev.into > 0 ? tgap.faces[ev.into]!.classIndex : -1;
      if (into >= 0 && linear[into] && network(into) === net) continue;
      stats.linearMerges++;
    } else stats.linearSplits++;
    const s = ev.step - 1;
    const sides = history.boundaryAt(L, s);
    const ports = portsOf(tgap, sides, (g) => linear[tgap.faces[g]!.classIndex] === true && network(tgap.faces[g]!.classIndex) === net);
    const anchors: Anchor[] = [];
    for (const g of history.heldBy(L, s)) {
      const list = pending.get(g);
      if (!list) continue;
      const keep = list.filter((a) => a.network !== net);
      anchors.push(...list.filter((a) => a.network === net));
      if (keep.length > 0) pending.set(g, keep);
      else pending.delete(g);
    }
    const name = `face ${L} (feature #${face.feature})`;
    const line = centreline(boundaryOf(tgap, sides), [...ports, ...anchors], name);
    if (line.paths.length === 0) {
      stats.empty++;
      continue;
    }
    const index = lines.length;
    const joins: LineJoin[] = [];
    ports.forEach((p, i) => {
      if (!line.reached[i]) return;
      joins.push({ x: p.x, y: p.y, line: -1, bridge: false });
      let list = pending.get(p.face);
      if (!list) pending.set(p.face, (list = []));
      list.push({ x: p.x, y: p.y, line: index, join: joins.length - 1, network: net });
      stats.ports++;
    });
    anchors.forEach((a, i) => {
      if (!line.reached[ports.length + i]) {
        stats.anchorsOutside++;
        return;
      }
      const bridge = line.bridged[ports.length + i]!;
      joins.push({ x: a.x, y: a.y, line: a.line, bridge });
      lines[a.line]!.joins[a.join]!.line = index;
      stats.anchorsReached++;
      if (bridge) stats.anchorsBridged++;
    });
    lines.push({ face: L, feature: face.feature, classIndex: face.classIndex, step: ev.step, paths: line.paths, joins, length: line.length });
    stats.length += line.length;
  }
  for (const list of pending.values()) stats.anchorsLeft += list.length;
  stats.lines = lines.length;
  return { lines, stats };
}

/** The face's boundary as directed segments (the face on their left), in global coordinates. */
function boundaryOf(tgap: Tgap, sides: FaceSide[]): Boundary {
  const local = new Map<number, number>();
  const xs: number[] = [], ys: number[] = [], segs: number[] = [];
  const of = (v: number): number => {
    let i = local.get(v);
    if (i === undefined) {
      i = xs.length;
      local.set(v, i);
      xs.push(tgap.xs[v]!);
      ys.push(tgap.ys[v]!);
    }
    return i;
  };
  for (const side of sides) {
    const verts = tgap.edges[side.edge]!.verts;
    for (let i = 0; i + 1 < verts.length; i++) {
      const a = of(verts[i]!), b = of(verts[i + 1]!);
      if (side.forward) segs.push(a, b);
      else segs.push(b, a);
    }
  }
  return { xs, ys, segs };
}

/**
 * A port per chain of boundary shared with a face of the network: the chains are the face's
 * sides towards that face, joined end to start (the face on their left).
 */
function portsOf(tgap: Tgap, sides: FaceSide[], inNetwork: (face: number) => boolean): (Point & { face: number })[] {
  const byFace = new Map<number, number[][]>();
  for (const side of sides) {
    if (side.other <= 0 || !inNetwork(side.other)) continue;
    const verts = Array.from(tgap.edges[side.edge]!.verts);
    if (!side.forward) verts.reverse();
    let list = byFace.get(side.other);
    if (!list) byFace.set(side.other, (list = []));
    list.push(verts);
  }
  const out: (Point & { face: number })[] = [];
  for (const face of [...byFace.keys()].sort((a, b) => a - b)) {
    for (const chain of joinChains(byFace.get(face)!)) {
      const coords: number[] = [];
      for (const v of chain) coords.push(tgap.xs[v]!, tgap.ys[v]!);
      out.push({ ...chainMidpoint(coords), face });
    }
  }
  return out;
}

/** Vertex chains joined where one ends and exactly one other starts. */
function joinChains(chains: number[][]): number[][] {
  const startAt = new Map<number, number[]>();
  const endAt = new Map<number, number>();
  chains.forEach((c, i) => {
    const l = startAt.get(c[0]!);
    if (l) l.push(i);
    else startAt.set(c[0]!, [i]);
    endAt.set(c[c.length - 1]!, (endAt.get(c[c.length - 1]!) ?? 0) + 1);
  });
  const next = (i: number): number => {
    const end = chains[i]![chains[i]!.length - 1]!;
    const l = startAt.get(end);
    return l && l.length === 1 && endAt.get(end) === 1 ? l[0]! : -1;
  };
  const hasPrev = new Uint8Array(chains.length);
  chains.forEach((_, i) => {
    const j = next(i);
    if (j >= 0 && j !== i) hasPrev[j] = 1;
  });
  const used = new Uint8Array(chains.length);
  const out: number[][] = [];
  const walk = (i0: number): void => {
    const chain = [...chains[i0]!];
    used[i0] = 1;
    for (let j = next(i0); j >= 0 && !used[j]; j = next(j)) {
      used[j] = 1;
      chain.push(...chains[j]!.slice(1));
    }
    out.push(chain);
  };
  chains.forEach((_, i) => {
    if (!hasPrev[i] && !used[i]) walk(i);
  });
  chains.forEach((_, i) => {
    if (!used[i]) walk(i);
  });
  return out;
}
