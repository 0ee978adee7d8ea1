// Which line network each class's lines belong to: its own, unless the style joins it to
// another linear class's (`network`, format/style.ts: a bridge deck carrying a road). Classes
// linked that way, directly or through others, are one network, numbered by its first class.
import type { StyleClass } from '../../format/style.js';

export function classNetworks(classes: readonly Pick<StyleClass, 'key' | 'network'>[]): Int32Array {
  const index = new Map(classes.map((c, i) => [c.key, i]));
  const parent = Int32Array.from(classes, (_, i) => i);
  const root = (i: number): number => {
    while (parent[i] !== i) i = parent[i] = parent[parent[i]!]!;
    return i;
  };
  classes.forEach((c, i) => {
    const to = c.network === undefined ? undefined : index.get(c.network);
    if (to === undefined) return;
    const [a, b] = [root(i), root(to)];
    // The smaller index is the root: the network is numbered by its first class.
    if (a < b) parent[b] = a;
    else parent[a] = b;
  });
  return Int32Array.from(classes, (_, i) => root(i));
}
