// Pruning over scale (issue 12, item 2): every line gets the step at which it leaves the map,
// so that its scale range is [step, prunedStep).
//
// The rule, per state s = 0..steps:
// - Budget. The length of the lines alive at s may be at most the budget of line-budget.ts:
//   the density the network has at the base scale, where it is all areas (measured by the
//   lines those areas become), held constant over scale (length in proportion to 1/scale).
//   Areas not yet collapsed do not count: they are faces, thinned by the tGAP's own rule of a
//   constant number of faces per map area. (Counting them too left almost no room for lines
//   early on: on bgt_otterlo_1800m at 1:1,500 the areas still hold 89 km of a 94 km budget,
//   and two lines in three went the step they were born.)
// - While over budget, one born line goes at a time, chosen among those of the networks over
//   their share of the budget (the share of the length each has at the base scale; any, if
//   those offer none), among those whose removal keeps every connected piece of the network in
//   one piece (not a cut vertex of the join graph, line-graph.ts, with unborn lines in it as
//   the areas they still are). Each piece offers one: its lines with a free end first
//   (dangling ends; after one goes, the next of its chain may dangle), then its others, the
//   least important first (the length of the line's stroke, strokes.ts, x its rule's weight),
//   then the lowest index. Of the pieces' offers the least important goes (then the lowest
//   index): the order within a network keeps it whole, importance weighs networks and classes
//   against each other. (Dangling ends first across all pieces would keep a lone pond's bank,
//   a closed ring, over every river that ends somewhere.) A free end of a line whose stroke
//   reaches the edge of the data is forgiven once: the road goes on beyond the data.
// - A cut line never goes: pieces shrink but never split, so a class's main network stays
//   connected while any of it is shown. Every piece has a line that is not a cut (a leaf of
//   its block tree), but it may be unborn: then the lines shown can stay over budget (counted).
// Cut lines and pieces are found again after every removal, over the whole graph (Tarjan,
// linear time): correct without bookkeeping, and 1-2 s for the 1,906 lines of
// bgt_otterlo_1800m (a removal each time costs a pass over all lines).
import { scaleInfoOf, type Tgap } from '../../format/tgap-model.js';
import type { Style } from '../style.js';
import type { LineObject } from './collapse-lines.js';
import { FaceHistory } from './face-history.js';
import { lineBudget, mapDensity } from './line-budget.js';
import { cutLines, joinAdjacency, lineGraphComponents } from './line-graph.js';
import { pointKey, pointUses } from './point-uses.js';
import { strokes } from './strokes.js';

export interface PrunedLine extends LineObject {
  /** The first state without this line: it is on the map at states step <= s < prunedStep. */
  prunedStep: number;
}

export interface PruneStats {
  /** Lines pruned below the top of the cube. */
  pruned: number;
  /** Of those, lines pruned at the state they are born in (never shown). */
  prunedAtBirth: number;
  /** Lines that stay to the top of the cube. */
  toTop: number;
  /** States left over budget because every line shown there was a cut line. */
  statesOverBudget: number;
}

export interface PruneOrderInput {
  /** Importance of each line (length x class weight): the least important goes first. */
  importance: ArrayLike<number>;
  /** Line length allowed at each state (index); the last index is the top state. */
  budget: ArrayLike<number>;
  /** 1 where a line goes on beyond the data (pruneLines: its stroke reaches the data's edge): one free end is not a dead end. */
  atEdge?: ArrayLike<number>;
  /** The network of each line (default: all one), and each network's share of the budget (default: all of it). */
  network?: ArrayLike<number>;
  share?: ArrayLike<number>;
}

type PruneShape = Pick<LineObject, 'step' | 'length' | 'paths' | 'joins'>;

