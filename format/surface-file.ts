// A surface file of either kind, told by its magic: a chunk file of triangles (chunk.ts) or a
// floor chunk file of boundaries (floor-chunk.ts). Both decode to the GPU's layout.
import { CHUNK_MAGIC, ChunkFormatError, decodeChunk, type DecodedChunk } from './chunk.js';
import { decodeFloorChunk, FLOOR_MAGIC } from './floor-chunk.js';

export function decodeSurfaceFile(input: Uint8Array | ArrayBuffer, name = 'chunk'): Promise<DecodedChunk> {
  const bytes = input instanceof Uint8Array ? input : new Uint8Array(input);
  const magic = bytes.byteLength >= 4 ? new DataView(bytes.buffer, bytes.byteOffset, 4).getUint32(0, true) : -1;
  if (magic === FLOOR_MAGIC) return decodeFloorChunk(bytes, name);
  if (magic === CHUNK_MAGIC || bytes.byteLength < 4) return decodeChunk(bytes, name);
  return Promise.reject(new ChunkFormatError(`${name}: neither a chunk nor a floor chunk file (bad magic)`));
}
