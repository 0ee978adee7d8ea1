// What the surfaces of a cube would weigh as one chunk file: every chunk's vertices merged
// where chunk borders split them apart (same place, z and faces), encoded as a chunk of its own.
// `ssc inspect` compares the chunks' bytes with it: what chunking costs.
import type { ChunkData } from '../../format/chunk.js';
import { encodeChunk } from '../../format/chunk-encode.js';

export function unchunkedBytes(chunks: Iterable<ChunkData>): number {
  const vertexOf = new Map<string, number>();
  const xs: number[] = [], ys: number[] = [], zs: number[] = [];
  const upper: number[] = [], lower: number[] = [], upperClass: number[] = [], lowerClass: number[] = [];
  const indices: number[] = [];
  let x0 = Infinity, y0 = Infinity, z0 = Infinity, x1 = -Infinity, y1 = -Infinity, z1 = -Infinity;
  for (const c of chunks) {
    const local = new Uint32Array(c.vertexCount);
    for (let v = 0; v < c.vertexCount; v++) {
      const x = c.originX + c.positions[3 * v]!, y = c.originY + c.positions[3 * v + 1]!, z = c.positions[3 * v + 2]!;
      const key = `${x},${y},${z},${c.upper[v]},${c.lower[v]}`;
      let k = vertexOf.get(key);
      if (k === undefined) {
        vertexOf.set(key, (k = xs.length));
        xs.push(x); ys.push(y); zs.push(z);
        upper.push(c.upper[v]!); lower.push(c.lower[v]!); upperClass.push(c.upperClass[v]!); lowerClass.push(c.lowerClass[v]!);
        x0 = Math.min(x0, x); x1 = Math.max(x1, x);
        y0 = Math.min(y0, y); y1 = Math.max(y1, y);
        z0 = Math.min(z0, z); z1 = Math.max(z1, z);
      }
      local[v] = k;
    }
    for (let i = 0; i < c.indices.length; i++) indices.push(local[c.indices[i]!]!);
  }
  if (xs.length === 0) return encodeChunk({ originX: 0, originY: 0, box: new Float32Array(6), positions: [], upper: [], lower: [], upperClass: [], lowerClass: [], indices: [] }).byteLength;
  // As a build would place it: a whole-unit origin at the smallest x, y.
  const ox = Math.floor(x0), oy = Math.floor(y0);
  const positions = new Float64Array(3 * xs.length);
  for (let k = 0; k < xs.length; k++) {
    positions[3 * k] = xs[k]! - ox;
    positions[3 * k + 1] = ys[k]! - oy;
    positions[3 * k + 2] = zs[k]!;
  }
  return encodeChunk({
    originX: ox, originY: oy, box: Float32Array.of(x0 - ox, y0 - oy, z0, x1 - ox, y1 - oy, z1), positions, upper, lower, upperClass, lowerClass, indices,
  }).byteLength;
}
