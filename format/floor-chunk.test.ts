// The floor chunk file on hand-made faces: what the reader cuts from the boundaries covers each
// face exactly (its area, and each sample point in one triangle of the right face), the writer
// stores a point two edges share once, and damaged files are refused with the file's name.
import test, { describe } from 'node:test';
import assert from 'node:assert/strict';
import { encodeChunk, encodeFaceStream } from './chunk-encode.js';
import { NO_CLASS, type DecodedChunk } from './chunk.js';
import { encodeFloorChunk, writeFloorChunk, type FloorChunkInput, type FloorFile } from './floor-chunk-encode.js';
import { MeshoptDecoder } from 'meshoptimizer/decoder';
import { decodeFloorChunk, FLOOR_CONTINUES, floorCycles, floorSections } from './floor-chunk.js';
import { decodeSurfaceFile } from './surface-file.js';

// A 4 x 4 square: face 7 on its left half, face 9 on its right half, and in 9 an island, face
// 11, over [2.5, 3.5]^2. Each edge has the face on its left first. Face 42 lies beyond the
// right side: not in this chunk, so it is stored as "none".
const square = (): FloorChunkInput => ({
  originX: 1000, originY: 2000,
  faces: [11, 9, 7], classes: [3, 2, 1],
  edges: [
    { xy: [2, 0, 2, 4], left: 7, right: 9 },
    { xy: [2, 4, 0, 4, 0, 0, 2, 0], left: 7, right: 0 },
    { xy: [2, 0, 4, 0, 4, 4, 2, 4], left: 9, right: 42 },
    { xy: [2.5, 2.5, 3.5, 2.5, 3.5, 3.5, 2.5, 3.5, 2.5, 2.5], left: 11, right: 9 },
  ],
  gridExponent: -4,
});

/** Each face's area from the decoded triangles, checking they are counterclockwise, at z = 0, over face 0. */
function areas(c: DecodedChunk): Map<number, number> {
  const out = new Map<number, number>();
  const p = c.positions;
  for (let t = 0; t < c.triangleCount; t++) {
    const [a, b, d] = [0, 1, 2].map((k) => c.indices[3 * t + k]!) as [number, number, number];
    const area = ((p[3 * b]! - p[3 * a]!) * (p[3 * d + 1]! - p[3 * a + 1]!) - (p[3 * d]! - p[3 * a]!) * (p[3 * b + 1]! - p[3 * a + 1]!)) / 2;
    assert.ok(area > 0, `triangle ${t} is counterclockwise`);
    for (const v of [a, b, d]) {
      assert.equal(p[3 * v + 2], 0);
      assert.equal(c.lower[v], 0);
      assert.equal(c.lowerClass[v], NO_CLASS);
      assert.equal(c.upper[v], c.upper[a]);
    }
    out.set(c.upper[a]!, (out.get(c.upper[a]!) ?? 0) + area);
  }
  return out;
}

/** The faces of the triangles over (x, y) relative to the origin. */
function facesAt(c: DecodedChunk, x: number, y: number): number[] {
  const p = c.positions, out: number[] = [];
  const cross = (a: number, b: number): number => (p[3 * b]! - p[3 * a]!) * (y - p[3 * a + 1]!) - (p[3 * b + 1]! - p[3 * a + 1]!) * (x - p[3 * a]!);
  for (let t = 0; t < c.triangleCount; t++) {
    const [a, b, d] = [0, 1, 2].map((k) => c.indices[3 * t + k]!) as [number, number, number];
    if (cross(a, b) > 0 && cross(b, d) > 0 && cross(d, a) > 0) out.push(c.upper[a]!);
  }
  return out;
}

