// SHA-256 of a chunk, to compare with the digits of its name (or a version 1 index's `sha256`).
// crypto.subtle exists only in secure contexts (https, localhost, 127.0.0.1): elsewhere the check
// cannot run and null says so.

export async function sha256Hex(bytes: ArrayBuffer): Promise<string | null> {
  const subtle = globalThis.crypto?.subtle;
  if (!subtle) return null;
  const digest = new Uint8Array(await subtle.digest('SHA-256', bytes));
  let hex = '';
  for (const b of digest) hex += b.toString(16).padStart(2, '0');
  return hex;
}
