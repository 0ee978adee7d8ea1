// The floor chunks (docs/FORMAT.md, "Floor chunks"): the floor triangles planned into chunks by
// ground, each chunk written as a floor chunk file: the boundaries of each face's part of it.
import type { Box3 } from '../../format/cube-index.js';
import { encodeFloorChunk, type FloorEdgeInput } from '../../format/floor-chunk-encode.js';
import { planFloorChunks, type ChunkingInput } from './chunking.js';
import { floorBoundaries } from './floor-boundaries.js';
import type { Surfaces } from './surfaces.js';

export interface FloorChunk {
  bytes: Uint8Array;
  triangles: number;
  /** Ground box, z from 0 to `top`. */
  bbox: Box3;
}

/** The floor triangles of `inp.surfaces` as floor chunk files, for the views below `top`. */
export function floorChunks(inp: ChunkingInput, top: number, classOf: (face: number) => number, gridExponent: number): FloorChunk[] {
  const s: Surfaces = inp.surfaces;
  const plan = planFloorChunks(inp, top);
  const out: FloorChunk[] = [];
  for (let c = 0; c + 1 < plan.start.length; c++) {
    const tris = plan.order.subarray(plan.start[c], plan.start[c + 1]);
    if (tris.length === 0) continue;
    // The faces' parts in this chunk: their sides that no other of the chunk's triangles of the face share.
    const ff = floorBoundaries(s, tris, inp.xs, inp.ys);
    // A whole-unit origin, as the triangle chunks have (assemble-chunk.ts).
    let ox = Infinity, oy = Infinity;
    for (const ed of ff.edges) for (const v of ed.verts) { ox = Math.min(ox, inp.xs[v]!); oy = Math.min(oy, inp.ys[v]!); }
    ox = Math.floor(ox);
    oy = Math.floor(oy);
    const edges: FloorEdgeInput[] = ff.edges.map((ed) => {
      const xy = new Float64Array(2 * ed.verts.length);
      ed.verts.forEach((v, k) => { xy[2 * k] = inp.xs[v]! - ox; xy[2 * k + 1] = inp.ys[v]! - oy; });
      return { xy, left: ed.left, right: ed.right };
    });
    const { bytes, triangles, ground } = encodeFloorChunk({
      originX: ox, originY: oy, faces: ff.faces, classes: ff.faces.map(classOf), edges, gridExponent,
      // The face's own floor triangles where earcut fails on the grid's points.
      triangles: (f) => ff.trianglesOf.get(f)!.flatMap((i) => [0, 1, 2].flatMap((j) => {
        const v = s.v[3 * i + j]!;
        return [inp.xs[v]! - ox, inp.ys[v]! - oy];
      })),
    });
    out.push({ bytes, triangles, bbox: [ox + ground[0], oy + ground[1], 0, ox + ground[2], oy + ground[3], top] });
  }
  return out;
}
