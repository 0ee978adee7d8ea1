// A point against a segment: where its perpendicular foot falls, and how far away it is. In
// format/ so that the build, the map (picking, overlays, line glides) and the tests share it.

/** Parameter in [0, 1] of the point of segment a-b nearest to p (0 for a segment of no length). */
export function projectOnSegment(px: number, py: number, ax: number, ay: number, bx: number, by: number): number {
  const dx = bx - ax, dy = by - ay;
  const l2 = dx * dx + dy * dy;
  return l2 === 0 ? 0 : Math.max(0, Math.min(1, ((px - ax) * dx + (py - ay) * dy) / l2));
}

/** Distance from p to the closed segment a-b. */
export function pointSegmentDistance(px: number, py: number, ax: number, ay: number, bx: number, by: number): number {
  const t = projectOnSegment(px, py, ax, ay, bx, by);
  return Math.hypot(px - ax - t * (bx - ax), py - ay - t * (by - ay));
}
