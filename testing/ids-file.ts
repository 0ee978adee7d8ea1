// The raw face-id files that `ssc map --ids` and `ssc slice --ids` write.
import { readFileSync } from 'node:fs';

/** Little-endian uint32 per pixel, row by row from the top. */
export function readIds(file: string): Uint32Array {
  const b = readFileSync(file);
  return new Uint32Array(b.buffer.slice(b.byteOffset, b.byteOffset + b.byteLength));
}
