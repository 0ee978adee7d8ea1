// How many connected pieces a set of lines forms: polylines that share a point (exactly the
// same coordinates) are connected. Lines of a network meet at ports, so this counts how far
// the network has come apart.
import { pointKey } from './point-uses.js';

/**
 * The piece of every polyline (flat x, y pairs), numbered from 0 in order of first polyline.
 * Only points count, not segments: a line's polylines may be given as one array.
 */
export function lineComponentLabels(paths: readonly ArrayLike<number>[]): Int32Array {
  return pieceLabels(pointIds(paths));
}

/**
 * Every polyline's points as ids, equal where the coordinates are: computed once, they let
 * `pieceLabels` count the pieces of many subsets of the same lines quickly.
 */
export function pointIds(paths: readonly ArrayLike<number>[]): Int32Array[] {
  const id = new Map<string, number>();
  return paths.map((p) => {
    const out = new Int32Array(p.length / 2);
    for (let k = 0; k < p.length; k += 2) {
      const key = pointKey(p[k]!, p[k + 1]!);
      let i = id.get(key);
      if (i === undefined) id.set(key, (i = id.size));
      out[k / 2] = i;
    }
    return out;
  });
}

/** `lineComponentLabels` of polylines given by `pointIds`. */
export function pieceLabels(ids: readonly Int32Array[]): Int32Array {
  const parent = ids.map((_, i) => i);
  const find = (i: number): number => {
    while (parent[i] !== i) {
      parent[i] = parent[parent[i]!]!;
      i = parent[i]!;
    }
    return i;
  };
  let points = 0;
  for (const p of ids) for (const v of p) points = Math.max(points, v + 1);
  const owner = new Int32Array(points).fill(-1);
  ids.forEach((p, i) => {
    for (const v of p) {
      const o = owner[v]!;
      if (o < 0) owner[v] = i;
      else parent[find(o)] = find(i);
    }
  });
  const label = new Map<number, number>();
  return Int32Array.from(ids, (_, i) => {
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

/**
 * The lines of the largest piece (by length) among the given lines, each line's polylines
 * taken together: a class's main network. Ties go to the piece of the earliest line.
 */
export function mainPiece<L extends { paths: readonly ArrayLike<number>[]; length: number }>(lines: readonly L[]): L[] {
  const label = lineComponentLabels(lines.map((l) => l.paths.flatMap((p) => Array.from(p))));
  const size: number[] = [];
  label.forEach((c, i) => (size[c] = (size[c] ?? 0) + lines[i]!.length));
  let best = 0;
  size.forEach((s, c) => {
    if (s > size[best]!) best = c;
  });
  return lines.filter((_, i) => label[i] === best);
}