describe('floor chunk file', () => {
  test('the reader cuts each face from its boundaries: its area, and every point of the square in one triangle of the right face', async () => {
    const { bytes, triangles } = encodeFloorChunk(square());
    const c = await decodeFloorChunk(bytes, 'b-square.bin');
    assert.equal(c.triangleCount, triangles, 'the encoder counts the triangles the reader makes');
    assert.deepEqual([c.originX, c.originY, c.gridExponent], [1000, 2000, -4]);
    assert.deepEqual([...c.box], [0, 0, 0, 4, 4, 0]);
    assert.deepEqual([...areas(c)].sort((a, b) => a[0] - b[0]), [[7, 8], [9, 7], [11, 1]]);
    const classOf = new Map([[7, 1], [9, 2], [11, 3]]);
    for (let v = 0; v < c.vertexCount; v++) assert.equal(c.upperClass[v], classOf.get(c.upper[v]!));
    // Sample points off every edge: x and y at odd sixteenths plus a little.
    for (let i = 0; i < 16; i++) for (let j = 0; j < 16; j++) {
      const x = (i + 0.3) / 4, y = (j + 0.6) / 4;
      const expected = x < 2 ? 7 : x > 2.5 && x < 3.5 && y > 2.5 && y < 3.5 ? 11 : 9;
      assert.deepEqual(facesAt(c, x, y), [expected], `(${x}, ${y})`);
    }
  });

  test('a point two edges share is stored once; version 2 names a face per cycle, the face table in the order the cycles name them', async () => {
    const bytes = encodeFloorChunk(square()).bytes;
    const dv = new DataView(bytes.buffer);
    assert.equal(dv.getUint32(4, true), 2);
    // 2 + 4 + 4 + 5 points; the second and third edges start where the one before ends.
    assert.equal(dv.getUint32(52, true), 15 - 2);
    assert.equal(FLOOR_CONTINUES, 1);
    // The cycles, in the order of their lowest half-edge (2e: edge e forward, 2e + 1 back): face 7
    // (edges 0 and 1 forward), face 9 (edge 0 back, edge 2), the outside (edges 1 and 2 back),
    // the island 11, and the hole it makes in 9.
    const F = dv.getUint32(8, true), C = dv.getUint32(60, true);
    assert.deepEqual([F, C], [3, 5]);
    const sec = floorSections(2, F, { faces: dv.getUint32(64, true), cycles: dv.getUint32(68, true), edges: dv.getUint32(72, true), points: dv.getUint32(76, true), triangles: dv.getUint32(80, true) });
    await MeshoptDecoder.ready;
    const faces = new Uint32Array(2 * F), cycles = new Uint32Array(C);
    MeshoptDecoder.decodeVertexBuffer(new Uint8Array(faces.buffer), F, 8, bytes.subarray(sec.faces, sec.faces + dv.getUint32(64, true)));
    MeshoptDecoder.decodeVertexBuffer(new Uint8Array(cycles.buffer), C, 4, bytes.subarray(sec.cycles, sec.cycles + dv.getUint32(68, true)));
    assert.deepEqual([...faces], [7, 1, 9, 2, 11, 3]);
    assert.deepEqual([...cycles], [1, 2, 0, 3, 2]);
  });

  test('the cycles round a point where four faces meet go round each face alone', () => {
    // A 2 x 2 square of unit cells meeting at (1, 1): faces 1 (bottom left), 2 (bottom right),
    // 3 (top right), 4 (top left); four inner edges leave the centre, four outer sides.
    const xy = [1, 1, 1, 0, 2, 0, 2, 1, 2, 2, 1, 2, 0, 2, 0, 1, 0, 0];
    const at = (x: number, y: number): number => xy.findIndex((_, i) => i % 2 === 0 && xy[i] === x && xy[i + 1] === y) / 2;
    const edges = [[[1, 1], [1, 0]], [[1, 1], [2, 1]], [[1, 1], [1, 2]], [[1, 1], [0, 1]], [[1, 0], [2, 0], [2, 1]], [[2, 1], [2, 2], [1, 2]], [[1, 2], [0, 2], [0, 1]], [[0, 1], [0, 0], [1, 0]]];
    const pointIds: number[] = [], edgeStart: number[] = [], edgeCount: number[] = [];
    for (const e of edges) {
      edgeStart.push(pointIds.length);
      edgeCount.push(e.length);
      for (const [x, y] of e) pointIds.push(at(x!, y!));
    }
    const pts = { id: Uint32Array.from(pointIds), xs: Float64Array.from(xy.filter((_, i) => i % 2 === 0)), ys: Float64Array.from(xy.filter((_, i) => i % 2 === 1)) };
    const { cycleOf, count } = floorCycles({ edgeStart: Uint32Array.from(edgeStart), edgeCount: Uint32Array.from(edgeCount) }, pts);
    // Each cell's cycle: two inner half-edges and an outer side; and the outside's.
    const cell = (...hs: number[]): void => assert.equal(new Set(hs.map((h) => cycleOf[h])).size, 1, `half-edges ${hs.join(', ')} go round one cycle`);
    cell(0 * 2 + 1, 7 * 2, 3 * 2); // bottom left: (1,0)->(1,1) back of edge 0... and its outer side, and edge 3 forward
    cell(0 * 2, 4 * 2, 1 * 2 + 1);
    cell(1 * 2, 5 * 2, 2 * 2 + 1);
    cell(2 * 2, 6 * 2, 3 * 2 + 1);
    cell(4 * 2 + 1, 5 * 2 + 1, 6 * 2 + 1, 7 * 2 + 1);
    assert.equal(count, 5);
  });

  test('a cycle of edges that does not bound one face is written as version 1, each edge naming its faces', async () => {
    // The unit square in two edges with different faces on their left (face 3, then 5): no face
    // can be said for its cycle. Face 3 also has a closed unit square of its own at (5, 0).
    const file: FloorFile = {
      originX: 0, originY: 0, gridExponent: 0, ground: [0, 0, 6, 1], faceIds: [3, 5], faceClasses: [4, 6],
      content: {
        points: Int32Array.of(0, 0, 1, 0, 1, 1, 0, 1, 0, 0, 5, 0, 6, 0, 6, 1, 5, 1, 5, 0), faceCount: 2,
        edgeStart: Uint32Array.of(0, 2, 5), edgeCount: Uint32Array.of(3, 3, 5), left: Uint32Array.of(1, 2, 1), right: Uint32Array.of(0, 0, 0),
        triangles: new Uint32Array(0),
      },
    };
    const bytes = writeFloorChunk(file);
    assert.equal(new DataView(bytes.buffer).getUint32(4, true), 1);
    // Read as each edge names its faces: face 3's closed square; the open walks bound nothing.
    const c = await decodeFloorChunk(bytes);
    assert.deepEqual([...areas(c)], [[3, 1]]);
    assert.deepEqual(facesAt(c, 5.3, 0.6), [3]);
    assert.deepEqual(facesAt(c, 0.3, 0.6), []);
  });

  test('the same input gives the same bytes', () => {
    assert.deepEqual(encodeFloorChunk(square()).bytes, encodeFloorChunk(square()).bytes);
  });

  test('a face that touches itself at a point, and a face with a hole touching its outer ring', async () => {
    // Face 5: two unit squares meeting at (1, 1). Face 6: a 3 x 3 square with a triangular hole
    // (face 8) whose corner lies on its bottom side.
    const c = await decodeFloorChunk(encodeFloorChunk({
      originX: 0, originY: 0, faces: [5, 6, 8], classes: [0, 0, 0], gridExponent: -2,
      edges: [
        { xy: [0, 0, 1, 0, 1, 1, 2, 1, 2, 2, 1, 2, 1, 1, 0, 1, 0, 0], left: 5, right: 0 },
        { xy: [10, 0, 13, 0, 13, 3, 10, 3, 10, 0], left: 6, right: 0 },
        { xy: [11.5, 0, 12, 1, 11, 1, 11.5, 0], left: 8, right: 6 },
      ],
    }).bytes);
    assert.deepEqual([...areas(c)].sort((a, b) => a[0] - b[0]), [[5, 2], [6, 8.5], [8, 0.5]]);
    assert.deepEqual(facesAt(c, 1.7, 1.4), [5]);
    assert.deepEqual(facesAt(c, 0.5, 1.5), []);
    assert.deepEqual(facesAt(c, 11.5, 0.7), [8]);
    assert.deepEqual(facesAt(c, 11.1, 0.5), [6]);
  });

  test('a face given as triangles is drawn from them, not cut again', async () => {
    // The unit square of face 3, its triangles given along the diagonal (0,1)-(1,0).
    const file: FloorFile = {
      originX: 0, originY: 0, gridExponent: 0, ground: [0, 0, 1, 1], faceIds: [3], faceClasses: [4],
      content: {
        points: Int32Array.of(0, 0, 1, 0, 1, 1, 0, 1, 0, 0), faceCount: 1,
        edgeStart: Uint32Array.of(0), edgeCount: Uint32Array.of(5), left: Uint32Array.of(1), right: Uint32Array.of(0),
        triangles: Uint32Array.of(0, 1, 3, 1, 1, 2, 3, 1),
      },
    };
    const c = await decodeFloorChunk(writeFloorChunk(file));
    assert.equal(c.triangleCount, 2);
    const corners = (t: number): string => [0, 1, 2].map((k) => c.indices[3 * t + k]!).map((v) => `${c.positions[3 * v]},${c.positions[3 * v + 1]}`).sort().join(' ');
    assert.deepEqual([corners(0), corners(1)].sort(), ['0,0 0,1 1,0', '0,1 1,0 1,1']);
  });

  test('a face earcut cannot cut from its boundary is written with the triangles the build gives for it', async () => {
    // A boundary that crosses itself: earcut's triangles do not add up to its rings' area.
    const input: FloorChunkInput = {
      originX: 0, originY: 0, faces: [4], classes: [0], gridExponent: 0,
      edges: [{ xy: [0, 0, 4, 0, 4, 4, 2, -2, 0, 4, 0, 0], left: 4, right: 0 }],
    };
    assert.throws(() => encodeFloorChunk(input), /earcut cannot cut face 4 from its boundary/);
    // One corner off every edge: the writer adds it as a point of its own.
    const given = [0, 0, 4, 0, 1, 1, 1, 1, 4, 0, 4, 4, 0, 0, 1, 1, 0, 4];
    const { bytes, triangles } = encodeFloorChunk({ ...input, triangles: (face) => (face === 4 ? given : []) });
    const dv = new DataView(bytes.buffer);
    assert.deepEqual([dv.getUint32(52, true), dv.getUint32(56, true), triangles], [6 + 1, 3, 3]);
    const c = await decodeFloorChunk(bytes);
    assert.deepEqual([...areas(c)], [[4, 2 + 6 + 2]]);
    assert.deepEqual(facesAt(c, 0.3, 1.6), [4]);
  });

  test('decodeSurfaceFile tells a floor chunk from a triangle chunk by its magic, and refuses anything else', async () => {
    const floor = await decodeSurfaceFile(encodeFloorChunk(square()).bytes, 'b-a.bin');
    assert.equal(floor.triangleCount, encodeFloorChunk(square()).triangles);
    const tri = encodeChunk({
      originX: 0, originY: 0, box: Float32Array.of(0, 0, 0, 1, 1, 0), positions: [0, 0, 0, 1, 0, 0, 0, 1, 0],
      upper: [1, 1, 1], lower: [0, 0, 0], upperClass: [0, 0, 0], lowerClass: [NO_CLASS, NO_CLASS, NO_CLASS], indices: [0, 1, 2],
    });
    assert.equal((await decodeSurfaceFile(tri, 'c-a.bin')).triangleCount, 1);
    await assert.rejects(decodeSurfaceFile(new Uint8Array(100), 'x.bin'), /^ChunkFormatError: x\.bin: neither a chunk nor a floor chunk file \(bad magic\)$/);
  });

  describe('damaged files are refused, naming the file', () => {
    const good = encodeFloorChunk(square()).bytes;
    const damaged = (edit: (dv: DataView) => void, bytes = good): Uint8Array => {
      const b = bytes.slice();
      edit(new DataView(b.buffer));
      return b;
    };
    const refuses = (b: Uint8Array, pattern: RegExp): Promise<void> =>
      assert.rejects(decodeFloorChunk(b, 'b-x.bin'), (e: unknown) => e instanceof Error && e.name === 'ChunkFormatError' && e.message.startsWith('b-x.bin: ') && pattern.test(e.message));
    test('truncated, another version, or a box that is not finite', async () => {
      await refuses(good.subarray(0, 40), /truncated \(40 bytes/);
      await refuses(good.subarray(0, good.length - 4), /bytes, its header .* needs/);
      await refuses(damaged((dv) => dv.setUint32(4, 3, true)), /floor chunk version 3, this reader knows versions 1 and 2/);
      await refuses(damaged((dv) => dv.setFloat32(36, NaN, true)), /its box is not finite/);
    });
    test('counts that cannot hold', async () => {
      await refuses(damaged((dv) => dv.setUint32(12, 1000, true)), /counts out of bounds \(3 faces, 1000 edges, 13 points, 5 cycles\)/);
      await refuses(damaged((dv) => dv.setUint32(8, 0, true)), /counts out of bounds|bytes, its header/);
      // Two billion points: refused before anything is allocated for them.
      await refuses(damaged((dv) => dv.setUint32(52, 2 ** 31, true)), /counts out of bounds for their streams \(4 edges in \d+ bytes, 2147483648 points in \d+/);
      await refuses(damaged((dv) => dv.setUint32(56, 5, true)), /counts out of bounds for their streams .*, 5 triangles in 0,/);
      // A stream length near 2^32 would wrap the sum of the lengths round to the file's length.
      await refuses(damaged((dv) => dv.setUint32(72, 2 ** 32 - 64, true)), /bytes, its header .* needs 4\d{9}$/);
      await refuses(damaged((dv) => dv.setUint32(60, 0, true)), /counts out of bounds \(3 faces, 4 edges, 13 points, 0 cycles\)/);
      await refuses(damaged((dv) => dv.setUint32(60, 4, true)), /its edges go round 5 cycles, its header gives faces for 4|do not decode/);
    });
    test('edges naming faces the table does not hold, or points beyond the stream', async () => {
      const content = (edit: (c: FloorFile['content']) => void): Uint8Array => {
        const c: FloorFile['content'] = {
          points: Int32Array.of(0, 0, 1, 0, 1, 1, 0, 1, 0, 0), faceCount: 1,
          edgeStart: Uint32Array.of(0), edgeCount: Uint32Array.of(5), left: Uint32Array.of(1), right: Uint32Array.of(0), triangles: new Uint32Array(0),
        };
        edit(c);
        return writeFloorChunk({ originX: 0, originY: 0, gridExponent: 0, ground: [0, 0, 1, 1], faceIds: [3], faceClasses: [4], content: c });
      };
      await refuses(content((c) => { c.left[0] = 2; }), /edge 0 lies between faces 2 and 0 of a table of 1/);
      await refuses(content((c) => { c.right[0] = 1; }), /edge 0 lies between faces 1 and 1/);
      await refuses(content((c) => { c.edgeCount[0] = 1; }), /edge 0 has 1 points/);
      await refuses(content((c) => { c.triangles = Uint32Array.of(0, 1, 9, 1); }), /triangle 0 names points 0, 1, 9 of 5 and face 1 of 1/);
    });
    test('a face of class 65,535 (the chunk file\'s class of face 0) in the face stream', async () => {
      // The writer refuses that class, so the face stream of a good file is swapped for one that
      // holds it; both are 1 record through the same codec, of the same length.
      const file = writeFloorChunk({
        originX: 0, originY: 0, gridExponent: 0, ground: [0, 0, 1, 1], faceIds: [3], faceClasses: [4],
        content: {
          points: Int32Array.of(0, 0, 1, 0, 1, 1, 0, 1, 0, 0), faceCount: 1, edgeStart: Uint32Array.of(0), edgeCount: Uint32Array.of(5),
          left: Uint32Array.of(1), right: Uint32Array.of(0), triangles: new Uint32Array(0),
        },
      });
      await decodeFloorChunk(file, 'b-x.bin');
      const dv = new DataView(file.buffer, file.byteOffset);
      assert.equal(dv.getUint32(4, true), 2, 'version 2, whose face stream is at 84 and its length at 64');
      const lf = dv.getUint32(64, true);
      const swapped = encodeFaceStream([3], [NO_CLASS]);
      assert.equal(swapped.length, lf);
      const b = file.slice();
      b.set(swapped, 84);
      await refuses(b, /face 3 has class 65535$/);
    });
    test('the encoder refuses what it cannot write', () => {
      const file: FloorFile = {
        originX: 0, originY: 0, gridExponent: 0, ground: [0, 0, 1, 1], faceIds: [3], faceClasses: [NO_CLASS],
        content: {
          points: Int32Array.of(0, 0, 1, 0, 1, 1, 0, 1, 0, 0), faceCount: 1, edgeStart: Uint32Array.of(0), edgeCount: Uint32Array.of(5),
          left: Uint32Array.of(1), right: Uint32Array.of(0), triangles: new Uint32Array(0),
        },
      };
      assert.throws(() => writeFloorChunk(file), /face 3 has class 65535, a class index is below 65535/);
      assert.throws(() => encodeFloorChunk({ ...square(), faces: [7, 9, 11, 13], classes: [1, 2, 3, 4] }), /face 13 has no edge/);
      assert.throws(() => encodeFloorChunk({ ...square(), edges: [...square().edges, { xy: [0, 0, 1, 1], left: 1, right: 2 }] }), /edge 4 between faces 1 and 2 bounds none of the chunk's faces/);
    });
  });
});
