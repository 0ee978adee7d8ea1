// The slicing surfaces of surfaces.ts rewritten around the view centre, for the GPU: whatever
// involves absolute (national grid) coordinates is done here in float64, so the shader works
// with offsets of at most a screen's ground size and float32 is precise enough.
// `relativeZ` is the shader's formula in JavaScript (client/shaders/surface.frag), for tests.
import type { Surface } from '../../../format/slicing-surface.js';

export const MAX_IDW_POINTS = 64;

export interface SurfaceParams {
  /** 0 flat, 1 tilted, 2 sine, 3 lens, 4 idw */
  kind: number;
  base: number;
  /**
   * tilted: z at the view centre, dzdx, dzdy, 0
   * sine:   phase at the view centre (mod 2 pi), d phase / dx, d phase / dy, amplitude
   * lens:   view centre minus lens centre (x, y), radius, depth
   */
  p: [number, number, number, number];
  power: number;
  /** idw: x, y relative to the view centre, z; per point. */
  points: Float32Array;
  count: number;
}

export function surfaceParams(s: Surface, centerX: number, centerY: number): SurfaceParams {
  const out: SurfaceParams = { kind: 0, base: s.base, p: [0, 0, 0, 0], power: 2, points: new Float32Array(0), count: 0 };
  const q = s.spec;
  switch (q.kind) {
    case 'flat':
      break;
    case 'tilted':
      out.kind = 1;
      out.p = [s.base + q.dzdx * (centerX - q.cx) + q.dzdy * (centerY - q.cy), q.dzdx, q.dzdy, 0];
      break;
    case 'sine': {
      out.kind = 2;
      const a = (q.angle * Math.PI) / 180;
      const kx = (2 * Math.PI * Math.cos(a)) / q.wavelength;
      const ky = (2 * Math.PI * Math.sin(a)) / q.wavelength;
      // sin(2 pi (x cos a + y sin a) / wavelength) at the centre, as a phase in [0, 2 pi).
      const phase = (2 * Math.PI * (centerX * Math.cos(a) + centerY * Math.sin(a))) / q.wavelength;
      out.p = [phase - 2 * Math.PI * Math.floor(phase / (2 * Math.PI)), kx, ky, q.amplitude];
      break;
    }
    case 'lens':
      out.kind = 3;
      out.p = [centerX - q.cx, centerY - q.cy, q.radius, q.depth];
      break;
    case 'idw': {
      out.kind = 4;
      out.power = q.power;
      const n = Math.min(q.points.length, MAX_IDW_POINTS);
      out.points = new Float32Array(3 * n);
      for (let i = 0; i < n; i++) {
        const pt = q.points[i]!;
        out.points[3 * i] = pt.x - centerX;
        out.points[3 * i + 1] = pt.y - centerY;
        out.points[3 * i + 2] = pt.z;
      }
      out.count = n;
      break;
    }
  }
  return out;
}

/**
 * The slice's one z (float32, clamped to [0, zMax] as surface.frag clamps) when it is flat, else
 * null: the passes then take it as a uniform instead of reading the surface target per pixel.
 */
export function flatSliceZ(s: Surface, zMax: number): number | null {
  return s.spec.kind === 'flat' ? Math.fround(Math.min(Math.max(s.base, 0), zMax)) : null;
}

/** z at offset (dx, dy) from the view centre, as surface.frag computes it (before clamping). */
export function relativeZ(sp: SurfaceParams, dx: number, dy: number): number {
  const p = sp.p;
  switch (sp.kind) {
    case 1:
      return p[0] + p[1] * dx + p[2] * dy;
    case 2:
      return sp.base + p[3] * Math.sin(p[0] + p[1] * dx + p[2] * dy);
    case 3: {
      const qx = dx + p[0], qy = dy + p[1];
      const d2 = qx * qx + qy * qy, r2 = p[2] * p[2];
      if (d2 >= r2) return sp.base;
      const t = 1 - d2 / r2;
      return sp.base - p[3] * t * t;
    }
    case 4: {
      if (sp.count === 0) return sp.base;
      let sw = 0, sz = 0;
      for (let i = 0; i < sp.count; i++) {
        const qx = dx - sp.points[3 * i]!, qy = dy - sp.points[3 * i + 1]!;
        const d2 = qx * qx + qy * qy;
        if (d2 === 0) return sp.points[3 * i + 2]!;
        const w = 1 / Math.pow(d2, sp.power / 2);
        sw += w;
        sz += w * sp.points[3 * i + 2]!;
      }
      return sz / sw;
    }
    default:
      return sp.base;
  }
}
