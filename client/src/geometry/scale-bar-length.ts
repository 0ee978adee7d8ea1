// The scale bar's length: the longest round ground distance (1, 2 or 5 times a power of ten)
// that fits in the bar's maximum width, and how to write scales and distances.

/** Ground length (units) and its width in CSS px for a bar of at most `maxPx` at `res` units/px. */
export function scaleBarLength(res: number, maxPx: number): { length: number; px: number } {
  const max = res * maxPx;
  const pow = Math.pow(10, Math.floor(Math.log10(max)));
  const m = max / pow;
  const nice = m >= 5 ? 5 : m >= 2 ? 2 : 1;
  const length = nice * pow;
  return { length, px: length / res };
}

export function formatDistance(metres: number): string {
  return metres >= 1000 ? `${+(metres / 1000).toPrecision(3)} km` : `${+metres.toPrecision(3)} m`;
}

/** The denominator as written: rounded to three significant digits. */
function roundScale(denominator: number): number {
  return Math.round(Number(denominator.toPrecision(3)));
}

/** "1:25 000": digits grouped by thin spaces, rounded to three significant digits. */
export function formatScale(denominator: number): string {
  return `1:${String(roundScale(denominator)).replace(/\B(?=(\d{3})+(?!\d))/g, '\u202f')}`;
}

/** "Scale 1:25,000" for screen readers: they read comma groups as one number, thin spaces not. */
export function spokenScale(denominator: number): string {
  return `Scale 1:${roundScale(denominator).toLocaleString('en-US')}`;
}
