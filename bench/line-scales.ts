// The lines that pruning (issue 12, item 2) leaves at a few scales, for bench:lines: per
// linear class, the lines shown, their length and density on the map, and the pieces they
// form, alone and with the areas not yet collapsed (standing in as the lines they become);
// the vertices they have in full and simplified (simplify-lines.ts); and whether each class's
// main network is one piece at every state it is shown.
import { scaleAtZ, zAtScale } from '../format/scale.js';
import { scaleInfoOf, type Tgap } from '../format/tgap-model.js';
import { mapDensity } from '../preprocess/lines/line-budget.js';
import { mainPiece, pieceLabels, pointIds } from '../preprocess/lines/line-components.js';
import type { PrunedLine } from '../preprocess/lines/prune-lines.js';
import { linePathsAt, type SimplifiedLine } from '../preprocess/lines/simplify-lines.js';
import type { Style } from '../preprocess/style.js';

export const LINE_SCALE_HEADER = ['dataset', 'scale', 'state', 'class', 'lines', 'length km', 'mm/mm²', 'pieces', 'with areas', 'main net pieces', 'with areas', 'vertices', 'simplified'];

/** A class's lines (or all), its main network, and each line's points as ids for counting pieces. */
interface LineGroup<L extends PrunedLine> {
  name: string;
  lines: L[];
  main: Set<L>;
  ids: Map<L, Int32Array>;
}

function groupsOf<L extends PrunedLine>(style: Pick<Style, 'classes'>, lines: L[]): LineGroup<L>[] {
  const group = (name: string, mine: L[]): LineGroup<L> => {
    // Each line as one point set: its polylines meet inside it.
    const ids = pointIds(mine.map((l) => l.paths.flatMap((p) => Array.from(p))));
    return { name, lines: mine, main: new Set(mainPiece(mine)), ids: new Map(mine.map((l, i) => [l, ids[i]!])) };
  };
  const out: LineGroup<L>[] = [];
  style.classes.forEach((c, ci) => {
    const mine = lines.filter((l) => l.classIndex === ci);
    if (mine.length > 0) out.push(group(c.key, mine));
  });
  out.push(group('all', lines));
  return out;
}

const shownAt = (s: number) => (l: PrunedLine): boolean => l.step <= s && l.prunedStep > s;
/** Lines shown at s, and those not yet born, whose areas carry the network until then. */
const networkAt = (s: number) => (l: PrunedLine): boolean => l.prunedStep > s;

function pieces<L extends PrunedLine>(g: LineGroup<L>, keep: (l: L) => boolean, mainOnly: boolean): number {
  const ids = g.lines.filter((l) => keep(l) && (!mainOnly || g.main.has(l))).map((l) => g.ids.get(l)!);
  return new Set(pieceLabels(ids)).size;
}

const vertices = (paths: ArrayLike<number>[]): number => paths.reduce((sum, p) => sum + p.length / 2, 0);

/** Rows of LINE_SCALE_HEADER at the base scale and the given scale denominators. */
export function lineScaleRows(name: string, tgap: Tgap, style: Pick<Style, 'classes'>, lines: SimplifiedLine[], scales: number[]): string[][] {
  const info = scaleInfoOf(tgap);
  const [x0, y0, x1, y1] = tgap.meta.extent;
  const area = (x1 - x0) * (y1 - y0);
  const groups = groupsOf(style, lines);
  const rows: string[][] = [];
  for (const s of [0, ...scales.map((sc) => Math.floor(zAtScale(info, sc)))]) {
    const scale = scaleAtZ(info, s);
    for (const g of groups) {
      const shown = g.lines.filter(shownAt(s));
      const m = shown.reduce((sum, l) => sum + l.length, 0);
      rows.push([
        name, s === 0 ? 'base' : `1:${Math.round(scale)}`, String(s), g.name, String(shown.length), (m / 1000).toFixed(2), mapDensity(m, area, scale).toFixed(4),
        String(pieces(g, shownAt(s), false)), String(pieces(g, networkAt(s), false)), String(pieces(g, shownAt(s), true)), String(pieces(g, networkAt(s), true)),
        String(shown.reduce((sum, l) => sum + vertices(l.paths), 0)), String(shown.reduce((sum, l) => sum + vertices(linePathsAt(l, s)), 0)),
      ]);
    }
  }
  return rows;
}

/**
 * Per linear class: states at which some of its main network is shown as lines, and how many of
 * those find it (lines with the areas not yet collapsed) in more than one piece. The network
 * only loses lines where one is pruned, so those states are the ones checked. `lines` are all
 * the pruned lines, those pruned at birth too: until then they stand in for their areas, which
 * the map shows.
 */
export function mainNetworkSplits(tgap: Tgap, style: Pick<Style, 'classes'>, lines: PrunedLine[]): { cls: string; shownStates: number; checked: number; split: number }[] {
  return groupsOf(style, lines).filter((g) => g.name !== 'all').map((g) => {
    const main = [...g.main];
    const shown = (s: number): boolean => main.some(shownAt(s));
    let shownStates = 0;
    for (let s = 0; s <= tgap.meta.steps; s++) if (shown(s)) shownStates++;
    let checked = 0, split = 0;
    for (const s of new Set(main.map((l) => l.prunedStep))) {
      if (s > tgap.meta.steps || !shown(s)) continue;
      checked++;
      if (pieces(g, networkAt(s), true) > 1) split++;
    }
    return { cls: g.name, shownStates, checked, split };
  });
}
