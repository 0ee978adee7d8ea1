// A line chunk on the GPU: a quad around each segment (line.vert), its four corners each
// carrying the segment, its line's ramp (format/line-ramp.ts) and its style rule, bound in a
// vertex array object. Not instanced: a software GPU (SwiftShader) sets up each instance as a
// draw of its own, which cost more than the fragments of every line. The segments and their
// lines stay on the CPU too, for picking.
//
// A slice meets only the segments alive at its z, a small part of a chunk's (each segment of
// each simplified version of each line lives over a short z range). The buffers hold those that
// meet a z window around the slice's range, chosen again when the slice leaves it: drawing a
// frame then costs the segments near its z, not the whole chunk's.
import type { Box3 } from '../../../format/cube-index.js';
import { glideShare } from '../../../format/line-glide.js';
import type { LineRamp } from '../../../format/line-ramp.js';
import { payloadBytes, type LinePayload } from '../source/worker-protocol.js';

/** Floats per segment: ax, ay, bx, by, z0, z1, atx, aty, btx, bty, aFrom, aTo, bFrom, bTo (LinePayload.segments). */
export const SEGMENT_FLOATS = 14;
/** Floats per corner of a segment's quad: the segment's, then its line's ramp (z0, z0Full, z1Full, z1). */
const CORNER_FLOATS = SEGMENT_FLOATS + 4;
/** Two triangles of a quad, over its corners in line.vert's order (a-left, a-right, b-left, b-right). */
const QUAD = [0, 1, 2, 2, 1, 3];

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
  private readonly lineRamps: Float32Array;
  lastUsed = 0;
  private readonly vao: WebGLVertexArrayObject;
  private readonly buffers: WebGLBuffer[];
  /** The z window the buffers hold the segments of, and how many they hold. */
  private window: [number, number] = [Infinity, -Infinity];
  private drawn = 0;
  /** How many segments the buffers have room for: those of the largest window so far. */
  private capacity = 0;

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
    this.lineRamps = c.lineRamp;
    const vao = gl.createVertexArray();
    gl.bindVertexArray(vao);
    const seg = gl.createBuffer();
    gl.bindBuffer(gl.ARRAY_BUFFER, seg);
    const stride = 4 * CORNER_FLOATS;
    // Per corner, float attributes at these locations: the ends (a, b), their z range, where
    // the ends glide to, when they glide, and the line's ramp (line.vert).
    const floats: [location: number, size: number, offset: number][] = [[0, 4, 0], [1, 2, 16], [4, 4, 24], [5, 4, 40], [3, 4, 4 * SEGMENT_FLOATS]];
    for (const [location, size, offset] of floats) {
      gl.enableVertexAttribArray(location);
      gl.vertexAttribPointer(location, size, gl.FLOAT, false, stride, offset);
    }
    const rule = gl.createBuffer();
    gl.bindBuffer(gl.ARRAY_BUFFER, rule);
    gl.enableVertexAttribArray(2);
    gl.vertexAttribIPointer(2, 1, gl.UNSIGNED_SHORT, 2, 0);
    const index = gl.createBuffer();
    gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, index);
    gl.bindVertexArray(null);
    gl.bindBuffer(gl.ARRAY_BUFFER, null);
    gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, null);
    this.vao = vao;
    this.buffers = [seg, rule, index];
  }

  /** Line i is on the map for z0 <= z < z1, full width between z0Full and z1Full. */
  lineRamp(i: number): LineRamp {
    const r = this.lineRamps;
    return { z0: r[4 * i]!, z0Full: r[4 * i + 1]!, z1Full: r[4 * i + 2]!, z1: r[4 * i + 3]! };
  }

  /** Segment k's ends at z (relative to the origin), its vertices glided as far as they are then: [ax, ay, bx, by]. */
  segmentAt(k: number, z: number): [number, number, number, number] {
    const s = this.segments, o = SEGMENT_FLOATS * k;
    const ga = glideShare(s[o + 10]!, s[o + 11]!, z), gb = glideShare(s[o + 12]!, s[o + 13]!, z);
    return [s[o]! + (s[o + 6]! - s[o]!) * ga, s[o + 1]! + (s[o + 7]! - s[o + 1]!) * ga, s[o + 2]! + (s[o + 8]! - s[o + 2]!) * gb, s[o + 3]! + (s[o + 9]! - s[o + 3]!) * gb];
  }

  /** Whether segment k is drawn at z (by its own range, before its rule's). */
  segmentAliveAt(k: number, z: number): boolean {
    const o = SEGMENT_FLOATS * k;
    return this.segments[o + 4]! <= z && z < this.segments[o + 5]!;
  }

  /**
   * Makes the buffers hold every segment that meets [zMin, zMax] (those of a window `margin`
   * wider on each side, when the range is not inside the last one), in order; returns how many.
   */
  prepare(gl: WebGL2RenderingContext, zMin: number, zMax: number, margin: number): number {
    const [w0, w1] = this.window;
    if (zMin >= w0 && zMax <= w1) return this.drawn;
    const lo = zMin - margin, hi = zMax + margin;
    const s = this.segments, F = SEGMENT_FLOATS;
    const keep: number[] = [];
    for (let k = 0; k < this.segmentCount; k++) if (s[F * k + 4]! <= hi && s[F * k + 5]! > lo) keep.push(k);
    const C = CORNER_FLOATS, ramps = this.lineRamps;
    const segs = new Float32Array(4 * C * keep.length), rules = new Uint16Array(4 * keep.length);
    keep.forEach((k, i) => {
      const line = this.segmentLine[k]!;
      for (let corner = 4 * i; corner < 4 * i + 4; corner++) {
        segs.set(s.subarray(F * k, F * k + F), C * corner);
        segs.set(ramps.subarray(4 * line, 4 * line + 4), C * corner + F);
        rules[corner] = this.segmentRule[k]!;
      }
    });
    const [seg, rule, index] = this.buffers as [WebGLBuffer, WebGLBuffer, WebGLBuffer];
    if (keep.length > this.capacity) {
      this.capacity = keep.length;
      // The same two triangles for every quad, over its four corners.
      const quads = new Uint32Array(6 * keep.length);
      for (let i = 0; i < keep.length; i++) for (let k = 0; k < 6; k++) quads[6 * i + k] = 4 * i + QUAD[k]!;
      // The element buffer binds to the vertex array: bound, it stays bound there.
      gl.bindVertexArray(this.vao);
      gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, index);
      gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, quads, gl.STATIC_DRAW);
      gl.bindVertexArray(null);
      gl.bindBuffer(gl.ARRAY_BUFFER, seg);
      gl.bufferData(gl.ARRAY_BUFFER, segs, gl.DYNAMIC_DRAW);
      gl.bindBuffer(gl.ARRAY_BUFFER, rule);
      gl.bufferData(gl.ARRAY_BUFFER, rules, gl.DYNAMIC_DRAW);
    } else if (keep.length > 0) {
      gl.bindBuffer(gl.ARRAY_BUFFER, seg);
      gl.bufferSubData(gl.ARRAY_BUFFER, 0, segs);
      gl.bindBuffer(gl.ARRAY_BUFFER, rule);
      gl.bufferSubData(gl.ARRAY_BUFFER, 0, rules);
    }
    gl.bindBuffer(gl.ARRAY_BUFFER, null);
    this.window = [lo, hi];
    this.drawn = keep.length;
    return this.drawn;
  }

  /** One quad (two triangles) per segment prepared. */
  draw(gl: WebGL2RenderingContext): void {
    if (this.drawn === 0) return;
    gl.bindVertexArray(this.vao);
    gl.drawElements(gl.TRIANGLES, 6 * this.drawn, gl.UNSIGNED_INT, 0);
  }

  delete(gl: WebGL2RenderingContext): void {
    gl.deleteVertexArray(this.vao);
    for (const b of this.buffers) gl.deleteBuffer(b);
  }
}
