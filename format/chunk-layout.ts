// A decoded chunk's vertex layout, the one the GPU binds as it is (docs/FORMAT.md, "Chunk
// file"): the columns one after the other, each `vertexCount` entries long. Apart from the
// decoder (chunk.ts) so that the renderer on the main thread does not load the codec.

export const VERTEX_COLUMNS = [
  { name: 'positions', components: 3, type: 'f32', bytes: 12 },
  { name: 'upper', components: 1, type: 'u32', bytes: 4 },
  { name: 'lower', components: 1, type: 'u32', bytes: 4 },
  { name: 'upperClass', components: 1, type: 'u16', bytes: 2 },
  { name: 'lowerClass', components: 1, type: 'u16', bytes: 2 },
] as const;

export type VertexColumn = (typeof VERTEX_COLUMNS)[number];

/** Bytes per decoded vertex over all columns (24). */
export const VERTEX_BYTES = VERTEX_COLUMNS.reduce((n, c) => n + c.bytes, 0);

/** Byte offset of column `i` from the start of the decoded vertex section. */
export function vertexColumnOffset(i: number, vertexCount: number): number {
  let o = 0;
  for (let k = 0; k < i; k++) o += VERTEX_COLUMNS[k]!.bytes * vertexCount;
  return o;
}
