// Only the inside-facing sides of the cube's surfaces are drawn: triangles counterclockwise seen
// from above (the polyhedron above looks down at them). They are chosen here, exactly, from the
// file's coordinates, not by the GPU's face culling: a GPU decides the winding after snapping
// the vertices to its sub-pixel grid, which flips long sliver triangles now and then and would
// leave holes where they were. Pure.

/**
 * Moves the triangles that face up (positive area seen from above) to the front of `indices`,
 * in their order, and returns how many there are. Down-facing and degenerate ones are dropped.
 */
export function keepUpwardTriangles(positions: Float32Array, indices: Uint16Array | Uint32Array): number {
  let kept = 0;
  for (let t = 0; t < indices.length; t += 3) {
    const a = indices[t]!, b = indices[t + 1]!, c = indices[t + 2]!;
    const ax = positions[3 * a]!, ay = positions[3 * a + 1]!;
    const area = (positions[3 * b]! - ax) * (positions[3 * c + 1]! - ay) - (positions[3 * b + 1]! - ay) * (positions[3 * c]! - ax);
    if (!(area > 0)) continue;
    if (kept !== t) {
      indices[kept] = a;
      indices[kept + 1] = b;
      indices[kept + 2] = c;
    }
    kept += 3;
  }
  return kept / 3;
}
