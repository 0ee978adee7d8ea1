// The chunk file, version 5: the encoder writes the header and face table of docs/FORMAT.md
// (checked at offsets worked out by hand), the decoder gives back what went in (positions
// within half a grid step, everything else exactly), and a damaged, truncated or old file is
// refused with a message that says what is wrong.
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { describe, test } from 'node:test';
import { fileURLToPath } from 'node:url';
import { encodeChunk, encodeFaceStream, orderForCodecs, type ChunkInput } from './chunk-encode.js';
import { VERTEX_BYTES, VERTEX_COLUMNS, vertexColumnOffset } from './chunk-layout.js';
import { MeshoptDecoder } from 'meshoptimizer/decoder';
import { CHUNK_MAGIC, ChunkFormatError, chunkLayout, decodeChunk, type DecodedChunk } from './chunk.js';

const fixture = (name: string): string => path.join(path.dirname(fileURLToPath(import.meta.url)), 'testdata', name);

/** Two triangles over four vertices: a unit square at z 3 (floor) and 5 (tilted corner). */
function square(): ChunkInput & { positions: Float32Array } {
  return {
    originX: 181000.5,
    originY: 457000.25,
    box: new Float32Array([0, 0, 3, 1, 1, 5]),
    positions: new Float32Array([0, 0, 3, 1, 0, 3, 1, 1, 5, 0, 1, 3]),
    upper: new Uint32Array([7, 7, 8, 7]),
    lower: new Uint32Array([0, 0, 7, 0]),
    upperClass: new Uint16Array([2, 2, 4, 2]),
    lowerClass: new Uint16Array([0xffff, 0xffff, 2, 0xffff]),
    indices: new Uint16Array([0, 1, 2, 0, 2, 3]),
  };
}

/** A deterministic pseudo-random sequence in [0, 1). */
function random(seed: number): () => number {
  let s = seed >>> 0;
  return () => {
    s = (Math.imul(s, 1664525) + 1013904223) >>> 0;
    return s / 2 ** 32;
  };
}

/**
 * A chunk like a built one: a grid of n x n points over `size` ground units (jittered off the
 * grid, so not on any power-of-two step), two triangles a cell, faces by 2 x 2 blocks of cells,
 * z per vertex in steps of 1/9 (the cube's phases) plus a tilt.
 */
function gridChunk(n: number, size: number, seed = 1): ChunkInput & { positions: Float64Array } {
  const r = random(seed);
  const V = n * n;
  const positions = new Float64Array(3 * V);
  for (let j = 0; j < n; j++) for (let i = 0; i < n; i++) {
    const k = j * n + i;
    positions[3 * k] = ((i + 0.3 * r()) / n) * size;
    positions[3 * k + 1] = ((j + 0.3 * r()) / n) * size;
    positions[3 * k + 2] = 40 + Math.floor(r() * 9) / 9 + (i % 3) * 0.0137;
  }
  // Vertices are per face here (each cell's corners carry its face), as a piece's would.
  const upper = new Uint32Array(V), lower = new Uint32Array(V);
  const face = (i: number, j: number): number => 1 + Math.floor(i / 2) + 1000 * Math.floor(j / 2);
  for (let j = 0; j < n; j++) for (let i = 0; i < n; i++) {
    upper[j * n + i] = face(Math.min(i, n - 2), Math.min(j, n - 2));
    lower[j * n + i] = (i + j) % 5 === 0 ? 0 : 999999;
  }
  const indices: number[] = [];
  for (let j = 0; j + 1 < n; j++) for (let i = 0; i + 1 < n; i++) {
    const a = j * n + i;
    // Only where all four corners name one face (as the build's pieces do).
    if (new Set([upper[a], upper[a + 1], upper[a + n], upper[a + n + 1]]).size !== 1) continue;
    if (new Set([lower[a], lower[a + 1], lower[a + n], lower[a + n + 1]]).size !== 1) continue;
    indices.push(a, a + 1, a + n + 1, a, a + n + 1, a + n);
  }
  // Only the vertices of a triangle, as a built chunk has.
  const keep = [...new Set(indices)].sort((x, y) => x - y);
  const at = new Map(keep.map((v, i) => [v, i]));
  const cls = (f: number): number => (f === 0 ? 0xffff : f % 7);
  const U = keep.map((v) => upper[v]!), D = keep.map((v) => lower[v]!);
  return {
    originX: 181234, originY: 456789, box: Float32Array.of(0, 0, 40, size, size, 42),
    positions: Float64Array.from(keep.flatMap((v) => [positions[3 * v]!, positions[3 * v + 1]!, positions[3 * v + 2]!])),
    upper: Uint32Array.from(U), lower: Uint32Array.from(D), upperClass: Uint16Array.from(U, cls), lowerClass: Uint16Array.from(D, cls),
    indices: keep.length <= 0xffff ? Uint16Array.from(indices, (v) => at.get(v)!) : Uint32Array.from(indices, (v) => at.get(v)!),
  };
}

