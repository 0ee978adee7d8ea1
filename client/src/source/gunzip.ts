// Bodies that are still gzip: a host that serves the precompressed copy of a file without a
// Content-Encoding header hands the client the gzip bytes themselves. Decompressed with the
// platform's DecompressionStream, or fflate where that is missing (2 kB in the worker, where
// pako's inflate took 13 kB gzip).
import { gunzipSync } from 'fflate';

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
  return gunzipWithoutStreams(bytes);
}

/** Gzip bytes decompressed in JavaScript (fflate), for platforms without DecompressionStream. */
export function gunzipWithoutStreams(bytes: ArrayBuffer): ArrayBuffer {
  const out = gunzipSync(new Uint8Array(bytes));
  // A view of exactly the output, so typed arrays over it start at offset 0.
  return out.byteOffset === 0 && out.byteLength === out.buffer.byteLength ? out.buffer : out.slice().buffer;
}
