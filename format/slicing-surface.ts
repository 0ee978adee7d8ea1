// Slicing surfaces: z (the step, i.e. the level of detail) as a function of the ground
// position, and their text form ("kind:key=value,...", what `ssc slice --surface` and the map's
// URL take; parseSurface reads it, formatSurface writes it so that numbers read back exactly).
// The CPU reference slicer and the map use these same definitions; the GPU version of each
// must agree with them (tests compare the two).

export type SurfaceSpec =
  | { kind: 'flat' }
  | { kind: 'tilted'; cx: number; cy: number; dzdx: number; dzdy: number }
  | { kind: 'sine'; amplitude: number; wavelength: number; angle: number }
  | { kind: 'lens'; cx: number; cy: number; radius: number; depth: number }
  | { kind: 'idw'; points: { x: number; y: number; z: number }[]; power: number };

/** A surface around a base z (from the scale of the view): every kind adds to or replaces it. */
export interface Surface {
  base: number;
  spec: SurfaceSpec;
}

/**
 * z at ground point (x, y), clamped to [0, zMax].
 * - flat:   base
 * - tilted: base + dzdx (x - cx) + dzdy (y - cy)                  (a plane through (cx, cy, base))
 * - sine:   base + amplitude sin(2 pi (x cos a + y sin a) / wavelength), a in degrees
 * - lens:   base - depth (1 - d^2 / r^2)^2 for d < r, else base    (more detail around (cx, cy))
 * - idw:    sum(w_i z_i) / sum(w_i), w_i = 1 / d_i^power          (z_i at a control point itself)
 */
export function surfaceZ(s: Surface, x: number, y: number, zMax: number): number {
  const z = rawZ(s, x, y);
  return z < 0 ? 0 : z > zMax ? zMax : z;
}

function rawZ(s: Surface, x: number, y: number): number {
  const p = s.spec;
  switch (p.kind) {
    case 'flat':
      return s.base;
    case 'tilted':
      return s.base + p.dzdx * (x - p.cx) + p.dzdy * (y - p.cy);
    case 'sine': {
      const a = (p.angle * Math.PI) / 180;
      return s.base + p.amplitude * Math.sin((2 * Math.PI * (x * Math.cos(a) + y * Math.sin(a))) / p.wavelength);
    }
    case 'lens': {
      const d2 = (x - p.cx) ** 2 + (y - p.cy) ** 2;
      const r2 = p.radius * p.radius;
      if (d2 >= r2) return s.base;
      const t = 1 - d2 / r2;
      return s.base - p.depth * t * t;
    }
    case 'idw': {
      if (p.points.length === 0) return s.base;
      let sw = 0, sz = 0;
      for (const q of p.points) {
        const d2 = (x - q.x) ** 2 + (y - q.y) ** 2;
        if (d2 === 0) return q.z;
        const w = 1 / Math.pow(d2, p.power / 2);
        sw += w;
        sz += w * q.z;
      }
      return sz / sw;
    }
  }
}

/** The lowest and highest z of the surface over a ground box (for choosing chunks). */
export function surfaceRange(s: Surface, bbox: [number, number, number, number], zMax: number): [number, number] {
  const p = s.spec;
  const clamp = (z: number): number => (z < 0 ? 0 : z > zMax ? zMax : z);
  switch (p.kind) {
    case 'flat':
      return [clamp(s.base), clamp(s.base)];
    case 'tilted': {
      const zs = [
        [bbox[0], bbox[1]], [bbox[2], bbox[1]], [bbox[0], bbox[3]], [bbox[2], bbox[3]],
      ].map(([x, y]) => surfaceZ(s, x!, y!, zMax));
      return [Math.min(...zs), Math.max(...zs)];
    }
    case 'sine':
      return [clamp(s.base - Math.abs(p.amplitude)), clamp(s.base + Math.abs(p.amplitude))];
    case 'lens':
      return [clamp(Math.min(s.base, s.base - p.depth)), clamp(Math.max(s.base, s.base - p.depth))];
    case 'idw': {
      if (p.points.length === 0) return [clamp(s.base), clamp(s.base)];
      const zs = p.points.map((q) => q.z);
      return [clamp(Math.min(...zs)), clamp(Math.max(...zs))];
    }
  }
}

