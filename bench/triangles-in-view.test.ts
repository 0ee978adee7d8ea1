import assert from 'node:assert/strict';
import { mkdtemp, rm, stat, writeFile } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { test } from 'node:test';
import type { ChunkData } from '../format/chunk.js';
import { encodeChunk } from '../format/chunk-encode.js';
import { parseIndex } from '../format/cube-index.js';
import { encodeFacePage, type FaceFields } from '../format/face-page.js';
import { PIXEL_SIZE_MM } from '../format/pixel-size.js';
import { scaleAtZ } from '../format/scale.js';
import { indexFile, namedLeaf } from '../testing/hand-made-cube.js';
import { forNeededTriangles, sessionNeeds } from './triangles-in-view.js';

// A chunk at origin (100, 200) with four triangles over the unit square's halves:
// 0: flat at z 0, face 1 (ends at z 5);
// 1: flat at z 0, face 2 (ends at z 3);
// 2: tilted from z 1 to z 3, face 3 (a merge's ramp, lives on);
// 3: flat at z 4, face 4, far off at x 10.
function chunk(): ChunkData {
  const corners = [
    [0, 0, 0], [1, 0, 0], [1, 1, 0],
    [0, 0, 0], [1, 1, 0], [0, 1, 0],
    [0, 0, 1], [1, 0, 2], [1, 1, 3],
    [10, 0, 4], [11, 0, 4], [11, 1, 4],
  ];
  const faces = [1, 2, 3, 4];
  const n = corners.length;
  return {
    vertexCount: n,
    triangleCount: n / 3,
    originX: 100,
    originY: 200,
    box: Float32Array.from([0, 0, 0, 11, 1, 4]),
    positions: Float32Array.from(corners.flat()),
    upper: Uint32Array.from(corners.map((_, i) => faces[Math.floor(i / 3)]!)),
    lower: new Uint32Array(n),
    upperClass: new Uint16Array(n),
    lowerClass: new Uint16Array(n),
    indices: Uint16Array.from(corners.map((_, i) => i)),
  };
}
const END = [0, 5, 3, Infinity, Infinity];
const endOf = (f: number): number => END[f]!;
const square: [number, number, number, number] = [100, 200, 101, 201];

function needed(z: number, box: [number, number, number, number]): [number, boolean][] {
  const out: [number, boolean][] = [];
  forNeededTriangles(chunk(), z, box, endOf, (t, cut) => out.push([t, cut]));
  return out;
}

test('a slice needs what lies at or below it, over its ground, whose upper face has not ended', () => {
  // Below the ramp's lowest corner: the two floor triangles, neither cut.
  assert.deepEqual(needed(0.5, square), [[0, false], [1, false]]);
  // At z 2 the ramp (corners at z 1 to 3) is cut; at 3.5 it lies below the slice, and face 2 has ended (at 3).
  assert.deepEqual(needed(2, square), [[0, false], [1, false], [2, true]]);
  assert.deepEqual(needed(3.5, square), [[0, false], [2, false]]);
  // Triangle 3 is needed only over its own ground.
  assert.deepEqual(needed(4.5, square), [[0, false], [2, false]]);
  assert.deepEqual(needed(5, square), [[2, false]]);
  assert.deepEqual(needed(4.5, [110, 200, 111, 201]), [[3, false]]);
});

