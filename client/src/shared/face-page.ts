// Decoder of a face table page (docs/FORMAT.md, "Face table page f-<hash>.bin"): per face its
// class, input feature and the steps it is alive in. Pure, like the chunk decoder.

export const FACE_PAGE_MAGIC = 0x46435353; // "SSCF"
export const FACE_PAGE_VERSION = 1;

export class FacePageError extends Error {
  constructor(message: string) {
    super(message);
    this.name = 'FacePageError';
  }
}

export interface FacePage {
  first: number;
  count: number;
  classIndex: Uint16Array;
  feature: Int32Array;
  stepLow: Uint32Array;
  stepHigh: Uint32Array;
  mergedInto: Int32Array;
}

export interface FaceRecord {
  face: number;
  classIndex: number;
  /** Input feature whose attributes the face carries (-1: none). */
  feature: number;
  stepLow: number;
  stepHigh: number;
  mergedInto: number;
}

export function decodeFacePage(buffer: ArrayBuffer): FacePage {
  if (buffer.byteLength < 16) throw new FacePageError(`face page is ${buffer.byteLength} bytes, shorter than its header`);
  const dv = new DataView(buffer);
  const magic = dv.getUint32(0, true);
  if (magic !== FACE_PAGE_MAGIC) throw new FacePageError(`not a face page: magic 0x${magic.toString(16).padStart(8, '0')}`);
  const version = dv.getUint32(4, true);
  if (version !== FACE_PAGE_VERSION) throw new FacePageError(`face page version ${version} is not supported`);
  const first = dv.getUint32(8, true);
  const count = dv.getUint32(12, true);
  const classBytes = (2 * count + 3) & ~3;
  const expected = 16 + classBytes + 16 * count;
  if (buffer.byteLength !== expected) throw new FacePageError(`face page is ${buffer.byteLength} bytes; ${count} faces need ${expected}`);
  let o = 16;
  const classIndex = new Uint16Array(buffer, o, count);
  o += classBytes;
  const feature = new Int32Array(buffer, o, count);
  o += 4 * count;
  const stepLow = new Uint32Array(buffer, o, count);
  o += 4 * count;
  const stepHigh = new Uint32Array(buffer, o, count);
  o += 4 * count;
  const mergedInto = new Int32Array(buffer, o, count);
  return { first, count, classIndex, feature, stepLow, stepHigh, mergedInto };
}

/** The record of `face` from a page that holds it, or undefined. */
export function faceRecord(page: FacePage, face: number): FaceRecord | undefined {
  const i = face - page.first;
  if (i < 0 || i >= page.count) return undefined;
  return {
    face,
    classIndex: page.classIndex[i]!,
    feature: page.feature[i]!,
    stepLow: page.stepLow[i]!,
    stepHigh: page.stepHigh[i]!,
    mergedInto: page.mergedInto[i]!,
  };
}
