// A chunk on the GPU: its vertex section as one buffer (attributes at offsets into it, exactly
// as the file lays them out) and its triangle indices, bound in a vertex array object.
import type { Box3 } from '../shared/cube-index.js';
import type { ChunkPayload } from '../source/worker-protocol.js';

export class GpuChunk {
  readonly file: string;
  readonly bbox: Box3;
  readonly originX: number;
  readonly originY: number;
  readonly triangleCount: number;
  readonly bytes: number;
  readonly indexType: number;
  /** Frame number of the last frame that drew it (least recently used goes first). */
  lastUsed = 0;
  private readonly vao: WebGLVertexArrayObject;
  private readonly buffers: WebGLBuffer[];

  constructor(gl: WebGL2RenderingContext, c: ChunkPayload) {
    this.file = c.file;
    this.bbox = c.bbox;
    this.originX = c.originX;
    this.originY = c.originY;
    this.triangleCount = c.triangleCount;
    const V = c.vertexCount;
    const indexBytes = c.indexSize * 3 * c.triangleCount;
    this.bytes = c.vertexByteLength + indexBytes;
    this.indexType = c.indexSize === 2 ? gl.UNSIGNED_SHORT : gl.UNSIGNED_INT;
    const vao = gl.createVertexArray();
    gl.bindVertexArray(vao);
    const vbo = gl.createBuffer();
    gl.bindBuffer(gl.ARRAY_BUFFER, vbo);
    gl.bufferData(gl.ARRAY_BUFFER, new Uint8Array(c.buffer, c.vertexByteOffset, c.vertexByteLength), gl.STATIC_DRAW);
    // Layout of the file's vertex section: positions (3 f32), upper and lower face (u32),
    // upper and lower class (u16).
    gl.enableVertexAttribArray(0);
    gl.vertexAttribPointer(0, 3, gl.FLOAT, false, 12, 0);
    gl.enableVertexAttribArray(1);
    gl.vertexAttribIPointer(1, 1, gl.UNSIGNED_INT, 4, 12 * V);
    gl.enableVertexAttribArray(2);
    gl.vertexAttribIPointer(2, 1, gl.UNSIGNED_INT, 4, 16 * V);
    gl.enableVertexAttribArray(3);
    gl.vertexAttribIPointer(3, 1, gl.UNSIGNED_SHORT, 2, 20 * V);
    gl.enableVertexAttribArray(4);
    gl.vertexAttribIPointer(4, 1, gl.UNSIGNED_SHORT, 2, 22 * V);
    const ibo = gl.createBuffer();
    gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, ibo);
    gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, new Uint8Array(c.buffer, c.indexByteOffset, indexBytes), gl.STATIC_DRAW);
    gl.bindVertexArray(null);
    gl.bindBuffer(gl.ARRAY_BUFFER, null);
    this.vao = vao;
    this.buffers = [vbo, ibo];
  }

  draw(gl: WebGL2RenderingContext): void {
    gl.bindVertexArray(this.vao);
    gl.drawElements(gl.TRIANGLES, 3 * this.triangleCount, this.indexType, 0);
  }

  delete(gl: WebGL2RenderingContext): void {
    gl.deleteVertexArray(this.vao);
    for (const b of this.buffers) gl.deleteBuffer(b);
  }
}
