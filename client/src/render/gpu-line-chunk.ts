// A line chunk on the GPU: its segments as one instance buffer (each instance a quad around one
// segment, line.vert) and each segment's style rule, bound in a vertex array object. The
// segments and their lines stay on the CPU too, for picking.
import type { Box3 } from '../../../format/cube-index.js';
import { payloadBytes, type LinePayload } from '../source/worker-protocol.js';

/** Floats per segment: ax, ay, bx, by, z0, z1 (LinePayload.segments). */
export const SEGMENT_FLOATS = 6;

export class GpuLineChunk {
  readonly kind = 'lines';
  readonly file: string;
  readonly bbox: Box3;
  readonly originX: number;
  readonly originY: number;
  readonly segmentCount: number;
  readonly bytes: number;
  /** What picking reads (format of LinePayload). */
  readonly segments: Float32Array;
  readonly segmentLine: Uint32Array;
  readonly segmentRule: Uint16Array;
  readonly lineClass: Uint16Array;
  readonly lineFeature: Int32Array;
  private readonly lineZ: Float32Array;
  lastUsed = 0;
  private readonly vao: WebGLVertexArrayObject;
  private readonly buffers: WebGLBuffer[];

  constructor(gl: WebGL2RenderingContext, c: LinePayload) {
    this.file = c.file;
    this.bbox = c.bbox;
    this.originX = c.originX;
    this.originY = c.originY;
    this.segmentCount = c.segmentCount;
    this.bytes = payloadBytes(c);
    this.segments = c.segments;
    this.segmentLine = c.segmentLine;
    this.segmentRule = c.segmentRule;
    this.lineClass = c.lineClass;
    this.lineFeature = c.lineFeature;
    this.lineZ = c.lineZ;
    const vao = gl.createVertexArray();
    gl.bindVertexArray(vao);
    const seg = gl.createBuffer();
    gl.bindBuffer(gl.ARRAY_BUFFER, seg);
    gl.bufferData(gl.ARRAY_BUFFER, c.segments, gl.STATIC_DRAW);
    const stride = 4 * SEGMENT_FLOATS;
    gl.enableVertexAttribArray(0);
    gl.vertexAttribPointer(0, 4, gl.FLOAT, false, stride, 0);
    gl.vertexAttribDivisor(0, 1);
    gl.enableVertexAttribArray(1);
    gl.vertexAttribPointer(1, 2, gl.FLOAT, false, stride, 16);
    gl.vertexAttribDivisor(1, 1);
    const rule = gl.createBuffer();
    gl.bindBuffer(gl.ARRAY_BUFFER, rule);
    gl.bufferData(gl.ARRAY_BUFFER, c.segmentRule, gl.STATIC_DRAW);
    gl.enableVertexAttribArray(2);
    gl.vertexAttribIPointer(2, 1, gl.UNSIGNED_SHORT, 2, 0);
    gl.vertexAttribDivisor(2, 1);
    gl.bindVertexArray(null);
    gl.bindBuffer(gl.ARRAY_BUFFER, null);
    this.vao = vao;
    this.buffers = [seg, rule];
  }

  /** Line i is on the map for z0 <= z < z1. */
  lineZRange(i: number): [number, number] {
    return [this.lineZ[2 * i]!, this.lineZ[2 * i + 1]!];
  }

  /** One quad (a triangle strip of 4 vertices) per segment. */
  draw(gl: WebGL2RenderingContext): void {
    if (this.segmentCount === 0) return;
    gl.bindVertexArray(this.vao);
    gl.drawArraysInstanced(gl.TRIANGLE_STRIP, 0, 4, this.segmentCount);
  }

  delete(gl: WebGL2RenderingContext): void {
    gl.deleteVertexArray(this.vao);
    for (const b of this.buffers) gl.deleteBuffer(b);
  }
}
