// A face table page (docs/FORMAT.md, "Face table page f-<hash>.bin"): per face its class,
// input feature and the steps it is alive in, for picking. Encoder and decoder. Pure.
import { pad4 } from './chunk.js';
import { FormatError } from './format-error.js';

export const FACE_PAGE_MAGIC = 0x46435353; // "SSCF"
export const FACE_PAGE_VERSION = 1;
/** Faces per page (the build's choice; a reader takes first and count from the page). */
export const FACE_PAGE_SIZE = 4096;
const HEADER = 16;

export class FacePageError extends FormatError {
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

/** What a page says of one face. */
export type FaceFields = Pick<FaceRecord, 'classIndex' | 'feature' | 'stepLow' | 'stepHigh' | 'mergedInto'>;

const classBytes = (count: number): number => pad4(2 * count);
const pageBytes = (count: number): number => HEADER + classBytes(count) + 16 * count;

/** The page of faces[first .. first + count). */
export function encodeFacePage(faces: readonly FaceFields[], first: number, count: number): Uint8Array {
  const buf = new ArrayBuffer(pageBytes(count));
  const dv = new DataView(buf);
  dv.setUint32(0, FACE_PAGE_MAGIC, true);
  dv.setUint32(4, FACE_PAGE_VERSION, true);
  dv.setUint32(8, first, true);
  dv.setUint32(12, count, true);
  const page = columns(buf, first, count);
  for (let i = 0; i < count; i++) {
    const f = faces[first + i]!;
    page.classIndex[i] = f.classIndex;
    page.feature[i] = f.feature;
    page.stepLow[i] = f.stepLow;
    page.stepHigh[i] = f.stepHigh;
    page.mergedInto[i] = f.mergedInto;
  }
  return new Uint8Array(buf);
}

/** The columns of a page buffer whose header says first and count. */
function columns(buffer: ArrayBuffer, first: number, count: number): FacePage {
  let o = HEADER;
  const classIndex = new Uint16Array(buffer, o, count);
  o += classBytes(count);
  const feature = new Int32Array(buffer, o, count);
  o += 4 * count;
  const stepLow = new Uint32Array(buffer, o, count);
  o += 4 * count;
  const stepHigh = new Uint32Array(buffer, o, count);
  o += 4 * count;
  const mergedInto = new Int32Array(buffer, o, count);
  return { first, count, classIndex, feature, stepLow, stepHigh, mergedInto };
}

export function decodeFacePage(buffer: ArrayBuffer): FacePage {
  if (buffer.byteLength < HEADER) throw new FacePageError(`face page is ${buffer.byteLength} bytes, shorter than its header`);
  const dv = new DataView(buffer);
  const magic = dv.getUint32(0, true);
  if (magic !== FACE_PAGE_MAGIC) throw new FacePageError(`not a face page: magic 0x${magic.toString(16).padStart(8, '0')}`);
  const version = dv.getUint32(4, true);
  if (version !== FACE_PAGE_VERSION) throw new FacePageError(`face page version ${version} is not supported`);
  const first = dv.getUint32(8, true);
  const count = dv.getUint32(12, true);
  const expected = pageBytes(count);
  if (buffer.byteLength !== expected) throw new FacePageError(`face page is ${buffer.byteLength} bytes; ${count} faces need ${expected}`);
  return columns(buffer, first, count);
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
