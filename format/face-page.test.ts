// Face table pages: a page written by hand after docs/FORMAT.md decodes to its rows, and the
// encoder writes exactly such a page.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { decodeFacePage, encodeFacePage, faceRecord, FacePageError, type FaceFields } from './face-page.js';

describe('face table pages', () => {
  /** A page written by hand after docs/FORMAT.md. */
  function page(first: number, rows: [number, number, number, number, number][]): ArrayBuffer {
    const n = rows.length;
    const classBytes = (2 * n + 3) & ~3;
    const buf = new ArrayBuffer(16 + classBytes + 16 * n);
    const dv = new DataView(buf);
    dv.setUint32(0, 0x46435353, true);
    dv.setUint32(4, 1, true);
    dv.setUint32(8, first, true);
    dv.setUint32(12, n, true);
    rows.forEach(([cls, feat, lo, hi, into], i) => {
      dv.setUint16(16 + 2 * i, cls, true);
      dv.setInt32(16 + classBytes + 4 * i, feat, true);
      dv.setUint32(16 + classBytes + 4 * n + 4 * i, lo, true);
      dv.setUint32(16 + classBytes + 8 * n + 4 * i, hi, true);
      dv.setInt32(16 + classBytes + 12 * n + 4 * i, into, true);
    });
    return buf;
  }

  test('give each face its class, feature and steps', () => {
    const p = decodeFacePage(page(100, [[3, 7, 0, 12, 101], [1, -1, 12, 475, -1], [65535, 9, 5, 6, 100]]));
    assert.deepEqual(faceRecord(p, 101), { face: 101, classIndex: 1, feature: -1, stepLow: 12, stepHigh: 475, mergedInto: -1 });
    assert.deepEqual(faceRecord(p, 102), { face: 102, classIndex: 65535, feature: 9, stepLow: 5, stepHigh: 6, mergedInto: 100 });
    assert.equal(faceRecord(p, 99), undefined);
    assert.equal(faceRecord(p, 103), undefined);
  });

  test('the encoder writes the page the document describes', () => {
    const rows: [number, number, number, number, number][] = [[3, 7, 0, 12, 101], [1, -1, 12, 475, -1], [65535, 9, 5, 6, 100]];
    const faces: FaceFields[] = rows.map(([classIndex, feature, stepLow, stepHigh, mergedInto]) => ({ classIndex, feature, stepLow, stepHigh, mergedInto }));
    // Faces 100..102 of a table whose first two faces belong to another page.
    const table = [faces[0]!, faces[0]!, ...faces];
    assert.deepEqual(encodeFacePage(table, 2, 3), new Uint8Array(page(2, rows)));
    // An odd count pads the class column to 4 bytes.
    assert.deepEqual(encodeFacePage(table, 2, 1), new Uint8Array(page(2, rows.slice(0, 1))));
  });

  test('refuse a bad magic or length', () => {
    const good = page(0, [[1, 2, 3, 4, 5]]);
    const bad = good.slice(0);
    new DataView(bad).setUint32(0, 0x12345678, true);
    assert.throws(() => decodeFacePage(bad), FacePageError);
    assert.throws(() => decodeFacePage(good.slice(0, good.byteLength - 4)), FacePageError);
  });
});
