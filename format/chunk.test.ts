// The chunk file, version 6: the encoder writes the header and face table of docs/FORMAT.md
// (checked at offsets worked out by hand), the decoder gives back what went in (positions
// within half a grid step, everything else exactly; a level piece as other triangles over the
// same ground), and a damaged, truncated or old file is refused with a message that says what
// is wrong.
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { describe, test } from 'node:test';
import { fileURLToPath } from 'node:url';
import { encodeChunk, encodeFaceStream, encodeSequence, orderForCodecs, type ChunkInput } from './chunk-encode.js';
import { VERTEX_BYTES, VERTEX_COLUMNS, vertexColumnOffset } from './chunk-layout.js';
import { MeshoptDecoder } from 'meshoptimizer/decoder';
import { CHUNK_MAGIC, ChunkFormatError, chunkLayout, decodeChunk, type DecodedChunk } from './chunk.js';
import { cover } from '../testing/triangle-cover.js';

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

/**
 * Level pieces and others at z 2 and 3: a square frame (0..4 with a hole 1..3, 8 triangles, face
 * 5 over nothing), a square fanned round its centre (10..12, 4 triangles, face 6 over 5), two
 * triangles of one piece that overlap (face 9), one turned over (face 10) and a tilted one (face 11).
 */
function levelChunk(): ChunkInput {
  const pos: number[] = [], up: number[] = [], low: number[] = [], idx: number[] = [];
  const cls = (f: number): number => (f === 0 ? 0xffff : f % 4);
  const tri = (pts: [number, number, number][], u: number, l: number): void => {
    for (const [x, y, z] of pts) {
      idx.push(up.length);
      pos.push(x, y, z);
      up.push(u);
      low.push(l);
    }
  };
  const o: [number, number][] = [[0, 0], [4, 0], [4, 4], [0, 4]], h: [number, number][] = [[1, 1], [3, 1], [3, 3], [1, 3]];
  for (let k = 0; k < 4; k++) {
    const [a, b, p, q] = [o[k]!, o[(k + 1) % 4]!, h[(k + 1) % 4]!, h[k]!];
    tri([[...a, 2], [...b, 2], [...p, 2]], 5, 0);
    tri([[...a, 2], [...p, 2], [...q, 2]], 5, 0);
  }
  const f: [number, number][] = [[10, 10], [12, 10], [12, 12], [10, 12]];
  for (let k = 0; k < 4; k++) tri([[...f[k]!, 2], [...f[(k + 1) % 4]!, 2], [11, 11, 2]], 6, 5);
  tri([[20, 0, 3], [22, 0, 3], [20, 2, 3]], 9, 0);
  tri([[20, 0, 3], [22, 0, 3], [21, 2, 3]], 9, 0);
  tri([[30, 0, 3], [30, 2, 3], [32, 0, 3]], 10, 0);
  tri([[40, 0, 2], [42, 0, 3], [40, 2, 3]], 11, 10);
  // One vertex per point of a piece, as a built chunk shares them.
  const key = (i: number): string => `${pos[3 * i]},${pos[3 * i + 1]},${pos[3 * i + 2]},${up[i]},${low[i]}`;
  const at = new Map<string, number>(), keep: number[] = [];
  const indices = idx.map((i) => {
    let v = at.get(key(i));
    if (v === undefined) at.set(key(i), (v = keep.push(i) - 1));
    return v;
  });
  const U = keep.map((i) => up[i]!), D = keep.map((i) => low[i]!);
  return {
    originX: 1000, originY: 2000, box: Float32Array.of(0, 0, 2, 42, 12, 3),
    positions: Float64Array.from(keep.flatMap((i) => [pos[3 * i]!, pos[3 * i + 1]!, pos[3 * i + 2]!])),
    upper: Uint32Array.from(U), lower: Uint32Array.from(D), upperClass: Uint16Array.from(U, cls), lowerClass: Uint16Array.from(D, cls),
    indices: Uint16Array.from(indices),
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

type Columns = Pick<ChunkInput, 'positions' | 'upper' | 'lower' | 'upperClass' | 'lowerClass' | 'indices'>;

/**
 * A chunk as what it draws: its triangles that are not level, each as its three corners (x, y
 * through `round`, z as float32, faces, classes) from its smallest corner on; and its level
 * triangles by piece (z, faces and classes), as corner coordinates.
 */
function drawn(c: Columns, round: (v: number) => number): { tilted: string[]; level: Map<string, number[][]> } {
  const tilted: string[] = [];
  const level = new Map<string, number[][]>();
  for (let t = 0; t < c.indices.length / 3; t++) {
    const vs = [0, 1, 2].map((j) => c.indices[3 * t + j]!);
    const zs = vs.map((v) => Math.fround(c.positions[3 * v + 2]!));
    const corner = (v: number): string => `${round(c.positions[3 * v]!)},${round(c.positions[3 * v + 1]!)},${Math.fround(c.positions[3 * v + 2]!)},${c.upper[v]},${c.lower[v]},${c.upperClass[v]},${c.lowerClass[v]}`;
    if (zs[0] === zs[1] && zs[1] === zs[2]) {
      const v = vs[0]!;
      const key = `${zs[0]}|${c.upper[v]}|${c.lower[v]}|${c.upperClass[v]}|${c.lowerClass[v]}`;
      if (!level.has(key)) level.set(key, []);
      // From its lowest corner (x, then y) on: the codec may turn a triangle.
      const xy = vs.map((u) => [round(c.positions[3 * u]!), round(c.positions[3 * u + 1]!)] as const);
      const m = xy.reduce((b, p, i) => (p[0] < xy[b]![0] || (p[0] === xy[b]![0] && p[1] < xy[b]![1]) ? i : b), 0);
      level.get(key)!.push([0, 1, 2].flatMap((j) => xy[(m + j) % 3]!));
      continue;
    }
    const s = vs.map(corner);
    const m = s.indexOf([...s].sort()[0]!);
    tilted.push([s[m], s[(m + 1) % 3], s[(m + 2) % 3]].join(' '));
  }
  return { tilted: tilted.sort(), level };
}

const area2 = (t: number[]): number => (t[2]! - t[0]!) * (t[5]! - t[1]!) - (t[4]! - t[0]!) * (t[3]! - t[1]!);

/**
 * Asserts the decoded chunk draws what the input does, its positions on the input's within
 * `tol` ground units: the same triangles that are not level, exactly (positions on the grid);
 * and per level piece the same area, with every triangle of either side, at its centre, under
 * exactly one triangle of the other's piece and of its own (the reader may cut a level piece
 * into other triangles).
 */
function assertSame(d: DecodedChunk, c: ChunkInput, tol: number): void {
  assert.equal(d.originX, c.originX);
  assert.equal(d.originY, c.originY);
  assert.deepEqual([...d.box], [...c.box]);
  const step = 2 ** d.gridExponent;
  const round = (v: number): number => Math.round(v / step) * step;
  let worst = 0;
  for (let k = 0; k < c.upper.length; k++) worst = Math.max(worst, Math.abs(round(c.positions[3 * k]!) - c.positions[3 * k]!), Math.abs(round(c.positions[3 * k + 1]!) - c.positions[3 * k + 1]!));
  assert.ok(worst <= tol, `positions off by up to ${worst}, at most ${tol} allowed`);
  const got = drawn(d, (v) => v), want = drawn(c, round);
  assert.deepEqual(got.tilted, want.tilted);
  assert.deepEqual([...got.level.keys()].sort(), [...want.level.keys()].sort());
  for (const [key, tris] of want.level) {
    const back = got.level.get(key)!;
    const sum = (ts: number[][]): number => ts.reduce((a, t) => a + area2(t), 0);
    assert.equal(sum(back), sum(tris), `piece ${key}: area`);
    // A piece that overlaps itself, or has a triangle turned over or of no area, stays as its triangles.
    const same = String(back.map(String).sort()) === String(tris.map(String).sort());
    if (!tris.every((t) => area2(t) > 0)) assert.ok(same, `piece ${key}: its own triangles`);
    if (same) continue;
    assert.ok(back.every((t) => area2(t) > 0), `piece ${key}: every triangle counterclockwise`);
    for (const t of [...tris, ...back].filter((u) => area2(u) > 0)) {
      // A point inside, off the centre (which may lie on a side of the other cut).
      const x = 0.6 * t[0]! + 0.25 * t[2]! + 0.15 * t[4]!, y = 0.6 * t[1]! + 0.25 * t[3]! + 0.15 * t[5]!;
      assert.equal(cover(back, x, y), 1, `piece ${key}: (${x}, ${y}) under one decoded triangle`);
      assert.equal(cover(tris, x, y), 1, `piece ${key}: (${x}, ${y}) under one of the input's`);
    }
  }
}

/** A copy of a good file with `edit` applied to it. */
function damagedCopy(good: Uint8Array, edit: (dv: DataView, b: Uint8Array) => void): Uint8Array {
  const b = good.slice();
  edit(new DataView(b.buffer), b);
  return b;
}

/** Asserts the decoder refuses `b` (read as c-x.bin) with a ChunkFormatError that names the file and matches `pattern`. */
async function refuses(b: Uint8Array, pattern: RegExp): Promise<void> {
  await assert.rejects(decodeChunk(b, 'c-x.bin'), (e: unknown) => e instanceof ChunkFormatError && e.message.startsWith('c-x.bin: ') && pattern.test(e.message));
}

describe('chunk file', () => {
  test('the encoder writes the documented header and face table', async () => {
    const bytes = encodeChunk(square());
    const dv = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
    assert.equal(dv.getUint32(0, true), 0x43435353);
    assert.equal(dv.getUint32(4, true), 6, 'version');
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
    // Both triangles are tilted: no ring piece.
    assert.deepEqual([100, 104, 108].map((o) => dv.getUint32(o, true)), [0, 0, 0], 'ring pieces, rings, ring points');
    const [pieceStream, ringLengthStream, ringPointStream] = [112, 116, 120].map((o) => dv.getUint32(o, true));
    // The face stream at 124: records of u32 id, u32 class through the vertex codec.
    assert.equal(bytes[124], 0xa1, 'the face stream starts at 124 with the vertex codec\'s version-1 header byte');
    await MeshoptDecoder.ready;
    const faces = new Uint32Array(6);
    MeshoptDecoder.decodeVertexBuffer(new Uint8Array(faces.buffer), 3, 8, bytes.subarray(124, 124 + faceStream!));
    assert.deepEqual([...faces], [7, 2, 0, 0xffff, 8, 4], 'ids in order of first mention (upper before lower), each with its class');
    const pointAt = (124 + faceStream! + 3) & ~3;
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
    // The three ring streams, empty: index sequences of no index (the codec's header byte and its tail).
    const pieceAt = (indexAt + indexStream! + 3) & ~3;
    const ringLengthAt = (pieceAt + pieceStream! + 3) & ~3, ringPointAt = (ringLengthAt + ringLengthStream! + 3) & ~3;
    for (const at of [pieceAt, ringLengthAt, ringPointAt]) assert.equal(bytes[at], 0xd1);
    assert.equal(bytes.byteLength, (ringPointAt + ringPointStream! + 3) & ~3);
  });

  test('a level piece goes as the rings round it, which the reader cuts into triangles over the same ground', async () => {
    const c = levelChunk();
    const bytes = encodeChunk(c);
    const dv = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
    // Given as triangles: the tilted one, the two that overlap and the one turned over.
    assert.equal(dv.getUint32(12, true), 4, 'triangles given as such');
    assert.deepEqual([100, 104, 108].map((o) => dv.getUint32(o, true)), [2, 3, 12], 'two pieces: the frame (outer ring and hole), the fan\'s square');
    const d = await decodeChunk(bytes);
    assertSame(d, c, 0);
    // A frame of 8 corners and a hole: 8 triangles; the fan's square without its centre: 2.
    assert.equal(d.triangleCount, 4 + 8 + 2);
    assert.equal(d.vertexCount, 10 + 8 + 4);
    assert.deepEqual(encodeChunk(levelChunk()), bytes, 'the same input, the same bytes');
    assert.deepEqual(encodeChunk(d), bytes, 'and a decoded chunk re-encodes to them');
  });

  test('a chunk of level pieces only, and one whose pieces take it past 65535 vertices (32-bit indices)', async () => {
    // The frame and the fan of levelChunk, without the triangles given as such.
    const all = levelChunk();
    const keep = Array.from({ length: 12 }, (_, t) => t);
    const used = [...new Set(keep.flatMap((t) => [0, 1, 2].map((k) => all.indices[3 * t + k]!)))].sort((a, b) => a - b);
    const at = new Map(used.map((v, i) => [v, i]));
    const pick = <A extends ArrayLike<number>>(a: A, n = 1): number[] => used.flatMap((v) => Array.from({ length: n }, (_, k) => a[n * v + k]!));
    const level: ChunkInput = {
      ...all, positions: pick(all.positions, 3), upper: pick(all.upper), lower: pick(all.lower), upperClass: pick(all.upperClass), lowerClass: pick(all.lowerClass),
      indices: keep.flatMap((t) => [0, 1, 2].map((k) => at.get(all.indices[3 * t + k]!)!)),
    };
    const bytes = encodeChunk(level);
    assert.deepEqual([8, 12].map((o) => new DataView(bytes.buffer).getUint32(o, true)), [0, 0], 'no vertex, no triangle given as such');
    const d = await decodeChunk(bytes);
    assertSame(d, level, 0);
    // 17,689 unit squares of one piece (two triangles each) beside one tilted triangle: 3 vertices given as such.
    const positions: number[] = [], indices: number[] = [];
    for (let a = 0; a < 133; a++) {
      for (let b = 0; b < 133; b++) {
        const v = positions.length / 3;
        positions.push(2 * a, 2 * b, 1, 2 * a + 1, 2 * b, 1, 2 * a + 1, 2 * b + 1, 1, 2 * a, 2 * b + 1, 1);
        indices.push(v, v + 1, v + 2, v, v + 2, v + 3);
      }
    }
    const v0 = positions.length / 3;
    positions.push(0, 0, 1, 10, 0, 2, 0, 10, 2);
    indices.push(v0, v0 + 1, v0 + 2);
    const V = v0 + 3;
    const big: ChunkInput = {
      originX: 0, originY: 0, box: Float32Array.of(0, 0, 1, 266, 266, 2), positions,
      upper: new Uint32Array(V).fill(3), lower: new Uint32Array(V), upperClass: new Uint16Array(V).fill(1), lowerClass: new Uint16Array(V).fill(0xffff), indices,
    };
    const bytes2 = encodeChunk(big);
    assert.deepEqual([8, 100, 104, 108].map((o) => new DataView(bytes2.buffer).getUint32(o, true)), [3, 1, 133 * 133, 4 * 133 * 133]);
    const bb = await decodeChunk(bytes2);
    assert.ok(bb.indices instanceof Uint32Array);
    assert.equal(bb.vertexCount, V);
    assert.equal(bb.triangleCount, indices.length / 3);
    assert.equal(Math.max(...bb.indices), V - 1);
  });

  test('a damaged ring piece is refused and the message says why', async () => {
    const good = encodeChunk(levelChunk());
    const dv = new DataView(good.buffer, good.byteOffset, good.byteLength);
    const damaged = (edit: (dv: DataView, b: Uint8Array) => void): Uint8Array => damagedCopy(good, edit);
    await refuses(damaged((d) => d.setUint32(100, 4, true)), /ring counts out of bounds \(4 pieces, 3 rings, 12 ring points/);
    await refuses(damaged((d) => d.setUint32(108, 2 ** 30, true)), /ring counts out of bounds \(2 pieces, 3 rings, 1073741824 ring points in \d+ \+ \d+ \+ \d+ bytes\)/);
    await refuses(damaged((d) => d.setUint32(64, 100, true)), /counts out of bounds \(4 triangles, 10 vertices, 100 points, 2 z values, 6 faces, 2 ring pieces, 12 ring points\)/);
    // The piece records, ring lengths and ring points re-written: a ring point beyond the table, a
    // piece of no ring, a ring of 2 points, a face beyond the table, rings left over.
    const withStreams = (pieces: number[], lengths: number[], points: number[], G = pieces.length / 4): Uint8Array => {
      const parts = [pieces, lengths, points].map((v) => encodeSequence(Uint32Array.from(v)));
      const start = [72, 76, 80, 84, 88, 92, 96].reduce((at, o) => at + ((dv.getUint32(o, true) + 3) & ~3), 124);
      const b = new Uint8Array(start + parts.reduce((n, q) => n + ((q.length + 3) & ~3), 0));
      b.set(good.subarray(0, start));
      const h = new DataView(b.buffer);
      [G, lengths.length, points.length].forEach((v, i) => h.setUint32(100 + 4 * i, v, true));
      let at = start;
      parts.forEach((q, i) => {
        h.setUint32(112 + 4 * i, q.length, true);
        b.set(q, at);
        at += (q.length + 3) & ~3;
      });
      return b;
    };
    const P = dv.getUint32(64, true);
    assert.equal(P, 22, 'the 12 ring points, then the 10 of the triangles given as such');
    const twelve = Array.from({ length: 12 }, (_, i) => i);
    await refuses(withStreams([0, 0, 1, 1], [12], [...twelve.slice(0, 11), P]), /a ring names point 22 of 22/);
    await refuses(withStreams([0, 0, 1, 0], [12], twelve), /ring piece 0 has 0 rings, 1 are left/);
    await refuses(withStreams([0, 0, 1, 2], [2, 10], twelve), /ring 0 has 2 points/);
    await refuses(withStreams([0, 9, 1, 1], [12], twelve), /ring piece 0 names z value 0 of 2 or faces 9 and 1 of 6/);
    await refuses(withStreams([0, 0, 1, 1], [3, 9], twelve), /1 rings and 9 ring points belong to no piece/);
    await refuses(withStreams([], [12], twelve, 0), /1 rings and 12 ring points belong to no piece/);
    assert.ok((await decodeChunk(withStreams([0, 0, 1, 1], [12], twelve))).triangleCount >= 4, 'the same streams, whole, are read');
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
    for (let k = 0; k < d.vertexCount; k++) for (const j of [0, 1]) assert.ok(Number.isInteger(d.positions[3 * k + j]! * 8192), `vertex ${k} on the grid`);
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
    const damaged = (edit: (dv: DataView, b: Uint8Array) => void): Uint8Array => damagedCopy(good, edit);
    await refuses(good.subarray(0, 40), /truncated \(40 bytes, the header alone is 124\)/);
    await refuses(good.subarray(0, 3), /truncated/);
    await refuses(damaged((dv) => dv.setUint32(0, CHUNK_MAGIC + 1, true)), /bad magic/);
    await refuses(damaged((dv) => dv.setUint32(4, 1, true)), /chunk version 1, this reader knows only versions 2 to 6 \(rebuild the cube with ssc build\)/);
    await refuses(damaged((dv) => dv.setUint32(4, 7, true)), /chunk version 7/);
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
    await refuses(damaged((dv) => dv.setUint32(64, 5, true)), /counts out of bounds \(2 triangles, 4 vertices, 5 points, 2 z values, 3 faces, 0 ring pieces, 0 ring points\)/);
    await refuses(damaged((dv) => dv.setUint32(68, 5, true)), /counts out of bounds \(2 triangles, 4 vertices, 4 points, 5 z values, 3 faces, 0 ring pieces, 0 ring points\)/);
    await refuses(damaged((dv) => dv.setUint32(84, 3, true)), /4 vertices cannot fit point and z index streams of 3 and 9 bytes/);
    await refuses(damaged((dv) => dv.setUint32(88, 3, true)), /4 vertices cannot fit point and z index streams of 9 and 3 bytes/);
    await refuses(damaged((_, b) => { b[124] = 0; }), /compressed faces, points, z values, vertices, triangles or ring pieces do not decode/);
    // A face stream whose second face has a class beyond the u16 column (0xffff is face 0's).
    const oldFaces = new DataView(good.buffer, good.byteOffset).getUint32(72, true);
    const badFaces = encodeFaceStream([7, 0, 8], [2, 0x10000, 4]);
    const rest = good.subarray((124 + oldFaces + 3) & ~3);
    const withBad = new Uint8Array(((124 + badFaces.length + 3) & ~3) + rest.length);
    withBad.set(good.subarray(0, 124));
    new DataView(withBad.buffer).setUint32(72, badFaces.length, true);
    withBad.set(badFaces, 124);
    withBad.set(rest, (124 + badFaces.length + 3) & ~3);
    await refuses(withBad, /face 0 has class 65536/);
    // A vertex's point index beyond the 4 points (the first index's delta made 2 larger).
    const head = new DataView(good.buffer, good.byteOffset);
    const vp = [72, 76, 80].reduce((at, o) => at + ((head.getUint32(o, true) + 3) & ~3), 124);
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
    await assert.rejects(decodeChunk(v1, 'c-old.bin'), /c-old\.bin: chunk version 1, this reader knows only versions 2 to 6/);
  });

  // Written by the older encoders from these chunks on a grid of 2^-12 (testdata/README.md).
  const fixtures = [
    { version: 5, what: 'every triangle given as such', headerBytes: 100, seed: 8, streams: 7 },
    { version: 4, what: 'one vertex stream of four lanes', headerBytes: 88, seed: 6, streams: 4 },
  ] as const;
  for (const { version, what, headerBytes, seed, streams } of fixtures) {
    test(`a file of version ${version} (${what}, ${headerBytes}-byte header) is still read`, async () => {
      const bytes = readFileSync(fixture(`chunk-v${version}.bin`));
      assert.equal(new DataView(bytes.buffer, bytes.byteOffset).getUint32(4, true), version);
      const d = await decodeChunk(bytes);
      assert.equal(d.gridExponent, -12);
      assertSame(d, gridChunk(12, 700, seed), 2 ** -13);
      await assert.rejects(decodeChunk(bytes.subarray(0, headerBytes - 2)), new RegExp(`truncated \\(${headerBytes - 2} bytes, the header alone is ${headerBytes}\\)`));
      const short = bytes.length - 4;
      await assert.rejects(decodeChunk(bytes.subarray(0, short)), new RegExp(`${short} bytes, its header \\(\\d+ faces, (\\d+ \\+ ){${streams - 1}}\\d+ bytes of streams\\) needs ${bytes.length}`));
    });
  }

  test("each version's vertex record is the one docs/FORMAT.md gives, 32-bit lanes included (the fixtures have only 16-bit ones)", () => {
    const record = (version: number, F: number, P: number, Z: number): [number, number, number] => {
      const l = chunkLayout(version)!;
      const s = l.laneSize(F, P, Z);
      return [s, l.stride(s), l.faceLane(s)];
    };
    const big = 70_000;
    // Versions 6 and 5: two face indices, 2 bytes each while F <= 65535; points and z values elsewhere.
    for (const v of [6, 5]) {
      assert.deepEqual(record(v, 10, big, big), [2, 4, 0]);
      assert.deepEqual(record(v, big, 10, 10), [4, 8, 0]);
    }
    // Version 4: 4s bytes (point, z, upper, lower), s = 2 while P, Z and F are all <= 65535.
    assert.deepEqual(record(4, 10, 10, 10), [2, 8, 2]);
    for (const [F, P, Z] of [[big, 10, 10], [10, big, 10], [10, 10, big]] as const) assert.deepEqual(record(4, F, P, Z), [4, 16, 2]);
    // Versions 3 and 2: 8 + 2f bytes (u32 point, f32 z, two faces of f bytes), f = 2 while F <= 65535.
    for (const v of [3, 2]) {
      assert.deepEqual(record(v, 10, big, 10), [2, 12, 4]);
      assert.deepEqual(record(v, big, 10, 10), [4, 16, 2]);
    }
    assert.deepEqual([6, 5, 4, 3, 2].map((v) => chunkLayout(v)!.headerBytes), [124, 100, 88, 80, 80]);
    assert.deepEqual([6, 5, 4, 3, 2].map((v) => chunkLayout(v)!.boxOwnGrid), [false, false, false, false, true]);
    assert.deepEqual([6, 5, 4, 3, 2].map((v) => chunkLayout(v)!.rings), [true, false, false, false, false]);
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