/** The prune step of every line by the rule above (top state + 1 for lines that stay). */
export function pruneOrder(lines: readonly PruneShape[], input: PruneOrderInput): { prunedStep: Int32Array; stats: PruneStats } {
  const n = lines.length;
  const top = input.budget.length - 1;
  const adj = joinAdjacency(lines);
  const ends = lines.map(lineEnds);
  const alive = new Uint8Array(n).fill(1);
  const prunedStep = new Int32Array(n).fill(top + 1);
  const stats: PruneStats = { pruned: 0, prunedAtBirth: 0, toTop: 0, statesOverBudget: 0 };
  const bornAt: number[][] = Array.from({ length: top + 1 }, () => []);
  lines.forEach((l, i) => {
    if (l.step <= top) bornAt[Math.max(0, l.step)]!.push(i);
  });
  let total = 0;
  const network = input.network ?? new Int32Array(n);
  const share = input.share ?? [1];
  const networkLength = new Float64Array(share.length);
  let cut = cutLines(adj, alive);
  let piece = lineGraphComponents(adj, alive);

  const dangles = (i: number): boolean => {
    let free = 0;
    for (const joined of ends[i]!) if (!joined.some((j) => alive[j])) free++;
    return free > (input.atEdge?.[i] ? 1 : 0);
  };

  for (let s = 0; s <= top; s++) {
    for (const i of bornAt[s]!) {
      total += lines[i]!.length;
      networkLength[network[i]!]! += lines[i]!.length;
    }
    while (total > input.budget[s]!) {
      // Each piece's offer, then the least important offer (lines in index order: ties go low),
      // from the networks over their share if they offer any.
      const offers = (overShareOnly: boolean): Map<number, { line: number; dangles: boolean }> => {
        const offer = new Map<number, { line: number; dangles: boolean }>();
        for (let i = 0; i < n; i++) {
          if (!alive[i] || cut[i] || lines[i]!.step > s) continue;
          const g = network[i]!;
          if (overShareOnly && !(networkLength[g]! > input.budget[s]! * share[g]!)) continue;
          const d = dangles(i);
          const o = offer.get(piece[i]!);
          if (!o || (d && !o.dangles) || (d === o.dangles && input.importance[i]! < input.importance[o.line]!)) offer.set(piece[i]!, { line: i, dangles: d });
        }
        return offer;
      };
      let offer = offers(true);
      if (offer.size === 0) offer = offers(false);
      let best = -1;
      for (const { line } of offer.values()) {
        if (best < 0 || input.importance[line]! < input.importance[best]! || (input.importance[line] === input.importance[best] && line < best)) best = line;
      }
      if (best < 0) {
        stats.statesOverBudget++;
        break;
      }
      alive[best] = 0;
      prunedStep[best] = s;
      total -= lines[best]!.length;
      networkLength[network[best]!]! -= lines[best]!.length;
      stats.pruned++;
      if (lines[best]!.step === s) stats.prunedAtBirth++;
      cut = cutLines(adj, alive);
      piece = lineGraphComponents(adj, alive);
    }
  }
  stats.toTop = n - stats.pruned;
  return { prunedStep, stats };
}

/**
 * The open ends of a line: ends of its polylines that no other of its polylines passes (a
 * junction inside the line) and that are not the other end of a closed polyline. Each end
 * lists the lines joined there; it is free when none of them is alive.
 */
function lineEnds(l: PruneShape): number[][] {
  const uses = pointUses(l.paths);
  const out: number[][] = [];
  for (const p of l.paths) {
    const n = p.length;
    if (n < 4) continue;
    for (const k of [0, n - 2]) {
      const at = pointKey(p[k]!, p[k + 1]!);
      if (uses.get(at) !== 1) continue;
      out.push(l.joins.filter((j) => j.line >= 0 && pointKey(j.x, j.y) === at).map((j) => j.line));
    }
  }
  return out;
}

export interface PruneOptions {
  /**
   * Line density to hold, in mm of line per mm² of map (default: that of the base scale, the
   * whole network's length over the data's extent).
   */
  density?: number;
  /** Importance per metre of each line (default: its class's weight); the style's line rules give it. */
  weights?: ArrayLike<number>;
  /** The group (style line rule) of each line, whose lines chain into strokes (default: its class). */
  groups?: ArrayLike<number>;
}

/**
 * Prune steps for the lines of `collapseLines`: a copy of each line with `prunedStep`, the
 * density held (mm per mm²) and the budget of every state (metres of line).
 */
