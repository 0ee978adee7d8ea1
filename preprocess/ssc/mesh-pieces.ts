// The connected pieces of a triangle list: triangles that share a vertex lie in one piece, as a
// front along the triangles' edges (smooth-merge.ts) passes from one to the other there.

/** Per piece of `tris` (vertex ids, 3 per triangle), its vertices, in the order first seen. */
export function meshPieces(tris: ArrayLike<number>): number[][] {
  const parent = new Map<number, number>();
  const root = (v: number): number => {
    let r = v;
    while (parent.get(r) !== r) r = parent.get(r)!;
    // Path compression: later lookups take one hop.
    for (let w = v; w !== r; ) {
      const next = parent.get(w)!;
      parent.set(w, r);
      w = next;
    }
    return r;
  };
  for (let i = 0; i < tris.length; i++) if (!parent.has(tris[i]!)) parent.set(tris[i]!, tris[i]!);
  for (let i = 0; i + 2 < tris.length; i += 3) {
    const a = root(tris[i]!);
    for (const w of [tris[i + 1]!, tris[i + 2]!]) {
      const b = root(w);
      if (a !== b) parent.set(b, a);
    }
  }
  const byRoot = new Map<number, number[]>();
  for (const v of parent.keys()) {
    const r = root(v);
    let l = byRoot.get(r);
    if (!l) byRoot.set(r, (l = []));
    l.push(v);
  }
  return [...byRoot.values()];
}
