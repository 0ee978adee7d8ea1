// A PNG of keys under lines (face ids, classes): where a line is painted its colour
// (draw-lines.ts), elsewhere the colour of the key below (0: transparent).
import type { LineRule } from '../../format/line-style.js';
import { linePaintColour, type LinePaint } from './draw-lines.js';
import { idsToPng } from './render-png.js';

/** Keys above every key below: the line's paint. */
const LINE_KEY = 0x80000000;

export function pngWithLines(below: ArrayLike<number>, linePaint: LinePaint, rules: readonly LineRule[], width: number, height: number, colourBelow: (key: number) => string | undefined): Uint8Array {
  const keys = new Uint32Array(width * height);
  for (let p = 0; p < keys.length; p++) keys[p] = linePaint[p] ? LINE_KEY + linePaint[p]! : below[p]!;
  return idsToPng(keys, width, height, (k) => (k > LINE_KEY ? linePaintColour(rules, k - LINE_KEY) : colourBelow(k)) ?? '#ff00ff');
}
