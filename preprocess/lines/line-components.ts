// How many connected pieces a set of lines forms: polylines that share a point (exactly the
// same coordinates) are connected. Lines of a network meet at ports, so this counts how far
// the network has come apart.

/**
 * The piece of every polyline (flat x, y pairs), numbered from 0 in order of first polyline.
 * Only points count, not segments: a line's polylines may be given as one array.
 */
export function lineComponentLabels(paths: readonly ArrayLike<number>[]): Int32Array {
  const parent = paths.map((_, i) => i);
  const find = (i: number): number => {
    while (parent[i] !== i) {
      parent[i] = parent[parent[i]!]!;
      i = parent[i]!;
    }
    return i;
  };
  const owner = new Map<string, number>();
  paths.forEach((p, i) => {
    for (let k = 0; k < p.length; k += 2) {
      const key = `${p[k]},${p[k + 1]}`;
      const o = owner.get(key);
      if (o === undefined) owner.set(key, i);
      else parent[find(o)] = find(i);
    }
  });
  const label = new Map<number, number>();
  return Int32Array.from(paths, (_, i) => {
    const r = find(i);
    let l = label.get(r);
    if (l === undefined) label.set(r, (l = label.size));
    return l;
  });
}

/** Connected pieces among the polylines (flat x, y pairs). */
export function lineComponents(paths: readonly ArrayLike<number>[]): number {
  return new Set(lineComponentLabels(paths)).size;
}
