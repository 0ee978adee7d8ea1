// Lines meet only at exactly equal coordinates (ports, anchors, junctions inside a line), so
// points are compared by a key of their coordinates.

export const pointKey = (x: number, y: number): string => `${x},${y}`;

/** How many vertices of the polylines (flat x, y pairs) lie at each point. */
export function pointUses(paths: readonly ArrayLike<number>[]): Map<string, number> {
  const uses = new Map<string, number>();
  for (const p of paths) {
    for (let k = 0; k < p.length; k += 2) {
      const key = pointKey(p[k]!, p[k + 1]!);
      uses.set(key, (uses.get(key) ?? 0) + 1);
    }
  }
  return uses;
}
