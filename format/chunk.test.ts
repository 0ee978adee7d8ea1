// The chunk file: the encoder writes the byte layout of docs/FORMAT.md (checked field by
// field at offsets worked out by hand), the decoder reads it back, and a damaged file is
// refused with a message that says what is wrong.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { CHUNK_MAGIC, ChunkFormatError, decodeChunk, encodeChunk, VERTEX_BYTES, VERTEX_COLUMNS, vertexColumnOffset } from './chunk.js';

/** Two triangles over four vertices: a unit square at z 3 (floor) and 5 (tilted corner). */
function square() {
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

describe('chunk file', () => {
  test('the encoder writes the documented layout', () => {
    const bytes = encodeChunk(square());
    const dv = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
    // Header: 64 bytes. Vertex section: 4 x 24 = 96 bytes. Indices: 6 x u16 = 12 bytes.
    assert.equal(bytes.byteLength, 64 + 96 + 12);
    assert.equal(dv.getUint32(0, true), 0x43435353);
    assert.equal(dv.getUint32(4, true), 1);
    assert.equal(dv.getUint32(8, true), 4, 'vertices');
    assert.equal(dv.getUint32(12, true), 2, 'triangles');
    assert.equal(dv.getFloat64(16, true), 181000.5);
    assert.equal(dv.getFloat64(24, true), 457000.25);
    assert.equal(dv.getFloat32(32 + 4 * 5, true), 5, 'box z1');
    assert.equal(dv.getUint32(60, true), 2, 'index size');
    // Columns, one after the other: positions at 64, upper at 64 + 48, lower at 64 + 64,
    // upper class at 64 + 80, lower class at 64 + 88.
    assert.equal(dv.getFloat32(64 + 4 * 8, true), 5, 'z of vertex 2');
    assert.equal(dv.getUint32(64 + 48 + 4 * 2, true), 8, 'upper of vertex 2');
    assert.equal(dv.getUint32(64 + 64 + 4 * 2, true), 7, 'lower of vertex 2');
    assert.equal(dv.getUint16(64 + 80 + 2 * 2, true), 4, 'upper class of vertex 2');
    assert.equal(dv.getUint16(64 + 88 + 2 * 0, true), 0xffff, 'lower class of vertex 0: none');
    assert.equal(dv.getUint16(64 + 96 + 2 * 5, true), 3, 'last index');
  });

  test('the vertex columns the renderer binds are the ones written', () => {
    assert.equal(VERTEX_BYTES, 24);
    assert.deepEqual(VERTEX_COLUMNS.map((c) => [c.name, vertexColumnOffset(VERTEX_COLUMNS.indexOf(c), 4)]), [
      ['positions', 0], ['upper', 48], ['lower', 64], ['upperClass', 80], ['lowerClass', 88],
    ]);
  });

  test('decodes what it encodes, also from an unaligned buffer', () => {
    const c = square();
    const bytes = encodeChunk(c);
    const shifted = new Uint8Array(bytes.length + 1);
    shifted.set(bytes, 1);
    for (const input of [bytes, shifted.subarray(1)]) {
      const d = decodeChunk(input);
      assert.equal(d.vertexCount, 4);
      assert.equal(d.triangleCount, 2);
      assert.equal(d.originX, c.originX);
      assert.equal(d.originY, c.originY);
      assert.deepEqual([...d.box], [...c.box]);
      assert.deepEqual([...d.positions], [...c.positions]);
      assert.deepEqual([...d.upper], [...c.upper]);
      assert.deepEqual([...d.lower], [...c.lower]);
      assert.deepEqual([...d.upperClass], [...c.upperClass]);
      assert.deepEqual([...d.lowerClass], [...c.lowerClass]);
      assert.deepEqual([...d.indices], [...c.indices]);
      assert.equal(d.vertexByteLength, 96);
    }
  });

  test('more than 65535 vertices take 32-bit indices', () => {
    const V = 65536 + 2;
    const positions = new Float32Array(3 * V);
    for (let i = 0; i < V; i++) positions[3 * i] = i % 100;
    const c = {
      originX: 0, originY: 0, box: new Float32Array([0, 0, 0, 100, 0, 0]), positions,
      upper: new Uint32Array(V).fill(1), lower: new Uint32Array(V), upperClass: new Uint16Array(V), lowerClass: new Uint16Array(V),
      indices: new Uint32Array([0, 1, V - 1]),
    };
    const bytes = encodeChunk(c);
    assert.equal(new DataView(bytes.buffer).getUint32(60, true), 4);
    const d = decodeChunk(bytes);
    assert.ok(d.indices instanceof Uint32Array);
    assert.deepEqual([...d.indices], [0, 1, V - 1]);
  });

  test('a damaged file is refused and the message says why', () => {
    const good = encodeChunk(square());
    const damaged = (edit: (dv: DataView, b: Uint8Array) => Uint8Array | void): Uint8Array => {
      const b = good.slice();
      return edit(new DataView(b.buffer), b) ?? b;
    };
    const refuses = (b: Uint8Array, pattern: RegExp): void => {
      assert.throws(() => decodeChunk(b, 'c-x.bin'), (e: unknown) => e instanceof ChunkFormatError && e.message.startsWith('c-x.bin: ') && pattern.test(e.message));
    };
    refuses(good.subarray(0, 40), /truncated/);
    refuses(damaged((dv) => dv.setUint32(0, CHUNK_MAGIC + 1, true)), /bad magic/);
    refuses(damaged((dv) => dv.setUint32(4, 2, true)), /version 2/);
    refuses(good.subarray(0, good.length - 4), /bytes, 4 vertices and 2 triangles need/);
    refuses(damaged((dv) => dv.setUint16(64 + 96 + 2, 9, true)), /triangle 0 names vertex 9 of 4/);
    refuses(damaged((dv) => dv.setFloat32(64 + 4 * 4, NaN, true)), /vertex 1 has a non-finite coordinate/);
    refuses(damaged((dv) => dv.setUint32(60, 4, true)), /index size 4 does not fit 4 vertices/);
  });
});