export function pruneLines(
  lines: readonly LineObject[],
  tgap: Tgap,
  style: Pick<Style, 'classes'>,
  opts: PruneOptions = {},
): { lines: PrunedLine[]; density: number; budget: Float64Array; stats: PruneStats } {
  const steps = tgap.meta.steps;
  lines.forEach((l, i) => {
    const bad = (what: string): never => {
      throw new Error(`line ${i} (face ${l.face}, feature #${l.feature}): ${what}`);
    };
    if (!Number.isInteger(l.step) || l.step < 1 || l.step > steps) bad(`step ${l.step} is not a step of the tGAP (1..${steps})`);
    if (!(l.length >= 0) || !Number.isFinite(l.length)) bad(`length ${l.length} is not a number >= 0`);
    if (!style.classes[l.classIndex]) bad(`class ${l.classIndex} is not in the style (${style.classes.length} classes)`);
  });
  const [x0, y0, x1, y1] = tgap.meta.extent;
  const area = (x1 - x0) * (y1 - y0);
  const total = lines.reduce((s, l) => s + l.length, 0);
  const density = opts.density ?? mapDensity(total, area, tgap.meta.baseScale);
  const budget = lineBudget(scaleInfoOf(tgap), steps, area, density);
  const history = new FaceHistory(tgap);
  // A line weighs as the stroke it is part of (strokes.ts): a main road cut into short pieces
  // at its junctions counts as the whole road, not as its pieces.
  const { stroke, strokeLength } = strokes(lines, opts.groups ?? lines.map((l) => l.classIndex));
  const importance = lines.map((l, i) => strokeLength[i]! * (opts.weights?.[i] ?? style.classes[l.classIndex]!.weight));
  // A stroke that reaches the edge of the data goes on beyond it: each of its lines may have a
  // free end without being a dead end, so a through road is not eaten away from the edge in.
  const edgeStroke = new Uint8Array(lines.length);
  lines.forEach((l, i) => {
    if (history.boundaryAt(l.face, l.step - 1).some((side) => side.other === 0)) edgeStroke[stroke[i]!] = 1;
  });
  const atEdge = lines.map((_, i) => edgeStroke[stroke[i]!]!);
  // Each network (the classes its joins link: each class alone by default) has a share of the
  // budget, the share of the length it has at the base scale; pruning takes from the networks
  // over their share. A class of long important strokes (main roads) would otherwise take the
  // whole budget and leave no water on the map, while a class under its share may still use
  // what the others leave.
  const network = new Int32Array(lines.length);
  const share: number[] = [];
  networks(lines).forEach((members, g) => {
    for (const i of members) network[i] = g;
    share.push(total > 0 ? members.reduce((sum, i) => sum + lines[i]!.length, 0) / total : 1);
  });
  const { prunedStep, stats } = pruneOrder(lines, { importance, budget, atEdge, network, share });
  return { lines: lines.map((l, i) => ({ ...l, prunedStep: prunedStep[i]! })), density, budget, stats };
}

/** The lines of each network, in index order: classes joined where a join links two of them. */
function networks(lines: readonly LineObject[]): number[][] {
  const classOf = new Map<number, number>();
  const find = (c: number): number => {
    let r = c;
    while (classOf.get(r) !== undefined && classOf.get(r) !== r) r = classOf.get(r)!;
    return r;
  };
  for (const l of lines) if (!classOf.has(l.classIndex)) classOf.set(l.classIndex, l.classIndex);
  for (const l of lines) {
    for (const j of l.joins) {
      if (j.line < 0) continue;
      const a = find(l.classIndex), b = find(lines[j.line]!.classIndex);
      if (a !== b) classOf.set(Math.max(a, b), Math.min(a, b));
    }
  }
  const groups = new Map<number, number[]>();
  lines.forEach((l, i) => {
    const r = find(l.classIndex);
    groups.set(r, [...(groups.get(r) ?? []), i]);
  });
  return [...groups.keys()].sort((a, b) => a - b).map((r) => groups.get(r)!);
}
