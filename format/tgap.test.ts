// The tGAP file: a hand-made tGAP of two squares (one merged into the other, an edge
// simplified, a re-draw) reads back equal; a damaged file is refused, naming the file.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { FormatError } from './format-error.js';
import { decodeTgap, encodeTgap, TGAP_MAGIC } from './tgap.js';
import { EventKind, resolveFace, type Tgap } from './tgap-model.js';

function twoSquares(): Tgap {
  // Vertices 0..5: two unit squares side by side, sharing the edge 1-4.
  return {
    meta: {
      version: 1, crs: 'EPSG:28992', extent: [0, 0, 2, 1], baseScale: 1000, resolutionMm: 0.28, baseFaces: 2, steps: 2,
      facesAlive: [2, 1, 1], holes: [], repairs: { reoriented: 1 }, source: 'two.geojson',
      style: { name: 'two', classes: [{ key: 'a', color: '#112233' }, { key: 'b', color: '#445566' }] },
      attributes: [{ id: 'left' }, { id: 'right' }], options: { group: 1 },
    },
    xs: new Float64Array([0, 1, 2, 2, 1, 0]),
    ys: new Float64Array([0, 0, 0, 1, 1, 1]),
    faces: [
      { classIndex: 0, feature: -1, stepLow: 0, stepHigh: 3, mergedInto: -1, endPhase: 0, area2: 0 },
      { classIndex: 0, feature: 0, stepLow: 0, stepHigh: 1, mergedInto: 2, endPhase: 0, area2: 2 },
      { classIndex: 1, feature: 1, stepLow: 0, stepHigh: 2, mergedInto: 3, endPhase: 7, area2: 2 },
      { classIndex: 1, feature: 1, stepLow: 2, stepHigh: 3, mergedInto: -1, endPhase: 0, area2: 4 },
    ],
    edges: [
      { start: 1, end: 4, left: 2, right: 1, verts: new Int32Array([1, 4]), stepLow: 0, stepHigh: 1, parents: new Int32Array([]), removed: new Int32Array([]), removedPhase: new Uint8Array([]) },
      { start: 4, end: 1, left: 0, right: 2, verts: new Int32Array([4, 5, 0, 1]), stepLow: 0, stepHigh: 1, parents: new Int32Array([]), removed: new Int32Array([]), removedPhase: new Uint8Array([]) },
      { start: 1, end: 1, left: 0, right: 3, verts: new Int32Array([1, 2, 3, 5, 1]), stepLow: 1, stepHigh: 3, parents: new Int32Array([-2, 2]), removed: new Int32Array([4, 0]), removedPhase: new Uint8Array([1, 2]) },
    ],
    events: [
      { kind: EventKind.Merge, step: 1, loser: 1, into: 2 },
      { kind: EventKind.Reemit, step: 2, loser: 2, into: 3 },
      { kind: EventKind.Split, step: 2, loser: 9, into: -1, tris: new Int32Array([0, 1, 4]), triFaces: new Int32Array([3]) },
    ],
  };
}

describe('tGAP file', () => {
  test('reads back what was written', () => {
    const t = twoSquares();
    const bytes = encodeTgap(t);
    assert.equal(new DataView(bytes.buffer, bytes.byteOffset).getUint32(0, true), TGAP_MAGIC);
    const back = decodeTgap(bytes, 'two.tgap');
    assert.deepEqual(back.meta, t.meta);
    assert.deepEqual([...back.xs], [...t.xs]);
    assert.deepEqual([...back.ys], [...t.ys]);
    assert.deepEqual(back.faces, t.faces);
    const plain = (e: Tgap['edges'][number]) => ({ ...e, verts: [...e.verts], parents: [...e.parents], removed: [...e.removed], removedPhase: [...e.removedPhase] });
    assert.deepEqual(back.edges.map(plain), t.edges.map(plain));
    assert.deepEqual(back.events.map((e) => ({ ...e, tris: e.tris && [...e.tris], triFaces: e.triFaces && [...e.triFaces] })),
      t.events.map((e) => ({ ...e, tris: e.tris && [...e.tris], triFaces: e.triFaces && [...e.triFaces] })));
    // The same input gives the same bytes.
    assert.deepEqual(encodeTgap(back), bytes);
  });

  test('merges and re-draws are followed to the face that holds the area', () => {
    const { faces } = twoSquares();
    assert.equal(resolveFace(faces, 1, 0), 1);
    assert.equal(resolveFace(faces, 1, 1), 2, 'merged into 2 at step 1');
    assert.equal(resolveFace(faces, 1, 2), 3, 'then 2 re-drawn as 3 at step 2');
  });

  test('a damaged file is refused, naming the file', () => {
    const bytes = encodeTgap(twoSquares());
    const refuses = (b: Uint8Array, pattern: RegExp): void => {
      assert.throws(() => decodeTgap(b, 'two.tgap'), (e: unknown) => e instanceof FormatError && e.message.startsWith('two.tgap: ') && pattern.test(e.message));
    };
    const flipped = bytes.slice();
    flipped[100] = flipped[100]! ^ 1;
    refuses(flipped, /checksum/);
    refuses(bytes.subarray(0, bytes.length - 10), /checksum|truncated/);
    refuses(bytes.subarray(0, 20), /truncated/);
  });

  test('a file naming a face or vertex that does not exist is refused', () => {
    const t = twoSquares();
    t.edges[0]!.left = 17;
    assert.throws(() => decodeTgap(encodeTgap(t), 'bad.tgap'), /bad.tgap: is inconsistent: an edge names a face that does not exist/);
    const u = twoSquares();
    u.edges[1]!.verts = new Int32Array([4, 99]);
    assert.throws(() => decodeTgap(encodeTgap(u), 'bad.tgap'), /an edge names a vertex that does not exist/);
  });
});
