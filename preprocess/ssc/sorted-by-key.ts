// A fast, deterministic argsort for millions of triangles.

/**
 * Indices 0..n-1 sorted by key, with a native numeric sort: the key, quantized to 2^26 levels
 * over its range, and the index are packed into one exact double (ties go by index).
 */
export function sortedBy(n: number, key: (i: number) => number): Uint32Array {
  const k = new Float64Array(n);
  let lo = Infinity, hi = -Infinity;
  for (let i = 0; i < n; i++) {
    const v = key(i);
    k[i] = v;
    if (v < lo) lo = v;
    if (v > hi) hi = v;
  }
  const levels = 67108863;
  const scale = hi > lo ? levels / (hi - lo) : 0;
  const packed = new Float64Array(n);
  for (let i = 0; i < n; i++) packed[i] = Math.min(levels, Math.floor((k[i]! - lo) * scale)) * 67108864 + i;
  packed.sort();
  const idx = new Uint32Array(n);
  for (let i = 0; i < n; i++) idx[i] = packed[i]! % 67108864;
  return idx;
}
