// Face ids to a PNG in the style's class colours.
import { PNG } from 'pngjs';

export function hexToRgb(hex: string): [number, number, number] {
  const v = parseInt(hex.slice(1), 16);
  return [(v >> 16) & 255, (v >> 8) & 255, v & 255];
}

/** `colourOf(face)` gives "#rrggbb"; face 0 (outside) is drawn transparent. */
export function idsToPng(ids: Uint32Array, width: number, height: number, colourOf: (face: number) => string): Uint8Array {
  const png = new PNG({ width, height });
  const cache = new Map<number, [number, number, number]>();
  const data = png.data;
  for (let p = 0; p < ids.length; p++) {
    const f = ids[p]!;
    if (f === 0) {
      data[4 * p + 3] = 0;
      continue;
    }
    let c = cache.get(f);
    if (!c) {
      c = hexToRgb(colourOf(f));
      cache.set(f, c);
    }
    data[4 * p] = c[0];
    data[4 * p + 1] = c[1];
    data[4 * p + 2] = c[2];
    data[4 * p + 3] = 255;
  }
  return PNG.sync.write(png);
}