/**
 * Parses "kind:key=value,key=value" (e.g. "lens:cx=181200,cy=456900,radius=100,depth=200");
 * idw points are "idw:power=2,points=x y z;x y z". Throws an Error naming what is wrong.
 */
export function parseSurface(text: string): SurfaceSpec {
  const [kind, rest = ''] = text.split(/:(.*)/s, 2) as [string, string?];
  const kv = new Map<string, string>();
  for (const part of rest.split(',').map((s) => s.trim()).filter(Boolean)) {
    const m = /^([a-z]+)=(.*)$/i.exec(part);
    if (!m) throw new Error(`surface: expected key=value, got ${JSON.stringify(part)}`);
    kv.set(m[1]!, m[2]!);
  }
  const num = (k: string, dflt?: number): number => {
    const v = kv.get(k);
    if (v === undefined) {
      if (dflt !== undefined) return dflt;
      throw new Error(`surface ${kind}: ${k}= is required`);
    }
    const n = Number(v);
    if (!Number.isFinite(n)) throw new Error(`surface ${kind}: ${k} must be a number, got ${JSON.stringify(v)}`);
    return n;
  };
  let spec: SurfaceSpec;
  switch (kind) {
    case 'flat':
      spec = { kind };
      break;
    case 'tilted':
      spec = { kind, cx: num('cx'), cy: num('cy'), dzdx: num('dzdx', 0), dzdy: num('dzdy', 0) };
      break;
    case 'sine':
      spec = { kind, amplitude: num('amplitude'), wavelength: num('wavelength'), angle: num('angle', 0) };
      if (spec.wavelength <= 0) throw new Error('surface sine: wavelength must be > 0');
      break;
    case 'lens':
      spec = { kind, cx: num('cx'), cy: num('cy'), radius: num('radius'), depth: num('depth') };
      if (spec.radius <= 0) throw new Error('surface lens: radius must be > 0');
      break;
    case 'idw': {
      const pts = (kv.get('points') ?? '').split(';').map((s) => s.trim()).filter(Boolean).map((s) => {
        const [x, y, z] = s.split(/\s+/).map(Number);
        if (![x, y, z].every((v) => Number.isFinite(v))) throw new Error(`surface idw: point ${JSON.stringify(s)} must be "x y z"`);
        return { x: x!, y: y!, z: z! };
      });
      if (pts.length === 0) throw new Error('surface idw: points=x y z;x y z;... is required');
      spec = { kind, points: pts, power: num('power', 2) };
      break;
    }
    default:
      throw new Error(`surface: unknown kind ${JSON.stringify(kind)} (flat, tilted, sine, lens, idw)`);
  }
  for (const k of kv.keys()) {
    if (!(k in spec) && !(kind === 'idw' && k === 'points')) throw new Error(`surface ${kind}: unknown key ${JSON.stringify(k)}`);
  }
  return spec;
}

export function formatSurface(spec: SurfaceSpec): string {
  const n = (v: number): string => String(v);
  switch (spec.kind) {
    case 'flat':
      return 'flat';
    case 'tilted':
      return `tilted:cx=${n(spec.cx)},cy=${n(spec.cy)},dzdx=${n(spec.dzdx)},dzdy=${n(spec.dzdy)}`;
    case 'sine':
      return `sine:amplitude=${n(spec.amplitude)},wavelength=${n(spec.wavelength)},angle=${n(spec.angle)}`;
    case 'lens':
      return `lens:cx=${n(spec.cx)},cy=${n(spec.cy)},radius=${n(spec.radius)},depth=${n(spec.depth)}`;
    case 'idw':
      return `idw:power=${n(spec.power)},points=${spec.points.map((p) => `${n(p.x)} ${n(p.y)} ${n(p.z)}`).join(';')}`;
  }
}
