// How many connected pieces a set of lines forms: polylines that share a point (exactly the
// same coordinates) are connected. Lines of a network meet at ports, so this counts how far
// the network has come apart.

/** Connected pieces among the polylines (flat x, y pairs). */
export function lineComponents(paths: readonly ArrayLike<number>[]): number {
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
  let n = 0;
  parent.forEach((_, i) => {
    if (find(i) === i) n++;
  });
  return n;
}
