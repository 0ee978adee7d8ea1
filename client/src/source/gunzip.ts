// Bodies that are still gzip: a host that serves the precompressed copy of a file without a
// Content-Encoding header hands the client the gzip bytes themselves. Decompressed with the
// platform's DecompressionStream, or fflate where that is missing (with crc-32, 3 kB in the
// worker, where pako's inflate took 13 kB gzip). fflate checks neither the stored length nor
// the CRC: done here, as DecompressionStream and pako do, so a damaged body is refused. The two
// are imported only then: the map reads index.json on its main thread, and its bundle (which
// loads them as a file of their own) need not carry them for the few browsers that lack
// DecompressionStream.

/** Deflate's largest expansion: 258 bytes from one code of 2 bits, about 1032 to 1. */
const MAX_DEFLATE_RATIO = 1032;
/** The smallest gzip member: a 10-byte header, an empty deflate block of 2 bytes, the 8-byte trailer. */
const MIN_GZIP_BYTES = 20;

export function isGzip(bytes: ArrayBuffer): boolean {
  if (bytes.byteLength < 2) return false;
  const b = new Uint8Array(bytes, 0, 2);
  return b[0] === 0x1f && b[1] === 0x8b;
}

/** The bytes, decompressed when they are gzip. */
export async function gunzipIfNeeded(bytes: ArrayBuffer): Promise<ArrayBuffer> {
  if (!isGzip(bytes)) return bytes;
  if (typeof DecompressionStream === 'function') {
    const stream = new Blob([bytes]).stream().pipeThrough(new DecompressionStream('gzip'));
    return await new Response(stream).arrayBuffer();
  }
  return await gunzipWithoutStreams(bytes);
}

/**
 * Gzip bytes (one member, as the build writes them) decompressed in JavaScript, for platforms
 * without DecompressionStream: refused unless the output has the length and CRC-32 the trailer
 * gives, and before anything is allocated when that length is more than deflate can give.
 */
export async function gunzipWithoutStreams(bytes: ArrayBuffer): Promise<ArrayBuffer> {
  if (bytes.byteLength < MIN_GZIP_BYTES) throw new Error(`gzip body of ${bytes.byteLength} bytes is too short to be whole`);
  const trailer = new DataView(bytes, bytes.byteLength - 8);
  const crc = trailer.getUint32(0, true), size = trailer.getUint32(4, true);
  if (size > MAX_DEFLATE_RATIO * bytes.byteLength) throw new Error(`gzip body of ${bytes.byteLength} bytes says it holds ${size}, more than deflate can give`);
  const { inflateGzip, crc32 } = await import('./inflate-gzip.js');
  const out = inflateGzip(new Uint8Array(bytes));
  if (out.byteLength !== size) throw new Error(`gzip body gave ${out.byteLength} bytes, its trailer says ${size}`);
  if (crc32(out) !== crc) throw new Error('gzip body damaged: its CRC-32 does not match');
  // A view of exactly the output, so typed arrays over it start at offset 0.
  return out.byteOffset === 0 && out.byteLength === out.buffer.byteLength ? out.buffer : out.slice().buffer;
}
