// The view as URL hash text, #x/y/scale: ground coordinates to about a pixel (fewer digits at
// smaller scales), the scale denominator rounded. Pure.

export function formatHash(center: [number, number], scale: number, pixelSizeMm: number): string {
  const res = (scale * pixelSizeMm) / 1000;
  const decimals = Math.min(6, Math.max(0, Math.ceil(-Math.log10(res))));
  return `#${center[0].toFixed(decimals)}/${center[1].toFixed(decimals)}/${Math.round(scale)}`;
}

export function parseHash(hash: string): { center: [number, number]; scaleDenominator: number } | null {
  const m = /^#?(-?[\d.]+)\/(-?[\d.]+)\/([\d.]+)$/.exec(hash);
  if (!m) return null;
  const x = Number(m[1]), y = Number(m[2]), s = Number(m[3]);
  return Number.isFinite(x) && Number.isFinite(y) && s > 0 ? { center: [x, y], scaleDenominator: s } : null;
}
