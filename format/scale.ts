// Scale denominators and z (steps) of a cube: a constant number of faces per map area, with
// the number of faces alive read from the cube's scale table (linear between knots).

export interface ScaleInfo {
  baseScale: number;
  baseFaces: number;
  /** [step, facesAlive] knots in increasing step order. */
  scaleTable: [number, number][];
  zMax: number;
}

export function facesAliveAt(info: ScaleInfo, z: number): number {
  const t = info.scaleTable;
  if (z <= t[0]![0]) return t[0]![1];
  for (let i = 1; i < t.length; i++) {
    const [s1, f1] = t[i]!;
    if (z <= s1) {
      const [s0, f0] = t[i - 1]!;
      return s1 === s0 ? f1 : f0 + ((z - s0) / (s1 - s0)) * (f1 - f0);
    }
  }
  return t[t.length - 1]![1];
}

/**
 * The scale denominator at which `facesAlive` faces are shown, when `baseFaces` are shown at
 * `baseScale`: a constant number of faces per map area, St = Sb sqrt(Nb / Nt).
 */
export function scaleOfFaces(baseScale: number, baseFaces: number, facesAlive: number): number {
  return baseScale * Math.sqrt(baseFaces / Math.max(1, facesAlive));
}

export function scaleAtZ(info: ScaleInfo, z: number): number {
  return scaleOfFaces(info.baseScale, info.baseFaces, facesAliveAt(info, z));
}

/** The z showing the given scale denominator (clamped to the cube). */
export function zAtScale(info: ScaleInfo, scale: number): number {
  const alive = info.baseFaces * (info.baseScale / Math.max(scale, 1e-9)) ** 2;
  const t = info.scaleTable;
  if (alive >= t[0]![1]) return t[0]![0];
  for (let i = 1; i < t.length; i++) {
    const [s0, f0] = t[i - 1]!;
    const [s1, f1] = t[i]!;
    if (alive >= f1) return f0 === f1 ? s0 : s0 + ((f0 - alive) / (f0 - f1)) * (s1 - s0);
  }
  return Math.min(info.zMax, t[t.length - 1]![0]);
}

/** Compresses a per-step facesAlive array to the knots where its slope changes. */
export function scaleKnots(facesAlive: number[]): [number, number][] {
  const n = facesAlive.length;
  if (n === 0) return [[0, 1]];
  const out: [number, number][] = [[0, facesAlive[0]!]];
  for (let s = 1; s < n - 1; s++) {
    const d0 = facesAlive[s]! - facesAlive[s - 1]!, d1 = facesAlive[s + 1]! - facesAlive[s]!;
    if (d0 !== d1) out.push([s, facesAlive[s]!]);
  }
  if (n > 1) out.push([n - 1, facesAlive[n - 1]!]);
  return out;
}
