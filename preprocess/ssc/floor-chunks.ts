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
    // The faces' pieces in this chunk: their sides that no other of the chunk's triangles of the face share.
    const ff = floorBoundaries(s, tris, inp.xs, inp.ys);
    let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
    for (let fi = 0; fi < ff.faces.length; fi++) {
      x0 = Math.min(x0, ff.box[4 * fi]!); y0 = Math.min(y0, ff.box[4 * fi + 1]!);
      x1 = Math.max(x1, ff.box[4 * fi + 2]!); y1 = Math.max(y1, ff.box[4 * fi + 3]!);
    }
    // A whole-unit origin, as the triangle chunks have (assemble-chunk.ts).
    const ox = Math.floor(x0), oy = Math.floor(y0);
    const edges: FloorEdgeInput[] = ff.edges.map((ed) => {
      const xy = new Float64Array(2 * ed.verts.length);
      ed.verts.forEach((v, k) => { xy[2 * k] = inp.xs[v]! - ox; xy[2 * k + 1] = inp.ys[v]! - oy; });
      return { xy, left: ed.left, right: ed.right };
    });
    const { bytes, triangles } = encodeFloorChunk({
      originX: ox, originY: oy, faces: ff.faces, classes: ff.faces.map(classOf), edges, gridExponent,
      // The face's own floor triangles where earcut fails on the grid's points.
      triangles: (f) => ff.trianglesOf[ff.faces.indexOf(f)]!.flatMap((i) => [0, 1, 2].flatMap((j) => {
        const v = s.v[3 * i + j]!;
        return [inp.xs[v]! - ox, inp.ys[v]! - oy];
      })),
    });
    out.push({ bytes, triangles, bbox: [x0, y0, 0, x1, y1, top] });
  }
  return out;
}
