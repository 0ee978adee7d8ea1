// A surface as text ("kind:key=value,..."), the form parseSurface in surfaces.ts reads and
// `ssc slice --surface` takes. Numbers are written so they read back exactly.
import type { SurfaceSpec } from './surfaces.js';

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
