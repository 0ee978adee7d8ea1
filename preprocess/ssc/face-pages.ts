// Face table pages (docs/FORMAT.md, "Face table page"): what picking needs to say about a face.
import { FACE_PAGE_MAGIC, FACE_PAGE_VERSION } from '../../client/src/shared/face-page.js';
import type { TgapFace } from '../tgap/model.js';

export const PAGE_SIZE = 4096;

export function encodeFacePage(faces: TgapFace[], first: number, count: number): Uint8Array {
  const classBytes = (2 * count + 3) & ~3;
  const buf = new ArrayBuffer(16 + classBytes + 16 * count);
  const dv = new DataView(buf);
  dv.setUint32(0, FACE_PAGE_MAGIC, true);
  dv.setUint32(4, FACE_PAGE_VERSION, true);
  dv.setUint32(8, first, true);
  dv.setUint32(12, count, true);
  let o = 16;
  const cls = new Uint16Array(buf, o, count);
  o += classBytes;
  const feature = new Int32Array(buf, o, count);
  o += 4 * count;
  const low = new Uint32Array(buf, o, count);
  o += 4 * count;
  const high = new Uint32Array(buf, o, count);
  o += 4 * count;
  const into = new Int32Array(buf, o, count);
  for (let i = 0; i < count; i++) {
    const f = faces[first + i]!;
    cls[i] = f.classIndex;
    feature[i] = f.feature;
    low[i] = f.stepLow;
    high[i] = f.stepHigh;
    into[i] = f.mergedInto;
  }
  return new Uint8Array(buf);
}