/** Triangles as strings, each turned to start at its smallest vertex (the codec may turn a triangle; the winding stays). */
function triangles(indices: ArrayLike<number>): string[] {
  const out: string[] = [];
  for (let t = 0; t < indices.length; t += 3) {
    const v = [indices[t]!, indices[t + 1]!, indices[t + 2]!];
    const m = v.indexOf(Math.min(...v));
    out.push([v[m], v[(m + 1) % 3], v[(m + 2) % 3]].join(','));
  }
  return out;
}

/** Asserts the decoded chunk is the input, positions within `tol` ground units. */
function assertSame(d: DecodedChunk, c: ChunkInput, tol: number): void {
  const V = c.upper.length;
  assert.equal(d.vertexCount, V);
  assert.equal(d.triangleCount, c.indices.length / 3);
  assert.equal(d.originX, c.originX);
  assert.equal(d.originY, c.originY);
  assert.deepEqual([...d.box], [...c.box]);
  let worst = 0;
  for (let k = 0; k < V; k++) {
    worst = Math.max(worst, Math.abs(d.positions[3 * k]! - c.positions[3 * k]!), Math.abs(d.positions[3 * k + 1]! - c.positions[3 * k + 1]!));
    assert.equal(d.positions[3 * k + 2], Math.fround(c.positions[3 * k + 2]!), `z of vertex ${k} is its float32`);
  }
  assert.ok(worst <= tol, `positions off by up to ${worst}, at most ${tol} allowed`);
  assert.deepEqual([...d.upper], Array.from(c.upper));
  assert.deepEqual([...d.lower], Array.from(c.lower));
  assert.deepEqual([...d.upperClass], Array.from(c.upperClass));
  assert.deepEqual([...d.lowerClass], Array.from(c.lowerClass));
  assert.deepEqual(triangles(d.indices), triangles(c.indices));
}

