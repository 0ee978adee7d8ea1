// The JavaScript gzip decoder and CRC-32 that gunzip.ts falls back on where the platform has
// no DecompressionStream, in a module of their own: gunzip.ts imports it only then, and only
// what is used here goes into the bundle (an import() of fflate itself keeps all of it).
import CRC32 from 'crc-32';

export { gunzipSync as inflateGzip } from 'fflate';

/** The unsigned CRC-32 of the bytes. */
export const crc32 = (bytes: Uint8Array): number => CRC32.buf(bytes) >>> 0;
