// The smoothness figure of one frame of a zoom (docs: DESIGN.md, "What the map is judged by"):
// of the pixels that show a face in both frames, how many show another class. Pixels with no
// face in either frame (outside the data) say nothing about how the map changes.

/** One frame's face id (0: none) and class per pixel, as the CPU slicer leaves them. */
export interface ClassFrame {
  ids: ArrayLike<number>;
  classes: ArrayLike<number>;
}

export interface ClassChange {
  /** Pixels with a face in both frames. */
  domain: number;
  /** Of those, the pixels whose class differs. */
  changed: number;
}

export function classChange(before: ClassFrame, after: ClassFrame): ClassChange {
  const n = before.ids.length;
  if (after.ids.length !== n || before.classes.length !== n || after.classes.length !== n) {
    throw new Error(`frames of different sizes: ${n} and ${after.ids.length} pixels`);
  }
  let domain = 0, changed = 0;
  for (let p = 0; p < n; p++) {
    if (before.ids[p] === 0 || after.ids[p] === 0) continue;
    domain++;
    if (before.classes[p] !== after.classes[p]) changed++;
  }
  return { domain, changed };
}

/** changed / domain (0 when no pixel is in the domain: nothing shown, nothing changed). */
export function changeShare(c: ClassChange): number {
  return c.domain === 0 ? 0 : c.changed / c.domain;
}