describe('chunk file', () => {
  test('the encoder writes the documented header and face table', async () => {
    const bytes = encodeChunk(square());
    const dv = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
    assert.equal(dv.getUint32(0, true), 0x43435353);
    assert.equal(dv.getUint32(4, true), 5, 'version');
    assert.equal(dv.getUint32(8, true), 4, 'vertices');
    assert.equal(dv.getUint32(12, true), 2, 'triangles');
    assert.equal(dv.getFloat64(16, true), 181000.5);
    assert.equal(dv.getFloat64(24, true), 457000.25);
    assert.equal(dv.getFloat32(32 + 4 * 5, true), 5, 'box z1');
    // The box reaches 1: the grid is 2^(1 - 24), so that |x| < 2^1.
    assert.equal(dv.getInt32(56, true), -23, 'position step exponent');
    assert.equal(dv.getUint32(60, true), 3, 'faces 7, 0 and 8');
    assert.equal(dv.getUint32(64, true), 4, 'points: the four corners');
    assert.equal(dv.getUint32(68, true), 2, 'z values 3 and 5');
    const [faceStream, pointStream, zStream, vertexPoints, vertexZs, vertexStream, indexStream] = [72, 76, 80, 84, 88, 92, 96].map((o) => dv.getUint32(o, true));
    // The face stream at 100: records of u32 id, u32 class through the vertex codec.
    assert.equal(bytes[100], 0xa1, 'the face stream starts at 100 with the vertex codec\'s version-1 header byte');
    await MeshoptDecoder.ready;
    const faces = new Uint32Array(6);
    MeshoptDecoder.decodeVertexBuffer(new Uint8Array(faces.buffer), 3, 8, bytes.subarray(100, 100 + faceStream!));
    assert.deepEqual([...faces], [7, 2, 0, 0xffff, 8, 4], 'ids in order of first mention (upper before lower), each with its class');
    const pointAt = (100 + faceStream! + 3) & ~3;
    assert.equal(bytes[pointAt], 0xa1, 'the point stream at the next multiple of 4');
    const zAt = (pointAt + pointStream! + 3) & ~3;
    assert.equal(bytes[zAt], 0xa1, 'the z stream at the next multiple of 4');
    const vertexPointsAt = (zAt + zStream! + 3) & ~3;
    assert.equal(bytes[vertexPointsAt], 0xd1, 'the vertices\' point indices at the next multiple of 4, with the index sequence codec\'s header byte');
    // 4 indices, a byte each, between the codec's header byte and its 4 bytes of tail.
    assert.equal(vertexPoints, 9);
    const vertexZsAt = (vertexPointsAt + vertexPoints + 3) & ~3;
    assert.equal(bytes[vertexZsAt], 0xd1, 'then their z indices');
    const vertexAt = (vertexZsAt + vertexZs! + 3) & ~3;
    assert.equal(bytes[vertexAt], 0xa1, 'the vertex stream (faces) at the next multiple of 4');
    // What each stream holds, vertex by vertex: corners (0,0), (1,0), (1,1), (0,1); z 3, 3, 5, 3;
    // faces 7 over 0 but 8 over 7 at the tilted corner (table places 0, 1 and 2).
    const pointIndices = new Uint32Array(4), zIndices = new Uint32Array(4), faceLanes = new Uint16Array(8);
    MeshoptDecoder.decodeIndexSequence(new Uint8Array(pointIndices.buffer), 4, 4, bytes.subarray(vertexPointsAt, vertexPointsAt + vertexPoints));
    MeshoptDecoder.decodeIndexSequence(new Uint8Array(zIndices.buffer), 4, 4, bytes.subarray(vertexZsAt, vertexZsAt + vertexZs!));
    MeshoptDecoder.decodeVertexBuffer(new Uint8Array(faceLanes.buffer), 4, 4, bytes.subarray(vertexAt, vertexAt + vertexStream!));
    assert.deepEqual([...pointIndices], [0, 1, 2, 3]);
    assert.deepEqual([...zIndices], [0, 0, 1, 0]);
    assert.deepEqual([...faceLanes], [0, 1, 0, 1, 2, 0, 0, 1], 'upper, then lower, u16 each');
    const indexAt = (vertexAt + vertexStream! + 3) & ~3;
    assert.equal(bytes[indexAt], 0xe1, 'the index stream at the next multiple of 4, with the index codec\'s header byte');
    assert.equal(bytes.byteLength, (indexAt + indexStream! + 3) & ~3);
  });

  test('the decoded vertex columns are the ones the renderer binds', async () => {
    assert.equal(VERTEX_BYTES, 24);
    assert.deepEqual(VERTEX_COLUMNS.map((c) => [c.name, vertexColumnOffset(VERTEX_COLUMNS.indexOf(c), 4)]), [
      ['positions', 0], ['upper', 48], ['lower', 64], ['upperClass', 80], ['lowerClass', 88],
    ]);
    const d = await decodeChunk(encodeChunk(square()));
    const buf = d.positions.buffer;
    assert.equal(d.vertexByteOffset, 0);
    assert.equal(d.vertexByteLength, 96);
    assert.deepEqual([...new Uint32Array(buf, 48, 4)], [7, 7, 8, 7], 'upper ids at their column offset');
    assert.deepEqual([...new Uint16Array(buf, 88, 4)], [0xffff, 0xffff, 2, 0xffff], 'lower classes at theirs');
    assert.equal(d.indices.byteOffset, 96, 'indices after the vertex columns');
  });

  test('decodes what it encodes, also from an unaligned buffer', async () => {
    const c = square();
    const bytes = encodeChunk(c);
    const shifted = new Uint8Array(bytes.length + 1);
    shifted.set(bytes, 1);
    for (const input of [bytes, shifted.subarray(1)]) assertSame(await decodeChunk(input), c, 0);
  });

  test('positions come back within half a grid step; z exactly as float32', async () => {
    // 1800 units: the grid is 2^(11 - 24) = 1/8192, so at most 1/16384 off.
    const c = gridChunk(60, 1800);
    const d = await decodeChunk(encodeChunk(c));
    assertSame(d, c, 2 ** -14);
    for (let k = 0; k < d.vertexCount; k++) {
      for (const j of [0, 1]) {
        const x = c.positions[3 * k + j]!, got = d.positions[3 * k + j]!;
        assert.ok(Number.isInteger(got * 8192), `vertex ${k} on the grid`);
        // From 1024 on, float32 itself keeps 1/8192: there the grid is exactly float32's rounding.
        if (x >= 1024) assert.equal(got, Math.fround(x), `vertex ${k}: as float32 would keep ${x}`);
      }
    }
  });

  test('two surfaces over the same corners share their points', async () => {
    // The square's floor (z 3) and a flat roof over it at z 9, between face 8 above and 7 below.
    const c = square();
    const roof: ChunkInput = {
      ...c,
      positions: Float32Array.from([...c.positions, 0, 0, 9, 1, 0, 9, 1, 1, 9, 0, 1, 9]),
      upper: Uint32Array.of(...Array.from(c.upper), 8, 8, 8, 8), lower: Uint32Array.of(...Array.from(c.lower), 7, 7, 7, 7),
      upperClass: Uint16Array.of(...Array.from(c.upperClass), 4, 4, 4, 4), lowerClass: Uint16Array.of(...Array.from(c.lowerClass), 2, 2, 2, 2),
      indices: Uint16Array.of(...Array.from(c.indices), 4, 5, 6, 4, 6, 7),
    };
    const bytes = encodeChunk(roof);
    assert.equal(new DataView(bytes.buffer).getUint32(64, true), 4, '8 vertices, 4 points');
    assertSame(await decodeChunk(bytes), roof, 0);
  });

  test('a small box gets a finer grid', async () => {
    // 40 units: 2^(6 - 24).
    const c = gridChunk(20, 40, 7);
    assertSame(await decodeChunk(encodeChunk(c)), c, 2 ** -19);
  });

  test('the same chunk encodes to the same bytes, and a decoded chunk re-encodes to them', async () => {
    const c = gridChunk(40, 700, 3);
    const bytes = encodeChunk(c);
    assert.deepEqual(encodeChunk(gridChunk(40, 700, 3)), bytes);
    assert.deepEqual(encodeChunk(await decodeChunk(bytes)), bytes);
  });

  test('more than 65535 vertices take 32-bit indices, more than 65535 faces 32-bit face lanes; 65538 points or z values come back', async () => {
    // Degenerate triangles, each of its own face; `V` vertices, `pointAt` and `zAt` say how many distinct.
    const chunk = (V: number, pointAt: (i: number) => [number, number], zAt: (i: number) => number): ChunkInput => {
      const positions = new Float32Array(3 * V);
      for (let i = 0; i < V; i++) positions.set([...pointAt(i), zAt(i)], 3 * i);
      const faces = Uint32Array.from({ length: V }, (_, i) => 1 + Math.floor(i / 3));
      return {
        originX: 0, originY: 0, box: new Float32Array([0, 0, 0, 1000, 1000, 70000]), positions,
        upper: faces, lower: new Uint32Array(V), upperClass: new Uint16Array(V), lowerClass: new Uint16Array(V).fill(0xffff),
        indices: Uint32Array.from({ length: V }, (_, i) => i),
      };
    };
    const few = chunk(65538, (i) => [i % 100, 0], () => 0);
    const d = await decodeChunk(encodeChunk(few));
    assert.ok(d.indices instanceof Uint32Array);
    assertSame(d, few, 0);
    // The point and z indices beyond a u16 (index sequences), and the faces in 4-byte lanes.
    const manyPoints = chunk(65538, (i) => [i % 1000, Math.floor(i / 1000)], () => 0);
    assertSame(await decodeChunk(encodeChunk(manyPoints)), manyPoints, 0);
    const manyZ = chunk(65538, () => [0, 0], (i) => i);
    assertSame(await decodeChunk(encodeChunk(manyZ)), manyZ, 0);
    const manyFaces = chunk(3 * 65536, (i) => [i % 100, 0], () => 0);
    const bytes = encodeChunk(manyFaces);
    assert.equal(new DataView(bytes.buffer).getUint32(60, true), 65537, 'every face and "nothing below"');
    assertSame(await decodeChunk(bytes), manyFaces, 0);
  });

  test('the codecs\' order keeps every triangle and its winding, and the chunk gets smaller', () => {
    const c = gridChunk(40, 700, 5);
    // The triangles in a scattered order, as a build might hand them over.
    const T = c.indices.length / 3, V = c.upper.length;
    const scattered = Uint32Array.from({ length: 3 * T }, (_, i) => c.indices[3 * ((Math.floor(i / 3) * 7919) % T) + (i % 3)]!);
    const input = { ...c, indices: scattered };
    const tri = scattered.slice();
    const renumber = orderForCodecs(tri, V);
    const old = new Uint32Array(V);
    for (let k = 0; k < V; k++) old[renumber[k]!] = k;
    assert.deepEqual(triangles(Array.from(tri, (v) => old[v]!)).sort(), triangles(scattered).sort());
    const reordered: ChunkInput = {
      ...input, indices: tri,
      positions: Float64Array.from({ length: 3 * V }, (_, i) => c.positions[3 * old[Math.floor(i / 3)]! + (i % 3)]!),
      upper: Uint32Array.from(old, (k) => c.upper[k]!), lower: Uint32Array.from(old, (k) => c.lower[k]!),
      upperClass: Uint16Array.from(old, (k) => c.upperClass[k]!), lowerClass: Uint16Array.from(old, (k) => c.lowerClass[k]!),
    };
    const before = encodeChunk(input).byteLength, after = encodeChunk(reordered).byteLength;
    assert.ok(after < before, `${after} bytes reordered, ${before} scattered`);
  });

  test('the encoder refuses a face with two classes, a vertex outside the box, a vertex in no triangle and a class beyond a u16', () => {
    const c = square();
    c.upperClass = Uint16Array.of(2, 2, 4, 3);
    assert.throws(() => encodeChunk(c), /face 7 has class 2 at one vertex and 3 at another/);
    const far = square();
    far.positions[3] = 5;
    assert.throws(() => encodeChunk(far), /vertex 1 lies outside the chunk's box/);
    const unused = square();
    unused.indices = Uint16Array.of(0, 1, 2);
    assert.throws(() => encodeChunk(unused), /vertex 3 is in no triangle/);
    // A class the decoder's u16 column cannot hold, which it would refuse.
    const wide = square();
    wide.upperClass = Uint32Array.of(70000, 70000, 4, 70000);
    assert.throws(() => encodeChunk(wide), /face 7 has class 70000, a class index is 0 to 65535/);
  });

  test('a damaged, truncated or old file is refused and the message says why', async () => {
    const good = encodeChunk(square());
    const damaged = (edit: (dv: DataView, b: Uint8Array) => void): Uint8Array => {
      const b = good.slice();
      edit(new DataView(b.buffer), b);
      return b;
    };
    const refuses = async (b: Uint8Array, pattern: RegExp): Promise<void> => {
      await assert.rejects(decodeChunk(b, 'c-x.bin'), (e: unknown) => e instanceof ChunkFormatError && e.message.startsWith('c-x.bin: ') && pattern.test(e.message));
    };
    await refuses(good.subarray(0, 40), /truncated \(40 bytes, the header alone is 100\)/);
    await refuses(good.subarray(0, 3), /truncated/);
    await refuses(damaged((dv) => dv.setUint32(0, CHUNK_MAGIC + 1, true)), /bad magic/);
    await refuses(damaged((dv) => dv.setUint32(4, 1, true)), /chunk version 1, this reader knows only versions 2 to 5 \(rebuild the cube with ssc build\)/);
    await refuses(damaged((dv) => dv.setUint32(4, 6, true)), /chunk version 6/);
    await refuses(good.subarray(0, good.length - 4), new RegExp(`${good.length - 4} bytes, its header .* needs ${good.length}`));
    // An index stream length near 2^32 would wrap the sum of the lengths round to the file's length.
    await refuses(damaged((dv) => dv.setUint32(96, 2 ** 32 - 64, true)), /bytes, its header .* needs 4\d{9}$/);
    await refuses(damaged((dv) => dv.setInt32(56, -24, true)), /position step 2\^-24 does not fit its box \(2\^-23 to 2\^64\)/);
    await refuses(damaged((dv) => dv.setInt32(56, 65, true)), /position step 2\^65 does not fit its box \(2\^-23 to 2\^64\)/);
    // Version 2 knew only the box's own grid: the version-3 fixture, on a coarser one, called version 2.
    const v3 = readFileSync(fixture('chunk-v3.bin'));
    const asV2 = new Uint8Array(v3);
    new DataView(asV2.buffer, asV2.byteOffset).setUint32(4, 2, true);
    await refuses(asV2, /position step 2\^-12 does not fit its box \(2\^-14\)/);
    await refuses(v3.subarray(0, 84), /84 bytes, its header \(\d+ faces, \d+ \+ \d+ \+ \d+ bytes of streams\) needs \d+/);
    await refuses(v3.subarray(0, 60), /truncated \(60 bytes, the header alone is 80\)/);
    await refuses(damaged((dv) => dv.setUint32(8, 2 ** 30, true)), /counts out of bounds \(2 triangles, 1073741824 vertices/);
    await refuses(damaged((dv) => dv.setUint32(12, 2 ** 30, true)), /1073741824 triangles cannot fit an index stream of \d+ bytes/);
    await refuses(damaged((dv) => dv.setUint32(64, 5, true)), /counts out of bounds \(2 triangles, 4 vertices, 5 points, 2 z values, 3 faces\)/);
    await refuses(damaged((dv) => dv.setUint32(68, 5, true)), /counts out of bounds \(2 triangles, 4 vertices, 4 points, 5 z values, 3 faces\)/);
    await refuses(damaged((dv) => dv.setUint32(84, 3, true)), /4 vertices cannot fit point and z index streams of 3 and 9 bytes/);
    await refuses(damaged((dv) => dv.setUint32(88, 3, true)), /4 vertices cannot fit point and z index streams of 9 and 3 bytes/);
    await refuses(damaged((_, b) => { b[100] = 0; }), /compressed faces, points, z values, vertices or triangles do not decode/);
    // A face stream whose second face has a class beyond the u16 column (0xffff is face 0's).
    const oldFaces = new DataView(good.buffer, good.byteOffset).getUint32(72, true);
    const badFaces = encodeFaceStream([7, 0, 8], [2, 0x10000, 4]);
    const rest = good.subarray((100 + oldFaces + 3) & ~3);
    const withBad = new Uint8Array(((100 + badFaces.length + 3) & ~3) + rest.length);
    withBad.set(good.subarray(0, 100));
    new DataView(withBad.buffer).setUint32(72, badFaces.length, true);
    withBad.set(badFaces, 100);
    withBad.set(rest, (100 + badFaces.length + 3) & ~3);
    await refuses(withBad, /face 0 has class 65536/);
    // A vertex's point index beyond the 4 points (the first index's delta made 2 larger).
    const head = new DataView(good.buffer, good.byteOffset);
    const vp = [72, 76, 80].reduce((at, o) => at + ((head.getUint32(o, true) + 3) & ~3), 100);
    assert.equal(good[vp], 0xd1, 'the point index stream where the header says');
    await refuses(damaged((_, b) => { b[vp + 1] = 8; }), /vertex \d names point [4-9] of 4/);
    // Likewise a z index beyond the 2 z values.
    const vz = vp + ((head.getUint32(84, true) + 3) & ~3);
    assert.equal(good[vz], 0xd1, 'the z index stream where the header says');
    await refuses(damaged((_, b) => { b[vz + 1] = 8; }), /vertex \d names z value [2-9] of 2/);
  });

  test('a file of version 1 (24 bytes a vertex) is refused, not misread', async () => {
    // The start of a version-1 file: magic, version 1, 4 vertices, 2 triangles, then its 64-byte header and columns.
    const v1 = new Uint8Array(64 + 96 + 12);
    const dv = new DataView(v1.buffer);
    dv.setUint32(0, CHUNK_MAGIC, true);
    dv.setUint32(4, 1, true);
    dv.setUint32(8, 4, true);
    dv.setUint32(12, 2, true);
    await assert.rejects(decodeChunk(v1, 'c-old.bin'), /c-old\.bin: chunk version 1, this reader knows only versions 2 to 5/);
  });

  test('a file of version 4 (one vertex stream of four lanes, 88-byte header) is still read', async () => {
    // Written by the version-4 encoder from this chunk on a grid of 2^-12 (testdata/README.md).
    const v4 = readFileSync(fixture('chunk-v4.bin'));
    assert.equal(new DataView(v4.buffer, v4.byteOffset).getUint32(4, true), 4);
    const d = await decodeChunk(v4);
    assert.equal(d.gridExponent, -12);
    assertSame(d, gridChunk(12, 700, 6), 2 ** -13);
    await assert.rejects(decodeChunk(v4.subarray(0, 86)), /truncated \(86 bytes, the header alone is 88\)/);
    await assert.rejects(decodeChunk(v4.subarray(0, v4.length - 4)), new RegExp(`${v4.length - 4} bytes, its header \\(\\d+ faces, \\d+ \\+ \\d+ \\+ \\d+ \\+ \\d+ bytes of streams\\) needs ${v4.length}`));
  });

  test("each version's vertex record is the one docs/FORMAT.md gives, 32-bit lanes included (the fixtures have only 16-bit ones)", () => {
    const record = (version: number, F: number, P: number, Z: number): [number, number, number] => {
      const l = chunkLayout(version)!;
      const s = l.laneSize(F, P, Z);
      return [s, l.stride(s), l.faceLane(s)];
    };
    const big = 70_000;
    // Version 5: two face indices, 2 bytes each while F <= 65535; points and z values elsewhere.
    assert.deepEqual(record(5, 10, big, big), [2, 4, 0]);
    assert.deepEqual(record(5, big, 10, 10), [4, 8, 0]);
    // Version 4: 4s bytes (point, z, upper, lower), s = 2 while P, Z and F are all <= 65535.
    assert.deepEqual(record(4, 10, 10, 10), [2, 8, 2]);
    for (const [F, P, Z] of [[big, 10, 10], [10, big, 10], [10, 10, big]] as const) assert.deepEqual(record(4, F, P, Z), [4, 16, 2]);
    // Versions 3 and 2: 8 + 2f bytes (u32 point, f32 z, two faces of f bytes), f = 2 while F <= 65535.
    for (const v of [3, 2]) {
      assert.deepEqual(record(v, 10, big, 10), [2, 12, 4]);
      assert.deepEqual(record(v, big, 10, 10), [4, 16, 2]);
    }
    assert.deepEqual([5, 4, 3, 2].map((v) => chunkLayout(v)!.headerBytes), [100, 88, 80, 80]);
    assert.deepEqual([5, 4, 3, 2].map((v) => chunkLayout(v)!.boxOwnGrid), [false, false, false, true]);
    assert.equal(chunkLayout(1), undefined);
  });

  test('files of versions 3 and 2 (a z in each vertex, 80-byte header) are still read', async () => {
    // Written by the version-3 encoder from these chunks (testdata/README.md): version 3 on a
    // grid of 2^-12, version 2 on its box's own, 2^-14.
    const v3 = await decodeChunk(readFileSync(fixture('chunk-v3.bin')));
    assert.equal(v3.gridExponent, -12);
    assertSame(v3, gridChunk(12, 700, 3), 2 ** -13);
    const v2 = await decodeChunk(readFileSync(fixture('chunk-v2.bin')));
    assert.equal(v2.gridExponent, -14);
    assertSame(v2, gridChunk(12, 700, 4), 2 ** -15);
  });

  test('on the cube\'s grid, a point two chunks share decodes to the same value in both', async () => {
    // One ground point in two chunks of different origins and sizes (a 1,500-unit chunk and a
    // 40-unit one): on each box's own grid the two decoded values differ; on the cube's grid
    // 2^-7 they are one value, and an exact multiple of the step.
    const px = 1712.345678, py = 2030.987654;
    const chunk = (ox: number, oy: number, size: number): ChunkInput => ({
      originX: ox, originY: oy, box: Float32Array.of(0, 0, 0, size, size, 1),
      positions: Float64Array.of(px - ox, py - oy, 0, size, 0, 0, 0, size, 0),
      upper: Uint32Array.of(1, 1, 1), lower: new Uint32Array(3), upperClass: new Uint16Array(3), lowerClass: new Uint16Array(3).fill(0xffff),
      indices: Uint16Array.of(0, 1, 2),
    });
    const absolute = async (ox: number, oy: number, size: number, grid?: number): Promise<[number, number]> => {
      const d = await decodeChunk(encodeChunk({ ...chunk(ox, oy, size), gridExponent: grid }));
      return [d.originX + d.positions[0]!, d.originY + d.positions[1]!];
    };
    const big = await absolute(1000, 1500, 1500), small = await absolute(1700, 2000, 40);
    assert.notDeepEqual(big, small, 'the boxes\' own grids differ (2^-13 and 2^-18)');
    const [bx, by] = await absolute(1000, 1500, 1500, -7), [sx, sy] = await absolute(1700, 2000, 40, -7);
    assert.deepEqual([bx, by], [sx, sy]);
    assert.deepEqual([bx, by], [Math.round(px * 128) / 128, Math.round(py * 128) / 128], 'the nearest 1/128');
    const bytes = encodeChunk({ ...chunk(1700, 2000, 40), gridExponent: -7 });
    assert.equal(new DataView(bytes.buffer).getInt32(56, true), -7, 'the header holds the cube\'s grid');
    // A grid finer than the box allows is not taken: the box's own.
    assert.equal(new DataView(encodeChunk({ ...chunk(1000, 1500, 1500), gridExponent: -20 }).buffer).getInt32(56, true), -13);
  });
});
