// Lines whose style draws nothing (a linear class without `line`, a rule of width 0) are left
// out before pruning: they take no share of the map's line budget and are not stored. The
// joins of the lines kept are renumbered; a join to a line left out becomes a join to no line
// (-1), as where the area across never became a line.
import type { LineObject } from './collapse-lines.js';

/** The lines with `keep[i]` set, in order, their joins renumbered. */
export function keepLines<T extends LineObject>(lines: readonly T[], keep: ArrayLike<boolean>): T[] {
  const index = new Int32Array(lines.length).fill(-1);
  let n = 0;
  lines.forEach((_, i) => {
    if (keep[i]) index[i] = n++;
  });
  return lines.filter((_, i) => keep[i]).map((l) => ({ ...l, joins: l.joins.map((j) => ({ ...j, line: j.line >= 0 ? index[j.line]! : -1 })) }));
}
