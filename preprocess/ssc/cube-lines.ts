// The cube's lines (issue 12): linear faces collapsed to lines, pruned and simplified over scale
// (preprocess/lines/), with their states turned into z as docs/FORMAT.md ("Line chunk file")
// states, and packed into line chunks of even size by the surfaces' split (chunking.ts).
import type { Box3 } from '../../format/cube-index.js';
import { encodeLineChunk } from '../../format/line-chunk-encode.js';
import { groundBox, type LineRecord } from '../../format/line-record.js';
import { phaseZ, type Tgap } from '../../format/tgap-model.js';
import { lineRuleFinder } from '../../format/line-style.js';
import { collapseLines } from '../lines/collapse-lines.js';
import { keepLines } from '../lines/keep-lines.js';
import { pruneLines } from '../lines/prune-lines.js';
import { simplifyLines } from '../lines/simplify-lines.js';
import type { Style } from '../style.js';
import type { TriangleBoxes } from './chunk-cuts.js';
import { splitEvenly } from './chunking.js';
import type { ViewModel } from './view-hit-chance.js';

/** z from which a line, or a vertex of it, is gone: the first state without it, at phase 0; past the top, the surfaces' top. */
export function stateEndZ(state: number, steps: number): number {
  return state > steps ? steps + 1 : phaseZ(state, 0);
}

/**
 * The lines of the cube before they are put in z: the collapsed lines the style draws, pruned
 * and simplified (`simplified.lines`), with `rules[i]` the line rule of line i (the style's,
 * from its feature's attributes). Lines never on the map are left out: those whose rule draws
 * nothing (keep-lines.ts: they take no share of the line budget either) and those pruned at
 * birth. Pruning weighs each line by its rule's weight, and chains lines of one rule into
 * strokes. `bench:lines` reports on these.
 */
export function generalizedLines(tgap: Tgap, style: Pick<Style, 'classes' | 'lineRules'>): { rules: number[]; pruned: ReturnType<typeof pruneLines>; simplified: ReturnType<typeof simplifyLines> } {
  const ruleOf = lineRuleFinder(style.lineRules);
  const collapsed = collapseLines(tgap, style).lines;
  const rules = collapsed.map((l) => ruleOf(l.classIndex, l.feature >= 0 ? tgap.meta.attributes[l.feature] : null));
  const drawn = rules.map((r) => r >= 0 && style.lineRules[r]!.width > 0);
  const kept = keepLines(collapsed, drawn);
  const keptRules = rules.filter((_, i) => drawn[i]);
  const pruned = pruneLines(kept, tgap, style, { weights: keptRules.map((r) => style.lineRules[r]!.weight), groups: keptRules });
  // Lines pruned the state they are born in are never on the map.
  const shown = pruned.lines.map((l, i) => ({ l, rule: keptRules[i]! })).filter(({ l }) => l.step < l.prunedStep);
  const simplified = simplifyLines(shown.map(({ l }) => l), tgap);
  return { rules: shown.map(({ rule }) => rule), pruned, simplified };
}

/**
 * The lines of generalizedLines in the cube's z, in the order collapseLines gives them, without
 * the vertices gone by the state a line is born in: a line is drawn from that state on, each
 * vertex while its state lasts (linePathsAtZ), so those are never drawn (on bgt_otterlo_1800m
 * 51,957 of 80,031 vertices, simplified away at scales where the line was still an area).
 */
export function cubeLines(tgap: Tgap, style: Pick<Style, 'classes' | 'lineRules'>): LineRecord[] {
  const steps = tgap.meta.steps;
  const { simplified, rules } = generalizedLines(tgap, style);
  return simplified.lines.map((l, i) => {
    const drawn = l.vertexEnd.map((ends) => [...ends.keys()].filter((j) => ends[j]! > l.step));
    return {
      classIndex: l.classIndex,
      rule: rules[i]!,
      feature: l.feature,
      zStart: phaseZ(l.step, 0),
      zEnd: stateEndZ(l.prunedStep, steps),
      paths: drawn.map((js, k) => Float64Array.from(js.flatMap((j) => [l.paths[k]![2 * j]!, l.paths[k]![2 * j + 1]!]))),
      leaveZ: drawn.map((js, k) => Float64Array.from(js, (j) => stateEndZ(l.vertexEnd[k]![j]!, steps))),
    };
  });
}

export interface LineChunk {
  bytes: Uint8Array;
  bbox: Box3;
  lines: number;
}

/** Bytes of a line's records in a line chunk before compression (docs/FORMAT.md), what the reader expands it to. */
function lineBytes(l: LineRecord): number {
  let vertices = 0;
  for (const p of l.paths) vertices += p.length / 2;
  return 20 + 4 * l.paths.length + 12 * vertices;
}

/**
 * Lines into chunks of nearly `targetBytes`, split where views are least likely to need both
 * sides; lines keep their order within a chunk. Positions on the cube's grid (`gridExponent`).
 */
export function lineChunks(lines: readonly LineRecord[], view: ViewModel & { targetBytes: number }, gridExponent?: number): LineChunk[] {
  if (lines.length === 0) return [];
  const n = lines.length;
  const boxes: TriangleBoxes = {
    x0: new Float64Array(n), y0: new Float64Array(n), x1: new Float64Array(n), y1: new Float64Array(n),
    z0: new Float64Array(n), z1: new Float64Array(n),
  };
  lines.forEach((l, i) => {
    [boxes.x0[i], boxes.y0[i], boxes.x1[i], boxes.y1[i]] = groundBox(l.paths);
    boxes.z0[i] = l.zStart;
    boxes.z1[i] = l.zEnd;
  });
  const { chunkOf, start } = splitEvenly(boxes, Float64Array.from(lines, lineBytes), view);
  const members: LineRecord[][] = Array.from({ length: start.length - 1 }, () => []);
  lines.forEach((l, i) => members[chunkOf[i]!]!.push(l));
  return members.filter((m) => m.length > 0).map((m) => ({ ...encodeLineChunk(m, gridExponent), lines: m.length }));
}
