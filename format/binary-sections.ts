// Little-endian binary sections of the tGAP file: 8-byte aligned typed arrays behind a u32
// length, and a SHA-256 trailer so truncation and corruption are found before anything is used.
import { createHash } from 'node:crypto';
import { FormatError } from './format-error.js';

type Typed = Int32Array | Uint32Array | Float64Array | Float32Array | Uint8Array | Uint16Array;

export class BinaryWriter {
  private parts: Uint8Array[] = [];
  private length = 0;

  bytes(b: Uint8Array): void {
    this.parts.push(b);
    this.length += b.length;
  }

  u32(v: number): void {
    const b = new Uint8Array(4);
    new DataView(b.buffer).setUint32(0, v, true);
    this.bytes(b);
  }

  private pad(): void {
    const r = this.length % 8;
    if (r) this.bytes(new Uint8Array(8 - r));
  }

  /** u32 element count, padding to 8 bytes, then the elements. */
  array(a: Typed): void {
    this.u32(a.length);
    this.pad();
    // Typed arrays are little-endian on every platform Node runs on that we support.
    this.bytes(new Uint8Array(a.buffer, a.byteOffset, a.byteLength));
    this.pad();
  }

  json(v: unknown): void {
    this.array(new TextEncoder().encode(JSON.stringify(v)));
  }

  /** The whole buffer with its SHA-256 appended. */
  finish(): Uint8Array {
    const out = new Uint8Array(this.length + 32);
    let o = 0;
    for (const p of this.parts) {
      out.set(p, o);
      o += p.length;
    }
    out.set(createHash('sha256').update(out.subarray(0, this.length)).digest(), this.length);
    return out;
  }
}

export class BinaryReader {
  private o = 0;
  private readonly view: DataView;
  private readonly end: number;

  constructor(private readonly buf: Uint8Array, private readonly file: string) {
    if (buf.length < 40) throw new FormatError('is truncated (shorter than a header)', file);
    this.end = buf.length - 32;
    const digest = createHash('sha256').update(buf.subarray(0, this.end)).digest();
    for (let i = 0; i < 32; i++) {
      if (digest[i] !== buf[this.end + i]) throw new FormatError('is corrupt or truncated (checksum mismatch)', file);
    }
    this.view = new DataView(buf.buffer, buf.byteOffset, buf.byteLength);
  }

  bytes(n: number): Uint8Array {
    this.need(n);
    const b = this.buf.subarray(this.o, this.o + n);
    this.o += n;
    return b;
  }

  u32(): number {
    this.need(4);
    const v = this.view.getUint32(this.o, true);
    this.o += 4;
    return v;
  }

  private align(): void {
    this.o = (this.o + 7) & ~7;
  }

  private need(n: number): void {
    if (this.o + n > this.end) throw new FormatError(`is truncated (needs ${n} bytes at offset ${this.o})`, this.file);
  }

  private raw(bytesPer: number): ArrayBuffer {
    const n = this.u32();
    this.align();
    this.need(n * bytesPer);
    // Copy into a fresh, aligned buffer: the file buffer's offset may not suit the element size.
    const copy = new Uint8Array(n * bytesPer);
    copy.set(this.buf.subarray(this.o, this.o + n * bytesPer));
    this.o += n * bytesPer;
    this.align();
    return copy.buffer;
  }

  i32(): Int32Array { return new Int32Array(this.raw(4)); }
  u32a(): Uint32Array { return new Uint32Array(this.raw(4)); }
  f64(): Float64Array { return new Float64Array(this.raw(8)); }
  f32(): Float32Array { return new Float32Array(this.raw(4)); }
  u16(): Uint16Array { return new Uint16Array(this.raw(2)); }
  u8(): Uint8Array { return new Uint8Array(this.raw(1)); }

  json<T>(): T {
    const b = this.u8();
    try {
      return JSON.parse(new TextDecoder().decode(b)) as T;
    } catch (err) {
      throw new FormatError(`has an unreadable JSON section: ${(err as Error).message}`, this.file);
    }
  }

  done(): void {
    if (this.o !== this.end) throw new FormatError(`has ${this.end - this.o} unexpected bytes before its checksum`, this.file);
  }
}
