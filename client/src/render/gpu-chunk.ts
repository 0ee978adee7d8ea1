// A chunk on the GPU: its vertex section as one buffer (attributes at offsets into it, exactly
// as the file lays them out) and its triangle indices, bound in a vertex array object. It draws
// only the triangles the view can show: in a ground cell that meets the view, not above the
// slice everywhere (draw-ranges.ts), in one call where WEBGL_multi_draw is there.
import { VERTEX_COLUMNS, vertexColumnOffset } from '../../../format/chunk-layout.js';
import type { Box3 } from '../../../format/cube-index.js';
import { drawRanges, rangesFor, type DrawBlocks, type DrawRanges } from '../source/draw-ranges.js';
import type { ChunkPayload } from '../source/worker-protocol.js';

export class GpuChunk {
  readonly kind = 'surfaces';
  readonly file: string;
  readonly bbox: Box3;
  readonly originX: number;
  readonly originY: number;
  readonly triangleCount: number;
  readonly bytes: number;
  readonly indexType: number;
  /** Frame number of the last frame that drew it (least recently used goes first). */
  lastUsed = 0;
  private readonly blocks: DrawBlocks;
  private readonly ranges: DrawRanges;
  /** The ranges as the GPU takes them: index counts and byte offsets. */
  private readonly counts: Int32Array;
  private readonly offsets: Int32Array;
  private readonly rect = new Float64Array(4);
  private readonly vao: WebGLVertexArrayObject;
  private readonly buffers: WebGLBuffer[];

  constructor(gl: WebGL2RenderingContext, c: ChunkPayload) {
    this.file = c.file;
    this.bbox = c.bbox;
    this.originX = c.originX;
    this.originY = c.originY;
    this.triangleCount = c.triangleCount;
    this.blocks = c.blocks;
    this.ranges = drawRanges(c.blocks);
    this.counts = new Int32Array(this.ranges.first.length);
    this.offsets = new Int32Array(this.ranges.first.length);
    const V = c.vertexCount;
    const indexBytes = c.indexSize * 3 * c.triangleCount;
    this.bytes = c.vertexByteLength + indexBytes;
    this.indexType = c.indexSize === 2 ? gl.UNSIGNED_SHORT : gl.UNSIGNED_INT;
    const vao = gl.createVertexArray();
    gl.bindVertexArray(vao);
    const vbo = gl.createBuffer();
    gl.bindBuffer(gl.ARRAY_BUFFER, vbo);
    gl.bufferData(gl.ARRAY_BUFFER, new Uint8Array(c.buffer, c.vertexByteOffset, c.vertexByteLength), gl.STATIC_DRAW);
    // Attribute i is the file's vertex column i, read in place (format/chunk.ts).
    VERTEX_COLUMNS.forEach((col, i) => {
      gl.enableVertexAttribArray(i);
      const offset = vertexColumnOffset(i, V);
      if (col.type === 'f32') gl.vertexAttribPointer(i, col.components, gl.FLOAT, false, col.bytes, offset);
      else gl.vertexAttribIPointer(i, col.components, col.type === 'u32' ? gl.UNSIGNED_INT : gl.UNSIGNED_SHORT, col.bytes, offset);
    });
    const ibo = gl.createBuffer();
    gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, ibo);
    gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, new Uint8Array(c.buffer, c.indexByteOffset, indexBytes), gl.STATIC_DRAW);
    gl.bindVertexArray(null);
    gl.bindBuffer(gl.ARRAY_BUFFER, null);
    this.vao = vao;
    this.buffers = [vbo, ibo];
  }

  /**
   * Draws the triangles that a slicing surface up to zMax over the ground box `view` (x0, y0,
   * x1, y1, absolute) can show; returns how many.
   */
  draw(gl: WebGL2RenderingContext, zMax: number, view: ArrayLike<number>, multiDraw: WEBGL_multi_draw | null): number {
    const rect = this.rect;
    rect[0] = view[0]! - this.originX;
    rect[1] = view[1]! - this.originY;
    rect[2] = view[2]! - this.originX;
    rect[3] = view[3]! - this.originY;
    const r = rangesFor(this.blocks, zMax, rect, this.ranges);
    if (r.n === 0) return 0;
    gl.bindVertexArray(this.vao);
    const indexBytes = this.indexType === gl.UNSIGNED_SHORT ? 2 : 4;
    for (let i = 0; i < r.n; i++) {
      this.counts[i] = 3 * r.count[i]!;
      this.offsets[i] = 3 * indexBytes * r.first[i]!;
    }
    if (multiDraw && r.n > 1) multiDraw.multiDrawElementsWEBGL(gl.TRIANGLES, this.counts, 0, this.indexType, this.offsets, 0, r.n);
    else for (let i = 0; i < r.n; i++) gl.drawElements(gl.TRIANGLES, this.counts[i]!, this.indexType, this.offsets[i]!);
    return r.triangles;
  }

  delete(gl: WebGL2RenderingContext): void {
    gl.deleteVertexArray(this.vao);
    for (const b of this.buffers) gl.deleteBuffer(b);
  }
}