test("a session's needs: each queried chunk once, the share of its triangles some view needs, and of those the share a slice cuts", async (t) => {
  const dir = await mkdtemp(path.join(tmpdir(), 'session-needs-'));
  t.after(() => rm(dir, { recursive: true, force: true }));
  // Chunk A is the chunk above; chunk B one flat triangle of face 4 at x 105 to 106, which no
  // view's ground meets, though B's index box (x 100 to 111) meets both views.
  const a = encodeChunk(chunk());
  const b = encodeChunk({
    originX: 100, originY: 200, box: Float32Array.of(5, 0, 0, 6, 1, 0),
    positions: Float32Array.of(5, 0, 0, 6, 0, 0, 6, 1, 0), upper: Uint32Array.of(4, 4, 4), lower: new Uint32Array(3),
    upperClass: new Uint16Array(3), lowerClass: new Uint16Array(3).fill(0xffff), indices: Uint16Array.of(0, 1, 2),
  });
  const la = namedLeaf([100, 200, 0, 111, 201, 10], a), lb = namedLeaf([100, 200, 0, 111, 201, 10], b);
  const index = JSON.parse(new TextDecoder().decode(indexFile({ bbox: [100, 200, 0, 111, 201, 10], children: [la, lb] }))) as { meta: { faces: unknown } };
  // The faces' ends as END gives them (steps; 11, past the top: none).
  const faces: FaceFields[] = END.map((e, f) => ({ classIndex: 0, feature: f, stepLow: 0, stepHigh: e === Infinity ? 11 : e, mergedInto: -1 }));
  index.meta.faces = { count: faces.length, pageSize: faces.length, pages: [{ first: 0, file: 'f-0.bin' }] };
  const json = JSON.stringify(index);
  await writeFile(path.join(dir, 'index.json'), json);
  await writeFile(path.join(dir, 'f-0.bin'), encodeFacePage(faces, 0, faces.length));
  await writeFile(path.join(dir, la.file), a);
  await writeFile(path.join(dir, lb.file), b);
  const meta = parseIndex(JSON.parse(json)).meta;
  // A view of 3 x 3 units round (cx, 200.5) at z: its scale is the one of that z, and it is 3 units across.
  const view = (z: number, cx: number): { scale: number; centre: [number, number]; width: number } => {
    const scale = scaleAtZ(meta, z);
    return { scale, centre: [cx, 200.5], width: 3 / ((scale * PIXEL_SIZE_MM) / 1000) };
  };
  const sizeOf = async (file: string): Promise<number> => (await stat(path.join(dir, file))).size;
  const [A, B] = [await sizeOf(la.file), await sizeOf(lb.file)];
  const run = async (vs: { z: number; cx: number }[]): Promise<number[]> => {
    const views = vs.map((v) => view(v.z, v.cx));
    // sessionNeeds takes one width in pixels for every view: these are at one z, one scale.
    const n = await sessionNeeds(dir, views.map(({ scale, centre }) => ({ scale, centre })), sizeOf, views[0]!.width, views[0]!.width);
    return [n.queriedBytes, n.neededBytes, n.cutBytes];
  };
  // At z 2 over the square: triangles 0, 1 and 2 of A's 4 (2 cut), none of B.
  assert.deepEqual(await run([{ z: 2, cx: 100.5 }]), [A + B, (3 / 4) * A, (1 / 4) * A]);
  // The same view twice counts once.
  assert.deepEqual(await run([{ z: 2, cx: 100.5 }, { z: 2, cx: 100.5 }]), [A + B, (3 / 4) * A, (1 / 4) * A]);
  // Then at z 2 over x 110 to 111 as well: triangle 3 (at z 4) lies above that slice, nothing more.
  assert.deepEqual(await run([{ z: 2, cx: 100.5 }, { z: 2, cx: 110.5 }]), [A + B, (3 / 4) * A, (1 / 4) * A]);
  // At z 4.5 there instead: triangle 3 too, not cut.
  const high = view(4.5, 110.5), low = view(2, 100.5);
  const n = await sessionNeeds(dir, [{ scale: low.scale, centre: low.centre }, { scale: high.scale, centre: high.centre }], sizeOf, low.width, low.width);
  // That view's box, at its own scale, is wider than 3 units but still misses the square (x <= 101).
  const halfWidth = (low.width / 2) * ((high.scale * PIXEL_SIZE_MM) / 1000);
  assert.ok(halfWidth > 1.5 && 110.5 - halfWidth > 101 && 110.5 - halfWidth < 110, `half width ${halfWidth}`);
  assert.deepEqual([n.queriedBytes, n.neededBytes, n.cutBytes], [A + B, A, (1 / 4) * A]);
});
